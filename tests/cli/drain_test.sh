#!/bin/bash
# fabvdb drain and powder-sim end to end on the shared sphere mesh: the drilled
# part is written, the report lists holes with the documented keys, the heat
# map is a binary PLY with colours and quality, the simulation reads the
# report; --target takes a percentage; bad inputs give exit code 2 (bad
# options 1) and leave no output.
set -u
fabvdb="$1"; data="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$fabvdb" info "$data/meshes/sphere.obj" --report "$work/info.json" --quiet || fail "info"
"$fabvdb" drain "$data/meshes/sphere.obj" --fit 40mm -o "$work/out.stl" --wall 3mm --holes 2 --patches 600 \
    --heatmap "$work/heat.ply" --report "$work/r.json" --quiet || fail "drain exit $?"
[ -s "$work/out.stl" ] || fail "no output mesh"
for key in '"holes"' '"center"' '"axis"' '"diameter"' '"cavity"' '"predicted_residual_fraction"' \
           '"predicted_residual_mm3"' '"baseline_residual_fraction"' '"timings"'; do
    grep -q "$key" "$work/r.json" || fail "report lacks $key"
done
head -c 200 "$work/heat.ply" | grep -q "format binary_little_endian" || fail "heat map not binary PLY"
head -c 400 "$work/heat.ply" | grep -q "property float quality" || fail "heat map lacks quality"
"$fabvdb" powder-sim "$work/out.stl" --holes "$work/r.json" --turns 3 --report "$work/s.json" --quiet \
    || fail "powder-sim exit $?"
grep -q '"residual_fraction"' "$work/s.json" || fail "simulation report lacks residual_fraction"

echo '{"holes": [{"center": [0, 0]}]}' > "$work/bad.json"
"$fabvdb" powder-sim "$work/out.stl" --holes "$work/bad.json" --quiet 2>/dev/null
[ $? -eq 2 ] || fail "bad holes JSON: expected exit 2"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --target 150% --quiet 2>/dev/null
[ $? -eq 1 ] || fail "--target 150%: expected exit 1"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --target 1x --quiet 2>/dev/null
[ $? -eq 1 ] || fail "--target 1x: expected exit 1"
"$fabvdb" drain "$data/meshes/sphere.obj" -o "$work/never.stl" --keep-out "$work/missing.json" --quiet 2>/dev/null
[ $? -eq 2 ] || fail "missing keep-out: expected exit 2"
[ ! -e "$work/never.stl" ] || fail "a failed drain left an output"
echo ok
