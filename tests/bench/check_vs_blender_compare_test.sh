# check_vs_blender_compare_test.sh — bench/check_vs_blender_compare.py on
# a 10 × 10 × 0.3 mm plate (12 triangles) and one triangle 40 mm away, with
# a thickness map written here: points 0.1 mm apart over the plate's top
# and bottom reading 0.3 mm, none near the far triangle. The Toolbox's
# marks are given: the top's two triangles (by their own rays) and the far
# one. The shares of the area are known by hand: top 100, bottom 100,
# sides 12, far triangle 2 mm².
# Arguments: the fabvdb binary, the shared data folder, the source folder.
source "$(dirname "$0")/../cli/lib.sh"
COMPARE=(/usr/bin/python3 "$SOURCE/bench/check_vs_blender_compare.py")

/usr/bin/python3 - "$WORK" <<'PY'
import json, struct, sys
work = sys.argv[1]
with open(work + "/plate.obj", "w") as f:
    for i in range(8):
        f.write("v %g %g %g\n" % (10 * (i >> 2 & 1), 10 * (i >> 1 & 1), 0.3 * (i & 1)))
    f.write("v 50 0 0\nv 52 0 0\nv 50 2 0\n")
    # x = 0, x = 10, y = 0, y = 10, z = 0 (triangles 8, 9), z = 0.3 (10, 11), outward
    for a, b, c, d in ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)):
        f.write("f %d %d %d\nf %d %d %d\n" % tuple(i + 1 for i in (a, b, c, a, c, d)))
    f.write("f 9 10 11\n")
points = [(0.1 * i, 0.1 * j, z) for i in range(101) for j in range(101) for z in (0.0, 0.3)]
with open(work + "/map.ply", "wb") as f:
    f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
             "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
             "property float quality\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"
             % len(points)).encode())
    for p in points:
        f.write(struct.pack("<fffBBBf", p[0], p[1], p[2], 0, 0, 0, 0.3))
json.dump({"triangles": 13, "left_out": [], "thin": [10, 11, 12], "own": [10, 11]}, open(work + "/marks.json", "w"))
PY
share() {  # KEY of the compare's JSON in $STDOUT, to 6 places
  printf '%s' "$STDOUT" | python3 -c 'import json, sys; print("%.6f" % json.load(sys.stdin)[sys.argv[1]])' "$1"
}
ratio() { python3 -c 'import sys; print("%.6f" % (float(sys.argv[1]) / 214))' "$1"; }  # of the 214 mm²

# Threshold 0.5 mm, voxel 0.1 mm: the plate is thin by fabvdb everywhere
# (the sides' points lie within two voxels of the map's edge points).
expect_exit 0 "${COMPARE[@]}" "$WORK/plate.obj" "$WORK/map.ply" "$WORK/marks.json" 0.5 0.1 "$WORK/classes.txt"
expect_match "$(share both_thin)" "^$(ratio 100)$"
expect_match "$(share only_fabvdb)" "^$(ratio 112)$"
expect_match "$(share off_surface)" "^$(ratio 2)$"
expect_match "$(share off_surface_toolbox_thin)" "^$(ratio 2)$"
expect_match "$(share both_thick)" '^0.000000$'
expect_match "$(share only_toolbox)" '^0.000000$'
expect_match "$(tr '\n' ' ' <"$WORK/classes.txt")" '^3 3 3 3 3 3 3 3 3 3 1 1 4 $'

# Threshold 0.25 mm: nothing thin by fabvdb; the top is the Toolbox's alone,
# by its own rays (none of it only as a face hit).
expect_exit 0 "${COMPARE[@]}" "$WORK/plate.obj" "$WORK/map.ply" "$WORK/marks.json" 0.25 0.1
expect_match "$(share only_toolbox)" "^$(ratio 100)$"
expect_match "$(share both_thick)" "^$(ratio 112)$"
expect_match "$(share only_toolbox_hit_only)" '^0.000000$'
expect_match "$(share fabvdb_thin)" '^0.000000$'

finish
