"""The Blender add-on, headless (run by run_blender_test.py inside Debian's
blender): installs the zip the build packed, enables it, and runs every
operator on a shared model — a 20 mm ico-sphere in a metric scene (1 unit =
1 m, so scene units are converted) — checking the objects it leaves by
measurement: closed solids, volumes, wall thickness, part counts.
Arguments after --: ZIP SPHERE_OBJ WORK_DIR."""
import math
import os
import sys
import traceback

import bmesh
import bpy
import numpy as np

ZIP, SPHERE_OBJ, WORK = sys.argv[sys.argv.index("--") + 1:]


def arrays(obj):
    """World positions (BU) and triangles of an object's mesh (triangulated polygons)."""
    data = obj.data
    data.calc_loop_triangles()
    v = np.empty(len(data.vertices) * 3)
    data.vertices.foreach_get("co", v)
    t = np.empty(len(data.loop_triangles) * 3, dtype=np.int64)
    data.loop_triangles.foreach_get("vertices", t)
    m = np.array(obj.matrix_world)
    return v.reshape(-1, 3) @ m[:3, :3].T + m[:3, 3], t.reshape(-1, 3)


def volume(obj):
    v, t = arrays(obj)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def closed(obj):
    _, t = arrays(obj)
    edges = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    n = int(t.max()) + 1
    forward, backward = edges[:, 0] * n + edges[:, 1], edges[:, 1] * n + edges[:, 0]
    return len(np.unique(forward)) == len(forward) and bool(np.all(np.isin(forward, backward)))


