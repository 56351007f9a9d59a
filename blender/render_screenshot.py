# render_screenshot.py — renders docs/blender.png headless with Cycles on the
# CPU (no display needed): Spot (data/spot.obj, 80 mm) after the add-on's
# Drain Holes (the drainability heat map of the cavity) and Decompose (the
# parts as coloured face groups), side by side.
#   blender --background --factory-startup --python blender/render_screenshot.py -- ZIP SPOT_OBJ OUT.png
# Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
import math
import sys

import bpy
from mathutils import Vector

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

# Frame both objects from the front, a little above.
corners = [obj.matrix_world @ Vector(c) for obj in (heat, parts) for c in obj.bound_box]
low = Vector([min(c[i] for c in corners) for i in range(3)])
high = Vector([max(c[i] for c in corners) for i in range(3)])
centre, width = (low + high) / 2, max(high.x - low.x, 2.2 * (high.z - low.z))
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
tilt = math.radians(12)
distance = 1.9 * width
camera.location = centre + Vector((0.0, distance * math.cos(tilt), distance * math.sin(tilt)))
camera.rotation_euler = (math.radians(90) - tilt, 0.0, math.radians(180))
scene.camera = camera
light = bpy.data.objects.new("sun", bpy.data.lights.new("sun", 'SUN'))
light.data.energy = 3.0
light.rotation_euler = (math.radians(35), math.radians(10), math.radians(160))
scene.collection.objects.link(light)
world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.55, 0.57, 0.6, 1.0)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
scene.view_settings.view_transform = 'Standard'  # the heat map's colours as the legend has them
scene.world = world
scene.render.engine = 'CYCLES'
scene.cycles.device = 'CPU'
scene.cycles.samples = 48
scene.cycles.use_denoising = False  # Debian's blender is built without OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = 1200, 560
scene.render.filepath = OUT
bpy.ops.render.render(write_still=True)
print("wrote", OUT)
