# check_test.sh — `fabvdb check` end to end on parts whose answer is known by
# construction (boxes written as OBJ here): a thick plate passes (exit 0), a
# thin one fails (exit 5, the thin wall's figure in the report near the
# plate's thickness), one just above the minimum warns (exit 0, exit 5 with
# --fail-on warn); a cube with a sealed cavity fails for resin, passes for
# FDM; a pocket open toward the vat is a resin cup (a warning: exit 5 with
# --fail-on warn, the summary naming it), none turned toward the plate; the
# same part in inches warns with the 25.4 scale and passes scaled;
# the build volume; the heat map and its legend; a farm's JSON profile; the
# batch recipe, whose summary names the failing order and why; bad inputs
# and options with the documented exit codes and messages naming the file.
source "$(dirname "$0")/lib.sh"

# box FILE X Y Z [SCALE]: an OBJ box from the origin to (X, Y, Z), times SCALE.
box() {
  python3 - "$@" <<'PY'
import sys
path, x, y, z = sys.argv[1], *map(float, sys.argv[2:5])
s = float(sys.argv[5]) if len(sys.argv) > 5 else 1.0
with open(path, 'w') as f:
    for i in range(8):
        f.write('v %r %r %r\n' % (x * s * (i & 1), y * s * (i >> 1 & 1), z * s * (i >> 2 & 1)))
    for a, b, c in [(0,2,3),(0,3,1),(4,5,7),(4,7,6),(0,1,5),(0,5,4),(2,6,7),(2,7,3),(0,4,6),(0,6,2),(1,3,7),(1,7,5)]:
        f.write('f %d %d %d\n' % (a + 1, b + 1, c + 1))
PY
}
# cavity FILE: a 20 mm cube with a sealed 10 mm cubic void in its middle.
cavity() {
  python3 - "$1" <<'PY'
import sys
faces = [(0,2,3),(0,3,1),(4,5,7),(4,7,6),(0,1,5),(0,5,4),(2,6,7),(2,7,3),(0,4,6),(0,6,2),(1,3,7),(1,7,5)]
with open(sys.argv[1], 'w') as f:
    for lo, hi in ((0, 20), (5, 15)):
        for i in range(8):
            f.write('v %d %d %d\n' % tuple(hi if (i >> k) & 1 else lo for k in range(3)))
    for a, b, c in faces:
        f.write('f %d %d %d\n' % (a + 1, b + 1, c + 1))
    for a, b, c in faces:
        f.write('f %d %d %d\n' % (a + 9, c + 9, b + 9))
PY
}
# cup FILE: a 10 x 10 x 8 mm block with a 6 x 6 x 6 mm pocket open at z = 8,
# written as the faces between filled and empty 2 mm cells (one clean shell).
cup() {
  python3 - "$1" <<'PY'
import sys
filled = lambda i, j, k: 0 <= i < 5 and 0 <= j < 5 and 0 <= k < 4 and not (1 <= i <= 3 and 1 <= j <= 3 and k >= 1)
index, faces = {}, []
def v(p):
    return index.setdefault(p, len(index) + 1)
for i in range(-1, 6):
    for j in range(-1, 6):
        for k in range(-1, 5):
            if not filled(i, j, k):
                continue
            for axis in range(3):
                for side in (0, 1):
                    n = [i, j, k]
                    n[axis] += 1 if side else -1
                    if filled(*n):
                        continue
                    a, b = (axis + 1) % 3, (axis + 2) % 3
                    quad = []
                    for da, db in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [i, j, k]
                        p[axis] += side
                        p[a] += da
                        p[b] += db
                        quad.append(v(tuple(2 * c for c in p)))
                    if not side:
                        quad.reverse()
                    faces += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
with open(sys.argv[1], 'w') as f:
    for p, _ in sorted(index.items(), key=lambda item: item[1]):
        f.write('v %d %d %d\n' % p)
    for face in faces:
        f.write('f %d %d %d\n' % face)
PY
}
# value FILE POINTER: a number or string of a JSON report at a JSON pointer.
value() {
  python3 - "$1" "$2" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
for key in sys.argv[2].strip('/').split('/'):
    v = v[int(key)] if isinstance(v, list) else v[key]
print(v)
PY
}
# near A B TOLERANCE: |A - B| <= TOLERANCE.
near() { python3 -c "import sys; sys.exit(0 if abs($1 - $2) <= $3 else 1)"; }

