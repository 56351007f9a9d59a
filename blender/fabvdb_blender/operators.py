# operators.py — the add-on's operators, each on the active mesh object
# through the fabvdb package: inspect, select problem spots, repair, hollow,
# drain (holes, heat map, routine), decompose and its edits (no-cut, smooth,
# cut, merge, undo, redo), molds. Results are new objects, collections and
# attributes; findings are listed in the panel (RESULTS).
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import bmesh
import bpy
import numpy as np

from . import bridge, fabvdb
from .jobs import STATE, FabvdbJob

# Lines the panel lists per object name (inspection, drain, decomposition).
RESULTS = {}
# Decomposition sessions per parts-object name: {"session", "source", "scale"}.
SESSIONS = {}


def settings(context):
    return context.scene.fabvdb


class FABVDB_OT_inspect(FabvdbJob, bpy.types.Operator):
    """Inspect the active object as a print-file checker would: size, holes, non-manifold and crossing
    triangles, volume"""
    bl_idname = "fabvdb.inspect"
    bl_label = "Inspect"
    bl_options = {'REGISTER'}

    def prepare(self, context):
        obj = context.active_object
        points, triangles, polygon = bridge.object_arrays(obj, context.evaluated_depsgraph_get())
        scale = bridge.mm_per_unit(context.scene)
        # The problem faces can be selected on the object's own polygons only
        # when its modifiers left them as they are.
        same_polygons = int(polygon.max(initial=-1)) + 1 == len(obj.data.polygons)
        return {"name": obj.name, "mesh": fabvdb.Mesh(points * scale, triangles), "scale": scale,
                "polygon": polygon if same_polygons else None}

    def work(self, inputs, ctx, progress):
        return fabvdb.inspect(inputs["mesh"], context=ctx, progress=progress)

    def finish(self, context, inputs, report):
        lines = [f"{report['triangles']} triangles, {report['components']} components",
                 "closed" if report["closed"] else "NOT closed (not watertight)"]
        if report.get("volume") is not None:
            lines.append(f"volume {report['volume'] / 1000.0:.2f} cm³")
        for key, label in (("boundary_loops", "holes"), ("non_manifold_edges", "non-manifold edges"),
                           ("non_manifold_vertices", "non-manifold vertices"),
                           ("degenerate_triangles", "degenerate triangles"),
                           ("duplicate_triangles", "duplicate triangles"),
                           ("self_intersecting_pairs", "self-intersecting pairs"),
                           ("inconsistent_edges", "inconsistent edges")):
            if report.get(key):
                lines.append(f"{label}: {report[key]}")
        if len(lines) == 2 or (len(lines) == 3 and report["closed"]):
            lines.append("no defect found")
        RESULTS[inputs["name"]] = lines
        obj = context.active_object
        obj["fabvdb_inspect"] = report["closed"]
        # The polygons holding a crossing or degenerate triangle, for Select Problems.
        if inputs["polygon"] is not None:
            triangles = np.array(report["self_intersecting_triangle_indices"] + report["degenerate_triangle_indices"],
                                 dtype=np.int64)
            obj["fabvdb_problem_faces"] = np.unique(inputs["polygon"][triangles]).tolist()
        elif "fabvdb_problem_faces" in obj:
            del obj["fabvdb_problem_faces"]
        self.report({'INFO'}, "fabvdb: " + "; ".join(lines))


class FABVDB_OT_select_problems(bpy.types.Operator):
    """Select the problem spots of the active object in Edit Mode: open and non-manifold edges, and the faces
    with crossing or degenerate triangles that the last Inspect found"""
    bl_idname = "fabvdb.select_problems"
    bl_label = "Select Problem Edges"
    bl_options = {'REGISTER', 'UNDO'}

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == 'MESH'

    def execute(self, context):
        if context.active_object.mode != 'EDIT':
            bpy.ops.object.mode_set(mode='EDIT')
        bpy.ops.mesh.select_mode(type='EDGE')
        bpy.ops.mesh.select_all(action='DESELECT')
        bpy.ops.mesh.select_non_manifold()
        faces = context.active_object.get("fabvdb_problem_faces")
        if faces:
            data = context.active_object.data
            mesh = bmesh.from_edit_mesh(data)
            mesh.faces.ensure_lookup_table()
            for index in faces:
                if index < len(mesh.faces):
                    mesh.faces[index].select_set(True)
            mesh.select_flush_mode()
            bmesh.update_edit_mesh(data)
        return {'FINISHED'}


