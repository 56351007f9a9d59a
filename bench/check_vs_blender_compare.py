#!/usr/bin/python3
# bench/check_vs_blender_compare.py — per input triangle, thin by Blender's
# 3D-Print Toolbox against thin by `fabvdb check`'s thickness map; run by
# bench/check_vs_blender.sh:
#
#   check_vs_blender_compare.py IN.obj MAP.ply TOOLBOX.json THRESHOLD VOXEL [CLASSES.txt]
#
# Takes the OBJ both ran on (v and f lines), fabvdb's map (binary PLY, the
# solid's extracted surface, per-vertex float `quality` = local thickness in
# mm), the Toolbox's JSON (bench/check_vs_blender_toolbox.py: the indices of
# the triangles it marks), the threshold in mm and fabvdb's voxel in mm.
# A triangle is thin by fabvdb when the map's thickness under one of four
# points spread over it (its centre and the midpoints between the centre and
# each corner, as the Toolbox spreads six rays) is under the threshold,
# where the thickness under a point is that of the nearest map vertex (grid
# hashing, cells of two voxels: every vertex within two voxels is seen).
# A point with no map vertex within two voxels is off the solid's surface
# (an open sheet or a shell inside another, which the solid has no surface
# for); a triangle whose every point is off is left to its own class.
# Prints one JSON object: the area and the share of the input's area in each
# class (both thin, both thick, only Toolbox, only fabvdb; off the surface,
# thin and not thin by the Toolbox), of only Toolbox the share marked only
# as the triangle another's ray hit (none of its own rays hits), the thin
# area by each; with
# CLASSES.txt, writes each triangle's class (0 both thick, 1 both thin,
# 2 only Toolbox, 3 only fabvdb, 4 off the surface), one per line.
# Costs O(triangles + map vertices) numpy work, 27 cells × the most vertices
# in a cell passes.
import json
import sys

import numpy

BOTH_THICK, BOTH_THIN, ONLY_TOOLBOX, ONLY_FABVDB, OFF_SURFACE = range(5)


def read_obj(path):
    vertices, triangles = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                triangles.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
    return (numpy.array(vertices, dtype=numpy.float64).reshape(-1, 3),
            numpy.array(triangles, dtype=numpy.int64).reshape(-1, 3))


def read_map(path):
    """Vertices and their `quality` from fabvdb's binary little-endian PLY."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise SystemExit(path + ": not a binary little-endian PLY")
    count, properties, in_vertex = 0, [], False
    sizes = {"float": "<f4", "uchar": "u1", "double": "<f8", "int": "<i4", "uint": "<u4"}
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count, in_vertex = int(words[2]), True
        elif words[:1] == ["element"]:
            in_vertex = False
        elif words[:1] == ["property"] and in_vertex:
            properties.append((words[2], sizes[words[1]]))
    vertex = numpy.frombuffer(data, dtype=numpy.dtype(properties), count=count, offset=end)
    points = numpy.stack([vertex["x"], vertex["y"], vertex["z"]], axis=1).astype(numpy.float64)
    return points, vertex["quality"].astype(numpy.float64)


def nearest_thickness(points, queries, thickness, cell):
    """Thickness of the nearest of `points` to each query within `cell`
    (NaN when none is): grid cells of side `cell`, the 27 around each query."""
    keys = numpy.floor(points / cell).astype(numpy.int64)
    # Codes cover the cells from two below the lowest to two above the
    # highest: the 27 around any query that can have a vertex near it.
    base = keys.min(axis=0) - 2
    span = keys.max(axis=0) - base + 3

    def code(k):
        k = k - base
        return (k[:, 0] * span[1] + k[:, 1]) * span[2] + k[:, 2]

    order = numpy.argsort(code(keys), kind="stable")
    sorted_codes = code(keys)[order]
    query_keys = numpy.floor(queries / cell).astype(numpy.int64)
    inside = numpy.all((query_keys >= base + 1) & (query_keys <= base + span - 2), axis=1)
    best = numpy.full(len(queries), numpy.inf)
    result = numpy.full(len(queries), numpy.nan)
    for offset in numpy.array(numpy.meshgrid([-1, 0, 1], [-1, 0, 1], [-1, 0, 1])).reshape(3, -1).T:
        c = code(numpy.where(inside[:, None], query_keys + offset, base + 1))
        lo = numpy.searchsorted(sorted_codes, c, side="left")
        hi = numpy.searchsorted(sorted_codes, c, side="right")
        hi = numpy.where(inside, hi, lo)
        for j in range(int((hi - lo).max(initial=0))):
            has = lo + j < hi
            index = order[numpy.minimum(lo + j, len(order) - 1)]
            d = numpy.linalg.norm(points[index] - queries, axis=1)
            better = has & (d < best) & (d <= cell)
            best = numpy.where(better, d, best)
            result = numpy.where(better, thickness[index], result)
    return result


def main():
    obj, ply, toolbox, threshold, voxel = sys.argv[1:6]
    threshold, voxel = float(threshold), float(voxel)
    vertices, triangles = read_obj(obj)
    map_points, map_thickness = read_map(ply)
    marked = json.load(open(toolbox))
    corners = vertices[triangles]
    area = 0.5 * numpy.linalg.norm(numpy.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    centre = corners.mean(axis=1)
    samples = [centre] + [0.5 * (centre + corners[:, k]) for k in range(3)]
    readings = numpy.stack([nearest_thickness(map_points, s, map_thickness, 2 * voxel) for s in samples], axis=1)
    off = numpy.all(numpy.isnan(readings), axis=1)
    fabvdb_thin = numpy.any(readings < threshold, axis=1)  # NaN compares false
    toolbox_thin = numpy.zeros(len(triangles), dtype=bool)
    toolbox_thin[marked["thin"]] = True
    classes = numpy.where(off, OFF_SURFACE,
                          numpy.where(toolbox_thin & fabvdb_thin, BOTH_THIN,
                                      numpy.where(toolbox_thin, ONLY_TOOLBOX,
                                                  numpy.where(fabvdb_thin, ONLY_FABVDB, BOTH_THICK))))
    total = area.sum()
    names = ["both_thick", "both_thin", "only_toolbox", "only_fabvdb", "off_surface"]
    result = {"triangles": len(triangles), "area": total}
    for k, name in enumerate(names):
        result[name] = float(area[classes == k].sum() / total)
    own = numpy.zeros(len(triangles), dtype=bool)
    own[marked["own"]] = True
    result["only_toolbox_hit_only"] = float(area[(classes == ONLY_TOOLBOX) & ~own].sum() / total)
    result["off_surface_toolbox_thin"] = float(area[off & toolbox_thin].sum() / total)
    result["toolbox_thin"] = float(area[toolbox_thin].sum() / total)
    result["fabvdb_thin"] = float(area[fabvdb_thin].sum() / total)
    print(json.dumps(result))
    if len(sys.argv) > 6:
        numpy.savetxt(sys.argv[6], classes, fmt="%d")


if __name__ == "__main__":
    main()
