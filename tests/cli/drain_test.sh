#!/bin/bash
# fabvdb drain and powder-sim end to end on the shared sphere mesh: the drilled
# part is written, the report lists holes with the documented keys, the heat
# maps are binary PLYs with colours and quality and PNG legends, the
# simulation reads the report and replays its cleaning routine exactly;
# --target takes a percentage; a part too thin for a cavity comes back solid
# without holes; bad inputs give exit code 2 (bad options 1, from the
# library's range checks) and leave no output.
set -u
fabvdb="$1"; data="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$fabvdb" info "$data/meshes/sphere.obj" --report "$work/info.json" --quiet || fail "info"
"$fabvdb" drain "$data/meshes/sphere.obj" --fit 40mm -o "$work/out.stl" --wall 3mm --holes 2 --patches 600 \
    --heatmap "$work/heat.ply" --report "$work/r.json" --quiet || fail "drain exit $?"
[ -s "$work/out.stl" ] || fail "no output mesh"
for key in '"holes"' '"center"' '"axis"' '"diameter"' '"cavity"' '"predicted_residual_fraction"' \
           '"predicted_residual_volume"' '"baseline_residual_fraction"' '"timings"'; do
    grep -q "$key" "$work/r.json" || fail "report lacks $key"
done
for map in heat heat_left; do
    head -c 200 "$work/$map.ply" | grep -q "format binary_little_endian" || fail "$map.ply not binary PLY"
    head -c 600 "$work/$map.ply" | grep -q "property float quality" || fail "$map.ply lacks quality"
    # A PNG legend: the signature, then an IHDR of a picture taller than wide.
    python3 - "$work/$map.png" <<'PY' || fail "$map.png is not a PNG colour bar"
import struct, sys
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n' and data[12:16] == b'IHDR'
width, height = struct.unpack('>II', data[16:24])
assert 50 <= width < height <= 1000, (width, height)
PY
done
"$fabvdb" powder-sim "$work/out.stl" --holes-from "$work/r.json" --turns 3 --report "$work/s.json" --quiet \
    || fail "powder-sim exit $?"
grep -q '"residual_fraction"' "$work/s.json" || fail "simulation report lacks residual_fraction"

# The recommended cleaning routine: printed on the terminal, replayed exactly
# by powder-sim --routine (same gravities, in order, first turn included).
"$fabvdb" drain "$data/meshes/sphere.obj" --fit 40mm -o "$work/out2.stl" --wall 3mm --holes 2 --patches 600 \
    --report "$work/r2.json" > "$work/drain.txt" 2>/dev/null || fail "drain (routine) exit $?"
grep -q "cleaning routine" "$work/drain.txt" || fail "the routine is not printed"
grep -q "as printed" "$work/drain.txt" || fail "the routine's first turn is not printed"
"$fabvdb" powder-sim "$work/out2.stl" --holes-from "$work/r2.json" --routine "$work/r2.json" --report "$work/s2.json" \
    --quiet || fail "powder-sim --routine exit $?"
python3 - "$work/r2.json" "$work/s2.json" <<'PY' || fail "powder-sim did not replay the reported routine"
import json, sys
drain, sim = (json.load(open(p)) for p in sys.argv[1:3])
steps = [step['gravity'] for step in drain['routine']]
assert len(steps) >= 9, len(steps)
assert sim['turns'] == len(steps) and len(sim['routine']) == len(steps)
for a, b in zip(steps, sim['routine']):
    assert max(abs(x - y) for x, y in zip(a, b)) < 1e-12, (a, b)
assert 0 <= drain['routine_residual_fraction'] <= 1
spread = drain['random_routines']
assert spread['min_fraction'] <= spread['mean_fraction'] <= spread['max_fraction']
PY
"$fabvdb" powder-sim "$work/out2.stl" --holes-from "$work/r2.json" --routine "$work/r2.json" --turns 3 --quiet \
    2>/dev/null
[ $? -eq 1 ] || fail "--routine with --turns: expected exit 1"
echo '{"routine": [{"gravity": [0, 0]}]}' > "$work/badroutine.json"
"$fabvdb" powder-sim "$work/out2.stl" --holes-from "$work/r2.json" --routine "$work/badroutine.json" --quiet 2>/dev/null
[ $? -eq 2 ] || fail "bad routine JSON: expected exit 2"

# A part too thin for a cavity needs no holes: written solid, exit 0, a warning.
"$fabvdb" drain "$data/meshes/sphere.obj" --fit 40mm -o "$work/solid.stl" --wall 25mm --heatmap "$work/none.ply" \
    --report "$work/solid.json" 2>"$work/solid.err" >"$work/solid.out" || fail "drain of a thin part: exit $?"
grep -q "warning: .*no cavity" "$work/solid.err" || fail "no warning for a part without cavity"
grep -q '"cavity_count": 0' "$work/solid.json" || fail "cavity_count is not 0"
grep -q '"holes": \[\]' "$work/solid.json" || fail "holes drilled in a part without cavity"
[ ! -e "$work/none.ply" ] || fail "a heat map of no cavity"
"$fabvdb" info "$work/solid.stl" --report "$work/solid-info.json" --quiet || fail "info of the solid part"
grep -q '"closed": true' "$work/solid-info.json" || fail "the solid part is not closed"
grep -q '"components": 1' "$work/solid-info.json" || fail "the solid part is not one shell"

echo '{"holes": [{"center": [0, 0]}]}' > "$work/bad.json"
"$fabvdb" powder-sim "$work/out.stl" --holes-from "$work/bad.json" --quiet 2>/dev/null
[ $? -eq 2 ] || fail "bad holes JSON: expected exit 2"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --target 150% --quiet 2>/dev/null
[ $? -eq 1 ] || fail "--target 150%: expected exit 1"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --target 1x --quiet 2>/dev/null
[ $? -eq 1 ] || fail "--target 1x: expected exit 1"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --keep-out "$work/missing.json" --quiet 2>/dev/null
[ $? -eq 2 ] || fail "missing keep-out: expected exit 2"
# Ranges are checked once, in the library; the command maps its invalid-argument status to exit 1.
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --patches 5 --quiet 2>"$work/err"
[ $? -eq 1 ] || fail "--patches 5: expected exit 1"
grep -q "patch_count must be >= 10" "$work/err" || fail "--patches 5: the message does not name the range"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --repose 95deg --quiet 2>/dev/null
[ $? -eq 1 ] || fail "--repose 95deg: expected exit 1"
"$fabvdb" powder-sim "$work/out.stl" --holes-from "$work/r.json" --turns 0 --quiet 2>/dev/null
[ $? -eq 1 ] || fail "powder-sim --turns 0: expected exit 1"
[ ! -e "$work/never.stl" ] || fail "a failed drain left an output"
echo ok