def shells(obj):
    """Connected pieces of the mesh (Blender's own linked selection count)."""
    v, t = arrays(obj)
    parent = list(range(len(v)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for a, b, c in t:
        parent[find(b)] = find(a)
        parent[find(c)] = find(a)
    return len({find(int(i)) for i in np.unique(t)})


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what, flush=True)


def activate(obj):
    for other in bpy.context.view_layer.objects:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def run():
    # The add-on installs from the zip and registers.
    bpy.ops.preferences.addon_install(filepath=ZIP, overwrite=True)
    bpy.ops.preferences.addon_enable(module="fabvdb_blender")
    import fabvdb_blender
    check(hasattr(bpy.types, "VIEW3D_PT_fabvdb") and hasattr(bpy.context.scene, "fabvdb"), "the add-on registers")
    print("fabvdb package from", fabvdb_blender.fabvdb.__file__)

    scene = bpy.context.scene
    check(scene.unit_settings.system == 'METRIC' and scene.unit_settings.scale_length == 1.0, "1 unit is 1 m")
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=3, radius=0.02, location=(0.1, 0, 0))
    sphere = bpy.context.active_object
    sphere.name = "sphere"
    solid = volume(sphere)

    # Inspect: a clean closed solid.
    bpy.ops.fabvdb.inspect()
    check(sphere["fabvdb_inspect"] and "closed" in fabvdb_blender.operators.RESULTS["sphere"], "inspect: closed")

    # Inspect and Select Problems: two cubes of 4 cm in one object, the
    # second moved by (2, 1, 0.5) cm, cross each other; the faces they cross
    # on are the first's +x, +y and +z faces and the second's -x, -y and -z
    # faces (the second's other faces, and the first's, miss the other cube).
    bpy.ops.mesh.primitive_cube_add(size=0.04, location=(0, 0.2, 0))
    first = bpy.context.active_object
    bpy.ops.mesh.primitive_cube_add(size=0.04, location=(0.02, 0.21, 0.005))
    second = bpy.context.active_object
    activate(first)
    second.select_set(True)
    bpy.ops.object.join()
    crossed = bpy.context.active_object
    crossed.name = "crossed_cubes"
    bpy.ops.fabvdb.inspect()
    check(any(line.startswith("self-intersecting pairs") for line in fabvdb_blender.operators.RESULTS["crossed_cubes"]),
          "inspect: crossing triangles listed")
    bpy.ops.fabvdb.select_problems()
    bpy.ops.object.mode_set(mode='OBJECT')
    centres = {(round(p.center[0] * 100, 1), round(p.center[1] * 100, 1), round(p.center[2] * 100, 1))
               for p in crossed.data.polygons if p.select}
    # Face centres in cm, in the joined object's frame (the first cube's).
    expected = {(2.0, 0.0, 0.0), (0.0, 2.0, 0.0), (0.0, 0.0, 2.0),
                (0.0, 1.0, 0.5), (2.0, -1.0, 0.5), (2.0, 1.0, -1.5)}
    check(centres == expected, "select problems: the six crossing faces (%s)" % sorted(centres))
    bpy.data.objects.remove(crossed)

    # Repair: an open box (a face deleted) comes back closed, as a new object.
    bpy.ops.mesh.primitive_cube_add(size=0.04, location=(-0.1, 0, 0))
    box = bpy.context.active_object
    box.name = "open_box"
    mesh = bmesh.new()
    mesh.from_mesh(box.data)
    mesh.faces.ensure_lookup_table()
    bmesh.ops.delete(mesh, geom=[mesh.faces[0]], context='FACES_ONLY')
    mesh.to_mesh(box.data)
    mesh.free()
    check(not closed(box), "the box is open")
    scene.fabvdb.resolution = 60
    bpy.ops.fabvdb.repair()
    repaired = bpy.data.objects["open_box_repaired"]
    check(closed(repaired), "repair: closed")
    check(abs(volume(repaired) - 0.04 ** 3) < 0.04 * 0.04 ** 3, "repair: the box's volume, in scene units")
    check(len(box.data.polygons) == 5, "repair: the input is unchanged")

    # Hollow: a 3 mm wall (0.003 m in scene units).
    activate(sphere)
    scene.fabvdb.wall = 0.003
    bpy.ops.fabvdb.hollow()
    hollow = bpy.data.objects["sphere_hollow"]
    check(closed(hollow) and shells(hollow) == 2, "hollow: closed, outer and cavity shells")
    v, _ = arrays(hollow)
    radius = np.linalg.norm(v - np.array([0.1, 0, 0]), axis=1)
    inner = radius[radius < 0.0185]
    check(len(inner) > 0 and abs(np.median(inner) - 0.017) < 0.0007, "hollow: the cavity lies 3 mm in")
    shell = volume(hollow)
    check(0.2 * solid < shell < 0.45 * solid, f"hollow: shell volume {shell:.3g} of solid {solid:.3g}")

    # Drain: two holes, the heat map as a colour attribute with its range.
    activate(sphere)
    scene.fabvdb.hole_count = 2
    scene.fabvdb.patches = 300
    bpy.ops.fabvdb.drain()
    drained = bpy.data.objects["sphere_drained"]
    check(closed(drained) and shells(drained) == 1, "drain: closed, the cavity opened to the outside")
    check(volume(drained) < shell, "drain: holes removed material")
    heat = bpy.data.objects["sphere_drainability"]
    check("drainability" in heat.data.color_attributes, "drain: colour attribute")
    values = np.empty(len(heat.data.vertices))
    heat.data.attributes["drains"].data.foreach_get("value", values)
    check(values.min() >= -1e-6 and values.max() <= 1 + 1e-6 and heat["drains_max"] >= heat["drains_min"],
          "drain: drainability in [0, 1] with its range")
    routine = [line for line in fabvdb_blender.operators.RESULTS["sphere"] if line[:1].isdigit()]
    check(len(routine) >= 1, "drain: the routine is listed")

    # Decompose: two parts as coloured face groups; merge, undo, cut, undo.
    activate(sphere)
    scene.fabvdb.parts = 2
    scene.fabvdb.low_res = 1500
    scene.fabvdb.shell = 0.003
    bpy.ops.fabvdb.decompose()
    parts = bpy.data.objects["sphere_parts"]
    labels = np.empty(len(parts.data.polygons), dtype=np.int32)
    parts.data.attributes["part"].data.foreach_get("value", labels)
    check(set(np.unique(labels)) == {0, 1} and len(parts.data.materials) == 2, "decompose: two coloured parts")
    activate(parts)
    select = np.zeros(len(labels), dtype=bool)
    select[np.flatnonzero(labels == 0)[0]] = True
    select[np.flatnonzero(labels == 1)[0]] = True
    parts.data.polygons.foreach_set("select", select)
    bpy.ops.fabvdb.merge()
    parts.data.attributes["part"].data.foreach_get("value", labels)
    check(len(parts.data.materials) == 1 and set(np.unique(labels)) == {0}, "merge: one part")
    bpy.ops.fabvdb.decomposition_undo()
    parts.data.attributes["part"].data.foreach_get("value", labels)
    check(len(parts.data.materials) == 2, "undo: two parts again")
    # A cut drawn as an annotation: a closed loop round the sphere in the plane x = 0.1.
    notes = bpy.data.grease_pencils.new("Annotations")
    scene.grease_pencil = notes
    stroke = notes.layers.new("Note").frames.new(1).strokes.new()
    angles = np.linspace(0, 2 * math.pi, 16, endpoint=False)
    stroke.points.add(len(angles))
    loop = np.stack([np.full_like(angles, 0.1), 0.02 * np.cos(angles), 0.02 * np.sin(angles)], axis=1)
    stroke.points.foreach_set("co", loop.ravel())
    bpy.ops.fabvdb.cut(closed=True)
    check(len(parts.data.materials) >= 3, "cut along a drawn path: more parts")
    bpy.ops.fabvdb.decomposition_undo()
    check(len(parts.data.materials) == 2, "undo the cut")

    # Molds from the decomposition: parts and mold pieces in a new collection.
    bpy.ops.fabvdb.mold()
    collection = bpy.data.collections["sphere_molds"]
    names = sorted(o.name for o in collection.objects)
    check(len([n for n in names if "_part_" in n]) == 2 and len([n for n in names if "_mold_" in n]) == 4,
          f"molds: 2 parts and 4 pieces ({names})")
    for obj in collection.objects:
        check(closed(obj) and volume(obj) > 0, f"molds: {obj.name} is a closed solid")
    bpy.ops.preferences.addon_disable(module="fabvdb_blender")
    check(not hasattr(bpy.types, "VIEW3D_PT_fabvdb"), "the add-on unregisters")


try:
    run()
except Exception:
    traceback.print_exc()
    sys.exit(1)
print("blender add-on test: all passed")