class MeshJob(FabvdbJob):
    """A job on the active object's mesh whose result is a new object beside it."""
    suffix = ""

    def prepare(self, context):
        obj = context.active_object
        return {"name": obj.name, "mesh": bridge.fabvdb_mesh(obj, context), "scale": bridge.mm_per_unit(context.scene),
                "settings": self.read_settings(context, bridge.mm_per_unit(context.scene))}

    def read_settings(self, context, scale):
        return {}

    def place(self, context, inputs, mesh):
        obj = bridge.new_object(context, f"{inputs['name']}_{self.suffix}", mesh)
        source = bpy.data.objects.get(inputs["name"])
        if source is not None:
            source.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        return obj


class FABVDB_OT_repair(MeshJob, bpy.types.Operator):
    """Make a clean watertight solid of the active object, as a new object (holes closed, crossing shells
    united, flipped triangles turned)"""
    bl_idname = "fabvdb.repair"
    bl_label = "Repair"
    suffix = "repaired"

    def read_settings(self, context, scale):
        return {"resolution": settings(context).resolution}

    def work(self, inputs, ctx, progress):
        return fabvdb.repair(inputs["mesh"], context=ctx, progress=progress, **inputs["settings"])

    def finish(self, context, inputs, result):
        obj = self.place(context, inputs, result.mesh)
        RESULTS[obj.name] = [f"repaired: {result.report.get('path', '')} path",
                             f"{result.mesh.triangle_count} triangles"]


class FABVDB_OT_hollow(MeshJob, bpy.types.Operator):
    """Hollow the active object for printing, as a new object: a wall under the surface, the inside emptied"""
    bl_idname = "fabvdb.hollow"
    bl_label = "Hollow"
    suffix = "hollow"

    def read_settings(self, context, scale):
        s = settings(context)
        options = {"wall": s.wall * scale, "closing": s.closing * scale}
        if s.infill:
            options.update(infill="gyroid", cell=s.cell * scale, strut=s.strut * scale)
        return options

    def work(self, inputs, ctx, progress):
        return fabvdb.hollow(inputs["mesh"], context=ctx, progress=progress, **inputs["settings"])

    def finish(self, context, inputs, result):
        obj = self.place(context, inputs, result.mesh)
        r = result.report
        RESULTS[obj.name] = [f"{100 * r['material_saved_fraction']:.0f}% material saved",
                             f"{r['cavity_count']} cavities"] + list(r.get("warnings", []))


class FABVDB_OT_drain(MeshJob, bpy.types.Operator):
    """Place and drill drain holes in the active object (hollowed first if solid), as a new object, with the
    drainability heat map of the cavity as a second object and the cleaning routine in the panel"""
    bl_idname = "fabvdb.drain"
    bl_label = "Drain Holes"
    suffix = "drained"

    def read_settings(self, context, scale):
        s = settings(context)
        return {"wall": s.wall * scale, "holes": s.hole_count or "auto", "hole_diameter": s.hole_diameter * scale,
                "patches": s.patches}

    def work(self, inputs, ctx, progress):
        return fabvdb.drain(inputs["mesh"], heatmap=True, context=ctx, progress=progress, **inputs["settings"])

    def finish(self, context, inputs, result):
        obj = self.place(context, inputs, result.mesh)
        report = result.report
        lines = [f"{len(result.holes)} holes; powder left {100 * report.get('routine_residual_fraction', 0):.2f}% "
                 f"(lowest points: {100 * report.get('baseline_residual_fraction', 0):.2f}%)"]
        lines += [f"{i + 1}. {step.get('instruction', '')}" for i, step in enumerate(result.routine)]
        heat = result.heatmap
        if heat is not None:
            low, high = float(heat.drains.min()), float(heat.drains.max())
            cavity = bridge.new_object(context, f"{inputs['name']}_drainability", heat.surface)
            bridge.set_point_colours(cavity, "drainability", heat.colours)
            bridge.set_point_values(cavity, "drains", heat.drains)
            bridge.set_point_values(cavity, "powder_left", heat.left)
            cavity.data.materials.append(bridge.colour_material("fabvdb drainability", "drainability"))
            cavity["drains_min"], cavity["drains_max"] = low, high
            lines.append(f"heat map '{cavity.name}': share drained {low:.2f} to {high:.2f} (viridis)")
        RESULTS[obj.name] = lines
        RESULTS[inputs["name"]] = lines


