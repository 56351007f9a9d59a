# corpus_check_cavity_test.sh — corpus_check's cavity count (`solid
# --cavity-wall --reference`) reads a reference stored inside out as the same
# solid: a 20 mm cube with a void made 0.2 mm inside its faces is one cavity made
# against the solid cube and against that cube turned inside out; the same
# hollow cube given as its own reference holds its void already (the input's
# own, no cavity made), as given and inside out.
# Arguments: the fabvdb binary, the shared data folder, the source folder,
# the corpus_check binary.
source "$(dirname "$0")/../cli/lib.sh"
CHECKER="$4"

# box.obj: the solid cube [0, 20]³; hollow.obj: it with the void [0.2, 19.8]³
# (its walls within 1% of the diagonal of the cube's faces, so the checker
# asks the reference's winding number), whose faces face into the void; hollow.stl the same as an ASCII STL (the
# checker reads outputs as STL).
python3 - "$WORK" <<'PY'
import sys
def box(lo, hi, inward):
    corner = [tuple(hi if i >> (2 - k) & 1 else lo for k in range(3)) for i in range(8)]
    for a, b, c, d in ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)):
        for t in ((a, b, c), (a, c, d)):
            yield [corner[i] for i in (t[::-1] if inward else t)]
def write_obj(path, triangles):
    with open(path, "w") as f:
        for n, t in enumerate(triangles):
            for p in t:
                f.write("v %g %g %g\n" % p)
            f.write("f %d %d %d\n" % (3 * n + 1, 3 * n + 2, 3 * n + 3))
solid = list(box(0, 20, False))
hollow = solid + list(box(0.2, 19.8, True))
write_obj(sys.argv[1] + "/box.obj", solid)
write_obj(sys.argv[1] + "/hollow.obj", hollow)
with open(sys.argv[1] + "/hollow.stl", "w") as f:
    f.write("solid hollow\n")
    for t in hollow:
        f.write("facet normal 0 0 0\nouter loop\n" + "".join("vertex %g %g %g\n" % p for p in t)
                + "endloop\nendfacet\n")
    f.write("endsolid hollow\n")
PY
"$CHECKER" flip "$WORK/box.obj" "$WORK/box_inside_out.obj" >/dev/null
"$CHECKER" flip "$WORK/hollow.obj" "$WORK/hollow_inside_out.obj" >/dev/null
count() {  # cavities made and the input's own voids in hollow.obj against reference $1
  "$CHECKER" solid "$WORK/hollow.stl" --reference "$WORK/$1" --fit 20 --cavity-wall |
    python3 -c 'import json, sys; r = json.load(sys.stdin); print(r["cavity_shells"], r["input_void_shells"])'
}
for reference in box.obj box_inside_out.obj; do
  expect_match "$(count $reference)" '^1 0$'
done
for reference in hollow.obj hollow_inside_out.obj; do
  expect_match "$(count $reference)" '^0 1$'
done
finish