box "$WORK/thick.obj" 20 15 1.5
box "$WORK/thin.obj" 20 15 0.3
box "$WORK/close.obj" 20 15 0.58
cavity "$WORK/cavity.obj"
cup "$WORK/cup.obj"
box "$WORK/part.obj" 50 30 20
box "$WORK/part_in.obj" 50 30 20 0.03937007874015748

expect_exit 0 "$FABVDB" check "$WORK/thick.obj" --process sla --voxel 0.08mm --report "$WORK/thick.json"
expect_match "$STDOUT" 'thick.obj: pass for sla'
expect_match "$STDOUT" 'wall thickness   pass'
expect_exit 0 test "$(value "$WORK/thick.json" /verdict)" = pass

expect_exit 5 "$FABVDB" check "$WORK/thin.obj" --process sla --voxel 0.08mm --report "$WORK/thin.json"
expect_match "$STDOUT" 'wall thickness   fail'
expect_match "$STDERR" '^fabvdb check: fail: wall thickness: '
expect_exit 0 near "$(value "$WORK/thin.json" /checks/wall_thickness/min_thickness)" 0.3 0.04
expect_exit 0 test -f "$WORK/thin.json"

expect_exit 0 "$FABVDB" check "$WORK/close.obj" --process sla --voxel 0.08mm --report "$WORK/close.json"
expect_exit 0 test "$(value "$WORK/close.json" /checks/wall_thickness/status)" = warn
expect_exit 5 "$FABVDB" check "$WORK/close.obj" --process sla --voxel 0.08mm --fail-on warn
expect_match "$STDERR" '^fabvdb check: warn: '

expect_exit 5 "$FABVDB" check "$WORK/cavity.obj" --process sla --report "$WORK/cavity.json"
expect_match "$STDOUT" 'trapped volumes  fail  1 sealed cavities'
expect_exit 0 near "$(value "$WORK/cavity.json" /checks/trapped_volumes/cavities/0/volume)" 1000 30
expect_exit 0 near "$(value "$WORK/cavity.json" /checks/trapped_volumes/cavities/0/center/0)" 10 0.3
expect_exit 0 "$FABVDB" check "$WORK/cavity.obj" --process fdm --report "$WORK/cavity_fdm.json"
expect_exit 0 test "$(value "$WORK/cavity_fdm.json" /checks/trapped_volumes/status)" = pass

# A cup toward the vat warns (suction, trapped resin); toward the plate it drains.
expect_exit 0 "$FABVDB" check "$WORK/cup.obj" --process sla --voxel 0.25mm --report "$WORK/cup.json"
expect_match "$STDOUT" 'cups             warn  1 cups hold'
expect_exit 0 test "$(value "$WORK/cup.json" /checks/mesh/status)" = pass
expect_exit 0 near "$(value "$WORK/cup.json" /checks/cups/cups/0/volume)" 216 9
expect_exit 5 "$FABVDB" check "$WORK/cup.obj" --process sla --voxel 0.25mm --fail-on warn
expect_match "$STDERR" '^fabvdb check: warn: cups: '
expect_exit 0 "$FABVDB" check "$WORK/cup.obj" --process sla --voxel 0.25mm --up -z --report "$WORK/cup_down.json"
expect_exit 0 test "$(value "$WORK/cup_down.json" /checks/cups/status)" = pass

# The same part in mm and in inches.
expect_exit 0 "$FABVDB" check "$WORK/part.obj" --process fdm --report "$WORK/mm.json"
expect_exit 0 test "$(value "$WORK/mm.json" /checks/units/status)" = pass
expect_exit 5 "$FABVDB" check "$WORK/part_in.obj" --process fdm --report "$WORK/in.json"
expect_match "$STDOUT" 'if it is in in, scale by 25.4'
expect_exit 0 test "$(value "$WORK/in.json" /checks/units/status)" = warn
expect_exit 0 test "$(value "$WORK/in.json" /checks/units/suggested_scale)" = 25.4
expect_exit 0 "$FABVDB" check "$WORK/part_in.obj" --process fdm --scale 25.4 --report "$WORK/scaled.json"
expect_exit 0 test "$(value "$WORK/scaled.json" /checks/units/status)" = pass