class FABVDB_OT_decompose(MeshJob, bpy.types.Operator):
    """Cut the active object into parts that each cast in a two-piece mold: a new object with the parts as
    coloured face groups, ready for edits"""
    bl_idname = "fabvdb.decompose"
    bl_label = "Decompose"
    suffix = "parts"

    def read_settings(self, context, scale):
        s = settings(context)
        options = {"gamma": s.gamma, "parts": s.parts or "auto", "draft": s.draft, "low_res": s.low_res}
        if s.shell > 0:
            options["shell"] = s.shell * scale
        return options

    def work(self, inputs, ctx, progress):
        return fabvdb.Decomposition(inputs["mesh"], context=ctx, progress=progress, **inputs["settings"])

    def finish(self, context, inputs, session):
        session.progress = None
        surface = session.surface
        obj = self.place(context, inputs, surface)
        SESSIONS[obj.name] = {"session": session, "source": inputs["name"], "scale": inputs["scale"]}
        refresh_parts(obj)


def refresh_parts(obj):
    """Shows the session's current step on its parts object: S_low positions, part colours, the summary."""
    entry = SESSIONS[obj.name]
    session = entry["session"]
    vertices = session.vertices / entry["scale"]
    obj.data.vertices.foreach_set("co", vertices.astype(np.float32).ravel())
    info = session.info
    bridge.show_parts(obj, session.labels, info["part_count"])
    RESULTS[obj.name] = [f"{info['part_count']} parts, energy {info['total_energy']:.4f} "
                         f"(gamma {info['gamma']:.3f}){'  OVER GAMMA' if info['over_gamma'] else ''}",
                         f"undo {info['undo_steps']}, redo {info['redo_steps']}, edits {info['edit_count']}"]


class SessionJob(FabvdbJob):
    """An edit of the decomposition shown by the active object (a parts object)."""

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return not STATE["running"] and obj is not None and obj.name in SESSIONS

    def prepare(self, context):
        obj = context.active_object
        entry = SESSIONS[obj.name]
        return {"name": obj.name, "session": entry["session"], "scale": entry["scale"],
                "edit": self.read_edit(context, obj, entry["scale"]), "apply": self.apply}

    def job_context(self, inputs):
        return inputs["session"].context

    def work(self, inputs, ctx, progress):
        session = inputs["session"]
        session.progress = progress
        try:
            inputs["apply"](session, inputs["edit"])
        finally:
            session.progress = None
        return None

    def finish(self, context, inputs, result):
        refresh_parts(bpy.data.objects[inputs["name"]])


class FABVDB_OT_no_cut(SessionJob, bpy.types.Operator):
    """Keep the selected faces (and the brush radius around them) inside one part"""
    bl_idname = "fabvdb.no_cut"
    bl_label = "No Cut"

    def read_edit(self, context, obj, scale):
        _, centres = bridge.selected_faces(obj)
        if len(centres) == 0:
            raise fabvdb.InvalidArgumentError("select the faces to keep in one part first (Edit Mode)")
        return {"points": centres * scale, "radius": settings(context).brush_radius * scale}

    def apply(self, session, edit):
        session.no_cut(edit["points"], edit["radius"])


class FABVDB_OT_smooth(SessionJob, bpy.types.Operator):
    """Smooth the part boundaries near the selected faces (within the brush radius)"""
    bl_idname = "fabvdb.smooth"
    bl_label = "Smooth"

    def read_edit(self, context, obj, scale):
        _, centres = bridge.selected_faces(obj)
        if len(centres) == 0:
            raise fabvdb.InvalidArgumentError("select faces along the boundaries to smooth first (Edit Mode)")
        return {"points": centres * scale, "radius": settings(context).brush_radius * scale}

    def apply(self, session, edit):
        session.smooth(edit["points"], edit["radius"])


