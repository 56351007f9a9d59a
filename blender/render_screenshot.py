# render_screenshot.py — renders docs/blender.png headless with Cycles on the
# CPU (no display needed): Spot (data/spot.obj, 80 mm) after the add-on's
# Drain Holes (the drainability heat map of the cavity) and Decompose (the
# parts as coloured face groups), side by side.
#   blender --background --factory-startup --python blender/render_screenshot.py -- ZIP SPOT_OBJ OUT.png
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import math
import sys

import bpy

ZIP, SPOT, OUT = sys.argv[sys.argv.index("--") + 1:]

bpy.ops.preferences.addon_install(filepath=ZIP, overwrite=True)
bpy.ops.preferences.addon_enable(module="fabvdb_blender")
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)
scene = bpy.context.scene
bpy.ops.wm.obj_import(filepath=SPOT, forward_axis='NEGATIVE_Z', up_axis='Y')
spot = bpy.context.selected_objects[0]
spot.name = "spot"
size = max(spot.dimensions)
spot.scale = (0.08 / size,) * 3  # 80 mm in a metric scene
bpy.context.view_layer.objects.active = spot
bpy.ops.object.transform_apply(scale=True)

s = scene.fabvdb
s.wall = 0.002
s.hole_count = 2
bpy.ops.fabvdb.drain()
bpy.context.view_layer.objects.active = spot
s.low_res = 5000
bpy.ops.fabvdb.decompose()

for name in ("spot", "spot_drained"):
    bpy.data.objects[name].hide_render = True
heat = bpy.data.objects["spot_drainability"]
parts = bpy.data.objects["spot_parts"]
heat.location.x -= 0.05
parts.location.x += 0.05
for obj in (heat, parts):
    obj.data.polygons.foreach_set("use_smooth", [True] * len(obj.data.polygons))

camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
camera.location = (0.0, -0.26, 0.12)
camera.rotation_euler = (math.radians(68), 0.0, 0.0)
scene.camera = camera
light = bpy.data.objects.new("sun", bpy.data.lights.new("sun", 'SUN'))
light.data.energy = 4.0
light.rotation_euler = (math.radians(40), math.radians(15), math.radians(30))
scene.collection.objects.link(light)
world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.8, 0.82, 0.85, 1.0)
scene.world = world
scene.render.engine = 'CYCLES'
scene.cycles.device = 'CPU'
scene.cycles.samples = 32
scene.render.resolution_x, scene.render.resolution_y = 1200, 560
scene.render.filepath = OUT
bpy.ops.render.render(write_still=True)
print("wrote", OUT)