# Build volume: fits, fits turned, does not fit; an orientation.
expect_exit 0 "$FABVDB" check "$WORK/part.obj" --process fdm --build-volume 250x210x220mm --report "$WORK/fit.json"
expect_exit 0 test "$(value "$WORK/fit.json" /checks/build_volume/status)" = pass
expect_exit 0 "$FABVDB" check "$WORK/part.obj" --process fdm --build-volume 3x6x5cm --report "$WORK/turned.json"
expect_exit 0 test "$(value "$WORK/turned.json" /checks/build_volume/status)" = warn
expect_exit 5 "$FABVDB" check "$WORK/part.obj" --process fdm --build-volume 1x1x1in
expect_match "$STDOUT" 'build volume     fail'
expect_exit 0 "$FABVDB" check "$WORK/part.obj" --process fdm --orientation 1,0,0 --build-volume 250x210x220mm \
  --report "$WORK/standing.json"
expect_exit 0 near "$(value "$WORK/standing.json" /checks/build_volume/size/2)" 50 1e-6

# The heat map and its legend.
expect_exit 0 "$FABVDB" check "$WORK/thick.obj" --voxel 0.1mm --thickness-map "$WORK/walls.ply" --quiet
expect_exit 0 test -s "$WORK/walls.ply"
expect_exit 0 test -s "$WORK/walls.png"
expect_match "$(head -c 400 "$WORK/walls.ply" | tr -d '\0')" 'property float quality'

# A farm's own profile: the thin plate passes a 0.25 mm minimum.
printf '{"base": "sla", "name": "fine resin", "min_wall": 0.25, "min_pin": 0.25, "min_feature": 0.25}\n' > "$WORK/fine.json"
expect_exit 0 "$FABVDB" check "$WORK/thin.obj" --process "$WORK/fine.json" --voxel 0.05mm --report "$WORK/fine_report.json"
expect_match "$STDOUT" 'for fine resin'
expect_exit 0 test "$(value "$WORK/fine_report.json" /checks/wall_thickness/status)" = pass

# The batch recipe: the summary names the failing order and why.
mkdir -p "$WORK/orders"
cp "$WORK/thick.obj" "$WORK/orders/good.obj"
cp "$WORK/thin.obj" "$WORK/orders/flimsy.obj"
printf 'fabvdb-job 1\ncheck {input} --process sla --voxel 0.08mm --report {out}/check.json --quiet\n' > "$WORK/check.job"
expect_exit 5 "$FABVDB" batch "$WORK/check.job" --inputs "$WORK/orders/*.obj" --out "$WORK/checked" \
  --report "$WORK/batch.json" --quiet
expect_exit 0 python3 - "$WORK/batch.json" <<'PY'
import json, sys
tasks = {t['task']: t for t in json.load(open(sys.argv[1]))['task_list']}
assert tasks['good']['status'] == 'done', tasks['good']
assert tasks['flimsy']['status'] == 'failed' and tasks['flimsy']['exit_code'] == 5, tasks['flimsy']
assert 'wall thickness' in tasks['flimsy']['message'], tasks['flimsy']['message']
PY

# Bad inputs and options.
expect_exit 2 "$FABVDB" check "$WORK/missing.stl"
expect_match "$STDERR" 'missing.stl'
printf 'solid nothing\nendsolid\n' > "$WORK/empty.stl"
expect_exit 2 "$FABVDB" check "$WORK/empty.stl"
expect_match "$STDERR" 'empty.stl'
printf 'garbage' > "$WORK/garbage.ply"
expect_exit 2 "$FABVDB" check "$WORK/garbage.ply"
expect_match "$STDERR" 'garbage.ply'
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --process laser
expect_match "$STDERR" "no process 'laser'"
expect_exit 2 "$FABVDB" check "$WORK/part.obj" --process "$WORK/none.json"
expect_match "$STDERR" 'none.json'
printf '{"min_wall": "thin"}' > "$WORK/bad_profile.json"
expect_exit 2 "$FABVDB" check "$WORK/part.obj" --process "$WORK/bad_profile.json"
expect_match "$STDERR" 'bad_profile.json'
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --up +w
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --orientation 0,0,0
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --orientation 1,2
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --up +z --orientation 0,0,1
expect_match "$STDERR" 'not both'
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --build-volume 250x210
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --build-volume 250x210x0mm
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --fail-on maybe
expect_exit 1 "$FABVDB" check "$WORK/part.obj" --voxel 0mm
expect_exit 1 "$FABVDB" check
expect_match "$STDERR" 'missing input file'

finish