class FABVDB_OT_cut(SessionJob, bpy.types.Operator):
    """Cut the parts along the last annotation stroke drawn on the object (Annotate tool), or through the
    selected faces in the order of their centres along the selection"""
    bl_idname = "fabvdb.cut"
    bl_label = "Cut Along Path"

    closed: bpy.props.BoolProperty(name="Closed", description="Join the path's end to its start", default=False)

    def read_edit(self, context, obj, scale):
        path = bridge.annotation_path(context)
        if path is None:
            _, path = bridge.selected_faces(obj)
        if path is None or len(path) < 2:
            raise fabvdb.InvalidArgumentError("draw a path with the Annotate tool (or select faces) first")
        return {"points": path * scale, "closed": self.closed}

    def apply(self, session, edit):
        session.cut(edit["points"], closed=edit["closed"])


class FABVDB_OT_merge(SessionJob, bpy.types.Operator):
    """Merge the two parts under the selected faces (select a face in each)"""
    bl_idname = "fabvdb.merge"
    bl_label = "Merge Parts"

    def read_edit(self, context, obj, scale):
        index, centres = bridge.selected_faces(obj)
        labels = SESSIONS[obj.name]["session"].labels
        picked = {}
        for face, centre in zip(index, centres):
            picked.setdefault(int(labels[face]), centre)
        if len(picked) != 2:
            raise fabvdb.InvalidArgumentError("select faces on exactly two parts")
        a, b = list(picked.values())
        return {"a": a * scale, "b": b * scale}

    def apply(self, session, edit):
        session.merge(edit["a"], edit["b"])


class FABVDB_OT_undo(bpy.types.Operator):
    """Undo (or redo) the last step of the decomposition"""
    bl_idname = "fabvdb.decomposition_undo"
    bl_label = "Undo Step"
    bl_options = {'REGISTER'}

    redo: bpy.props.BoolProperty(name="Redo", default=False)

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return not STATE["running"] and obj is not None and obj.name in SESSIONS

    def execute(self, context):
        obj = context.active_object
        session = SESSIONS[obj.name]["session"]
        moved = session.redo() if self.redo else session.undo()
        if not moved:
            self.report({'INFO'}, "fabvdb: nothing to " + ("redo" if self.redo else "undo"))
            return {'CANCELLED'}
        refresh_parts(obj)
        return {'FINISHED'}


class FABVDB_OT_mold(MeshJob, bpy.types.Operator):
    """Make cast-ready parts and two-piece molds for the active object (its decomposition if it is a parts
    object, else an automatic one) into a new collection"""
    bl_idname = "fabvdb.mold"
    bl_label = "Molds"

    def prepare(self, context):
        obj = context.active_object
        scale = bridge.mm_per_unit(context.scene)
        entry = SESSIONS.get(obj.name)
        source = bpy.data.objects[entry["source"]] if entry else obj
        s = settings(context)
        options = {"mold_margin": s.margin * scale}
        if not entry:
            options.update(gamma=s.gamma, parts=s.parts, low_res=s.low_res)
            if s.shell > 0:
                options["shell"] = s.shell * scale
        return {"name": source.name, "mesh": bridge.fabvdb_mesh(source, context), "scale": scale,
                "session": entry["session"] if entry else None, "settings": options}

    def work(self, inputs, ctx, progress):
        return fabvdb.mold(inputs["mesh"], decomposition=inputs["session"], context=ctx, progress=progress,
                           **inputs["settings"])

    def finish(self, context, inputs, result):
        collection = bridge.new_collection(context, f"{inputs['name']}_molds")
        for i, part in enumerate(result.parts):
            obj = bridge.new_object(context, f"{inputs['name']}_part_{i:02d}", part, collection)
            obj.data.materials.append(bridge.part_material(i))
        for i, (top, bottom) in enumerate(result.molds):
            bridge.new_object(context, f"{inputs['name']}_mold_{i:02d}_top", top, collection)
            bridge.new_object(context, f"{inputs['name']}_mold_{i:02d}_bottom", bottom, collection)
        RESULTS[collection.name] = [f"{len(result.parts)} parts, {2 * len(result.molds)} mold pieces"]
        RESULTS[inputs["name"]] = RESULTS[collection.name]


CLASSES = (FABVDB_OT_inspect, FABVDB_OT_select_problems, FABVDB_OT_repair, FABVDB_OT_hollow, FABVDB_OT_drain,
           FABVDB_OT_decompose, FABVDB_OT_no_cut, FABVDB_OT_smooth, FABVDB_OT_cut, FABVDB_OT_merge, FABVDB_OT_undo,
           FABVDB_OT_mold)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)


def unregister():
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
    SESSIONS.clear()
    RESULTS.clear()
