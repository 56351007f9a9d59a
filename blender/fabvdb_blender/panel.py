# panel.py — the fabvdb panel in the 3D view's sidebar (N panel, "fabvdb"
# tab) and the settings it shows (scene.fabvdb). Lengths are properties with
# unit LENGTH: shown and typed in the scene's units, converted to millimetres
# by the operators.
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import bpy

from . import fabvdb
from .jobs import STATE
from .operators import RESULTS, SESSIONS


class FabvdbSettings(bpy.types.PropertyGroup):
    resolution: bpy.props.IntProperty(name="Resolution", description="Voxels along the longest side (repair)",
                                      default=400, min=16, max=4000)
    wall: bpy.props.FloatProperty(name="Wall", description="Wall thickness", default=0.003, min=0.0,
                                  subtype='DISTANCE', unit='LENGTH', precision=4)
    closing: bpy.props.FloatProperty(name="Closing", description="Rounds the cavity; drops narrow passages",
                                     default=0.0, min=0.0, subtype='DISTANCE', unit='LENGTH', precision=4)
    infill: bpy.props.BoolProperty(name="Gyroid Infill", description="Fill the cavity with an open-cell lattice",
                                   default=False)
    cell: bpy.props.FloatProperty(name="Cell", default=0.01, min=0.0, subtype='DISTANCE', unit='LENGTH',
                                  precision=4)
    strut: bpy.props.FloatProperty(name="Strut", default=0.0012, min=0.0, subtype='DISTANCE', unit='LENGTH',
                                   precision=4)
    hole_count: bpy.props.IntProperty(name="Holes", description="Drain holes; 0 = automatic", default=0, min=0,
                                      max=64)
    hole_diameter: bpy.props.FloatProperty(name="Diameter", default=0.004, min=0.0, subtype='DISTANCE',
                                           unit='LENGTH', precision=4)
    patches: bpy.props.IntProperty(name="Patches", description="Cavity patches of the drainability model",
                                   default=2000, min=10)
    shell: bpy.props.FloatProperty(name="Shell", description="Shell thickness of the parts; 0 = 3% of the longest "
                                   "side", default=0.0, min=0.0, subtype='DISTANCE', unit='LENGTH', precision=4)
    gamma: bpy.props.FloatProperty(name="Gamma", description="Threshold on the total moldability energy",
                                   default=0.05, min=0.0001, max=10.0, precision=3)
    parts: bpy.props.IntProperty(name="Parts", description="Part count; 0 = automatic", default=0, min=0, max=1000)
    draft: bpy.props.FloatProperty(name="Draft", description="Draft angle, degrees", default=1.0, min=0.0, max=30.0)
    low_res: bpy.props.IntProperty(name="Low-res Triangles", default=10000, min=100)
    brush_radius: bpy.props.FloatProperty(name="Brush Radius", default=0.003, min=0.0, subtype='DISTANCE',
                                          unit='LENGTH', precision=4)
    margin: bpy.props.FloatProperty(name="Mold Margin", default=0.01, min=0.0, subtype='DISTANCE', unit='LENGTH',
                                    precision=4)


def _lines(layout, key):
    for line in RESULTS.get(key, []):
        layout.label(text=line)


class VIEW3D_PT_fabvdb(bpy.types.Panel):
    bl_label = "fabvdb"
    bl_idname = "VIEW3D_PT_fabvdb"
    bl_space_type = 'VIEW_3D'
    bl_region_type = 'UI'
    bl_category = "fabvdb"

    def draw(self, context):
        layout = self.layout
        s = context.scene.fabvdb
        obj = context.active_object
        if STATE["running"]:
            box = layout.box()
            box.label(text=f"{STATE['label']}: {STATE['stage']} {100 * STATE['fraction']:.0f}%", icon='TIME')
            box.label(text="Esc cancels")
        if obj is None or obj.type != 'MESH':
            layout.label(text="Select a mesh object")
            return
        layout.label(text=f"{obj.name}  (fabvdb {fabvdb.__version__})")

        box = layout.box()
        row = box.row(align=True)
        row.operator("fabvdb.inspect", icon='VIEWZOOM')
        row.operator("fabvdb.select_problems", text="Select Problems", icon='RESTRICT_SELECT_OFF')
        _lines(box, obj.name)

        box = layout.box()
        box.prop(s, "resolution")
        box.operator("fabvdb.repair", icon='MODIFIER')

        box = layout.box()
        box.prop(s, "wall")
        box.prop(s, "closing")
        box.prop(s, "infill")
        if s.infill:
            row = box.row(align=True)
            row.prop(s, "cell")
            row.prop(s, "strut")
        box.operator("fabvdb.hollow", icon='MOD_SOLIDIFY')

        box = layout.box()
        row = box.row(align=True)
        row.prop(s, "hole_count")
        row.prop(s, "hole_diameter")
        box.prop(s, "patches")
        box.operator("fabvdb.drain", icon='MOD_BOOLEAN')

        box = layout.box()
        box.prop(s, "shell")
        row = box.row(align=True)
        row.prop(s, "gamma")
        row.prop(s, "parts")
        row = box.row(align=True)
        row.prop(s, "draft")
        row.prop(s, "low_res", text="Low-res")
        box.operator("fabvdb.decompose", icon='MOD_EXPLODE')
        if obj.name in SESSIONS:
            box.prop(s, "brush_radius")
            row = box.row(align=True)
            row.operator("fabvdb.no_cut")
            row.operator("fabvdb.smooth")
            row = box.row(align=True)
            row.operator("fabvdb.cut")
            row.operator("fabvdb.merge")
            row = box.row(align=True)
            row.operator("fabvdb.decomposition_undo", text="Undo", icon='LOOP_BACK').redo = False
            row.operator("fabvdb.decomposition_undo", text="Redo", icon='LOOP_FORWARDS').redo = True

        box = layout.box()
        box.prop(s, "margin")
        box.operator("fabvdb.mold", icon='MESH_CUBE')


CLASSES = (FabvdbSettings, VIEW3D_PT_fabvdb)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.fabvdb = bpy.props.PointerProperty(type=FabvdbSettings)


def unregister():
    del bpy.types.Scene.fabvdb
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
