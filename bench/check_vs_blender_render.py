# bench/check_vs_blender_render.py — a picture of where Blender's 3D-Print
# Toolbox and `fabvdb check` disagree on thin walls, for one model of
# bench/check_vs_blender.sh's OUT_DIR:
#
#   blender -b --factory-startup --python bench/check_vs_blender_render.py -- MODEL_DIR OUT.png [AZIMUTH ELEVATION]
#
# Takes MODEL_DIR/input.obj and MODEL_DIR/classes.txt (one class per
# triangle: 0 both thick, 1 both thin, 2 only the Toolbox, 3 only fabvdb,
# 4 off fabvdb's surface) and renders the triangles in those classes'
# colours (light grey, blue, red, green, yellow) with Workbench, flat
# lighting, from the direction AZIMUTH, ELEVATION in degrees (default 35,
# 30), the model filling a 900 × 900 picture. Costs a second or two.
import math
import sys

import bpy
import numpy
from mathutils import Vector

COLOURS = [(0.8, 0.8, 0.8, 1), (0.15, 0.35, 0.95, 1), (0.95, 0.1, 0.1, 1), (0.1, 0.75, 0.2, 1), (0.95, 0.85, 0.1, 1)]


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    folder, out = args[0], args[1]
    azimuth, elevation = (math.radians(float(a)) for a in (args[2:4] if len(args) >= 4 else (35, 30)))
    vertices, triangles = [], []
    with open(folder + "/input.obj") as f:
        for line in f:
            if line.startswith("v "):
                vertices.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                triangles.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
    classes = numpy.loadtxt(folder + "/classes.txt", dtype=int).reshape(-1)
    keep = [i for i, t in enumerate(triangles) if len(set(t)) == 3]
    mesh = bpy.data.meshes.new("input")
    mesh.from_pydata(vertices, [], [triangles[i] for i in keep])
    colour = mesh.color_attributes.new("class", "FLOAT_COLOR", "CORNER")
    for polygon, i in zip(mesh.polygons, keep):
        for loop in polygon.loop_indices:
            colour.data[loop].color = COLOURS[classes[i]]
    scene = bpy.context.scene
    for obj in list(scene.objects):
        bpy.data.objects.remove(obj)
    obj = bpy.data.objects.new("input", mesh)
    scene.collection.objects.link(obj)
    points = numpy.array(vertices)
    centre = Vector(((points.min(axis=0) + points.max(axis=0)) / 2).tolist())
    radius = float(numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))) / 2
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    direction = Vector((math.cos(elevation) * math.cos(azimuth), math.cos(elevation) * math.sin(azimuth),
                        math.sin(elevation)))
    camera.location = centre + direction * radius * 2.9
    camera.rotation_euler = (-direction).to_track_quat("-Z", "Y").to_euler()
    camera.data.lens = 50
    scene.camera = camera
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.display.shading.light = "STUDIO"
    scene.display.shading.color_type = "VERTEX"
    scene.display.shading.show_backface_culling = False
    scene.render.resolution_x = scene.render.resolution_y = 900
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)


main()
