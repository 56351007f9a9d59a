# mold_test.sh — `fabvdb mold`: a run on the bundled sphere (decomposed first)
# writes the parts, the mold pieces, the decomposition and the report, and
# every STL is closed by `fabvdb info`; its decomposition file is read back,
# also for one common mold;
# the same file for another model or scale, a malformed file and a file with
# a part missing exit 2 without creating the folder; bad options exit 1.
source "$(dirname "$0")/lib.sh"

COARSE=(--voxel 0.8mm --mold-margin 6mm --quiet)
expect_exit 0 "$FABVDB" mold "$SOURCE/data/sphere.obj" --fit 40mm -o "$WORK/sphere" --parts 2 --low-res 1500 --shell 3mm \
  "${COARSE[@]}" --report "$WORK/r.json"
expect_match "$STDOUT" '^2 parts'
for f in parts/part_00.stl parts/part_01.stl molds/part_00_top.stl molds/part_00_bottom.stl \
  molds/part_01_top.stl molds/part_01_bottom.stl decomposition/decomposition.json; do
  if [ -f "$WORK/sphere/$f" ]; then passed=$((passed + 1)); else fail "missing $WORK/sphere/$f"; fi
done
for f in "$WORK"/sphere/parts/*.stl "$WORK"/sphere/molds/*.stl; do
  expect_exit 0 "$FABVDB" info "$f"
  expect_match "$STDOUT" 'closed (watertight) *yes'
  expect_match "$STDOUT" 'non-manifold edges *0'
  expect_match "$STDOUT" 'degenerate triangles *0'
  expect_match "$STDOUT" 'self-intersecting pairs *0'
done
expect_match "$(cat "$WORK/r.json")" '"hausdorff_ratio"'
expect_match "$(cat "$WORK/r.json")" '"file": "parts/part_01.stl"'

D="$WORK/sphere/decomposition/decomposition.json"
expect_exit 0 "$FABVDB" mold "$SOURCE/data/sphere.obj" --fit 40mm -o "$WORK/again" --decomposition "$D" "${COARSE[@]}"
expect_match "$STDOUT" '^2 parts'

expect_exit 0 "$FABVDB" mold "$SOURCE/data/sphere.obj" --fit 40mm -o "$WORK/common" --decomposition "$D" \
  --common-mold "${COARSE[@]}" --report "$WORK/c.json"
for f in common_top.stl common_bottom.stl; do
  expect_exit 0 "$FABVDB" info "$WORK/common/molds/$f"
  expect_match "$STDOUT" 'closed (watertight) *yes'
  expect_match "$STDOUT" 'degenerate triangles *0'
  expect_match "$STDOUT" 'self-intersecting pairs *0'
done
expect_match "$(cat "$WORK/c.json")" '"common_mold_offset"'

expect_exit 2 "$FABVDB" mold "$SOURCE/data/torus.obj" --fit 40mm -o "$WORK/bad" --decomposition "$D" "${COARSE[@]}"
expect_match "$STDERR" 'does not belong'
expect_exit 2 "$FABVDB" mold "$SOURCE/data/sphere.obj" --fit 80mm -o "$WORK/bad" --decomposition "$D" "${COARSE[@]}"
expect_match "$STDERR" 'does not belong'
python3 - "$D" "$WORK/missing.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
del d["parts"][1]
json.dump(d, open(sys.argv[2], "w"))
PY
expect_exit 2 "$FABVDB" mold "$SOURCE/data/sphere.obj" --fit 40mm -o "$WORK/bad" --decomposition "$WORK/missing.json" \
  "${COARSE[@]}"
expect_match "$STDERR" 'part 1 is missing'
echo '{"format": "fabvdb decomposition", "version": 1, "parts": [' > "$WORK/malformed.json"
expect_exit 2 "$FABVDB" mold "$SOURCE/data/sphere.obj" --fit 40mm -o "$WORK/bad" --decomposition "$WORK/malformed.json"
expect_match "$STDERR" 'malformed.json'
expect_no_file "$WORK/bad"
expect_exit 1 "$FABVDB" mold "$SOURCE/data/sphere.obj" -o "$WORK/bad" --decomposition "$D" --parts 3
expect_exit 1 "$FABVDB" mold "$SOURCE/data/sphere.obj" -o "$WORK/bad" --mold-margin -1mm
expect_no_file "$WORK/bad"
finish
