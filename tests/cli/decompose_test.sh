# decompose_test.sh — `fabvdb decompose`: a run writes the three files and the
# report; over gamma, a warning names the part and where; edits from a file are applied (a merge of the two parts of the torus
# leaves one part; a smoothing stroke across the boundary is recorded); bad options exit 1 and a bad edits file exits 2, both
# without creating the output folder; `fabvdb info` reads decomposition.ply.
source "$(dirname "$0")/lib.sh"

expect_exit 0 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/torus" --low-res 1200 --report "$WORK/r.json" --quiet
expect_match "$STDOUT" '^2 parts'
for f in decomposition.json decomposition.ply deformation.ply; do
  if [ -f "$WORK/torus/$f" ]; then passed=$((passed + 1)); else fail "missing $WORK/torus/$f"; fi
done
expect_match "$(cat "$WORK/r.json")" '"part_count": 2'
expect_match "$(cat "$WORK/torus/decomposition.json")" '"parting_direction"'
expect_exit 0 "$FABVDB" info "$WORK/torus/decomposition.ply"

# Merge the two parts through points on the outer equator of the torus (one on each part: they split across the y axis).
cat > "$WORK/merge.json" <<'JSON'
{"edits": [{"type": "merge", "points": [[1.0, 0.25, 0.0], [1.0, -0.25, 0.0]]}]}
JSON
expect_exit 0 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/merged" --low-res 1200 --edits "$WORK/merge.json" \
  --report "$WORK/m.json" --quiet
expect_match "$STDOUT" '^1 parts'
expect_match "$(cat "$WORK/m.json")" '"type": "merge"'

# A smoothing stroke on the boundary (the y = 0 plane, where the two parts meet) is applied and recorded.
cat > "$WORK/smooth.json" <<'JSON'
{"edits": [{"type": "smooth", "points": [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]], "radius": 0.6}]}
JSON
expect_exit 0 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/smoothed" --low-res 1200 --smoothing 0 \
  --edits "$WORK/smooth.json" --report "$WORK/s.json" --quiet
expect_match "$STDOUT" '^2 parts'
expect_match "$(cat "$WORK/s.json")" '"type": "smooth"'

# Over gamma (a gamma no decomposition meets): a warning on stderr, even with
# --quiet, names the part that carries most of the energy and where it is.
expect_exit 0 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/over" --low-res 1200 --parts 2 --gamma 1e-12 --quiet
expect_match "$STDOUT" 'WARNING: over gamma'
expect_match "$STDERR" 'warning: the total moldability energy .* is not under gamma 1e-12 with 2 parts: part [01] [(]around .* mm[)] carries'

cat > "$WORK/bad.json" <<'JSON'
{"edits": [{"type": "cut", "points": [[0, 0, 0]]}]}
JSON
expect_exit 2 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/bad" --low-res 1200 --edits "$WORK/bad.json" --quiet
expect_match "$STDERR" 'at least two points'
expect_no_file "$WORK/bad"
expect_exit 1 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/bad" --parts two
expect_exit 1 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/bad" --gamma -1
expect_exit 1 "$FABVDB" decompose "$MESHES/torus.obj" -o "$WORK/bad" --smoothing -1
expect_no_file "$WORK/bad"
finish
