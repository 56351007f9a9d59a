# bench/check_vs_blender_toolbox.py — Blender's 3D-Print Toolbox thickness
# check on one mesh, run headless by bench/check_vs_blender.sh:
#
#   blender -b --factory-startup --python bench/check_vs_blender_toolbox.py -- IN.obj THICKNESS OUT.json
#
# Takes an OBJ of triangles (v and f lines only, as `corpus_check obj`
# writes it, one Blender unit per mm) and the threshold in mm. Builds the
# mesh with the file's vertices and triangles in order (a triangle that
# repeats a corner is left out: Blender's meshes cannot hold one; it has no
# area), runs the add-on's own check, object_print3d_utils.mesh_helpers.
# bmesh_check_thick_object (what "Thickness" in the Toolbox panel calls: six
# random points per face, a ray from each backwards along the face normal
# as far as the threshold, and a hit marks that face and the face hit), and
# writes JSON: triangles (in the file), left_out (their indices), thin (the
# indices of the triangles it marks, in the file's numbering), seconds (the
# check alone), and own: the marked triangles one of whose own rays hits (the
# others are marked only as the triangle another's ray hit), from the
# add-on's loop cast again (its sampling function, bias and ray length); the
# script stops with an error unless those and the triangles they hit are
# exactly the add-on's. Costs six ray casts per triangle in Blender's Python,
# about 10 µs each, twice.
import json
import os
import sys
import time

import bmesh
import bpy
import numpy

from object_print3d_utils import mesh_helpers

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_vs_blender_compare import read_obj  # noqa: E402 (found beside this script)


def own_ray_hits(obj, thickness):
    """The add-on's loop again (mesh_helpers.bmesh_check_thick_object): the
    faces one of whose six rays hits, and the faces hit."""
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    own, hit = set(), set()
    for face in bm.faces:
        normal = face.normal.copy()
        for point in mesh_helpers.bmesh_face_points_random(face, num_points=6):
            start, end = point - normal * 0.0001, point - normal * thickness
            ok, _co, _normal, index = obj.ray_cast(start, end - start, distance=(end - start).length)
            if ok:
                own.add(face.index)
                hit.add(index)
    bm.free()
    return own, hit


def main():
    path, thickness, out = sys.argv[sys.argv.index("--") + 1:][:3]
    vertices, triangles = read_obj(path)
    t = triangles
    repeats = (t[:, 0] == t[:, 1]) | (t[:, 1] == t[:, 2]) | (t[:, 0] == t[:, 2])
    kept = numpy.flatnonzero(~repeats)
    faces = triangles[kept]
    mesh = bpy.data.meshes.new("input")
    mesh.vertices.add(len(vertices))
    mesh.vertices.foreach_set("co", vertices.ravel())
    mesh.loops.add(3 * len(faces))
    mesh.loops.foreach_set("vertex_index", faces.ravel())
    mesh.polygons.add(len(faces))
    mesh.polygons.foreach_set("loop_start", numpy.arange(0, 3 * len(faces), 3))
    mesh.polygons.foreach_set("loop_total", numpy.full(len(faces), 3))
    mesh.update(calc_edges=True)
    obj = bpy.data.objects.new("input", mesh)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    if len(mesh.polygons) != len(faces):
        raise SystemExit("Blender holds %d faces of the %d given" % (len(mesh.polygons), len(faces)))
    start = time.perf_counter()
    thin = mesh_helpers.bmesh_check_thick_object(obj, float(thickness))
    seconds = time.perf_counter() - start
    own, hit = own_ray_hits(obj, float(thickness))
    if own | hit != set(thin):
        raise SystemExit("the add-on's loop cast again marks %d faces, the add-on %d" % (len(own | hit), len(thin)))
    with open(out, "w") as f:
        json.dump({"triangles": len(triangles), "left_out": numpy.flatnonzero(repeats).tolist(),
                   "thin": sorted(int(kept[i]) for i in thin), "own": sorted(int(kept[i]) for i in own),
                   "seconds": seconds}, f)


main()
