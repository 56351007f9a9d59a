#!/usr/bin/env bash
# bench/check_vs_blender.sh BUILD_DIR [OUT_DIR] — `fabvdb check`'s wall
# thickness against Blender's 3D-Print Toolbox thickness check
# (object_print3d_utils, run headless) on 24 corpus models: per category a
# fixed share (CAD 6, sculpture 6, scan 4, dirty 4, large 2, degenerate 2),
# taken evenly spaced in the category's order by triangle count (index
# ⌊(i + ½)·n / share⌋). Each model is scaled to 60 mm (`corpus_check obj
# --fit 60`, as fabvdb's --fit scales) and written as OBJ, which both read,
# with the resin profile's minimum wall, 0.5 mm, as the threshold; per input
# triangle, thin by the Toolbox (bench/check_vs_blender_toolbox.py) against
# thin by fabvdb's thickness map (bench/check_vs_blender_compare.py).
# Prints a Markdown table: per model the shares of the input's area thin by
# both, thick by both, thin by the Toolbox only (and of that, marked only
# as the face another's ray hit), by fabvdb only and off fabvdb's surface
# (and of that, thin by the Toolbox), and the seconds of both (fabvdb: the
# whole command with the map; the Toolbox: its check alone). OUT_DIR keeps
# each model's OBJ, map, reports and per-triangle classes (default: a
# temporary folder; bench/check_vs_blender_render.py draws them).
# Needs BUILD_DIR/fabvdb and BUILD_DIR/bench/corpus_check (or both in
# BUILD_DIR itself), blender and /usr/bin/python3 with numpy.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: bench/check_vs_blender.sh BUILD_DIR [OUT_DIR]" >&2; exit 1; }
BUILD="$(cd "$1" && pwd)"
SOURCE="$(cd "$(dirname "$0")/.." && pwd)"
CORPUS="${FABVDB_SHARED_DATA:-$SOURCE/../shared/data}/corpus"
FABVDB="$BUILD/fabvdb"
CHECKER="$BUILD/bench/corpus_check"
[ -x "$CHECKER" ] || CHECKER="$BUILD/corpus_check"
THRESHOLD=0.5   # mm: the sla profile's min_wall (docs/check.md)
FIT=60          # mm: the corpus recipe's size
if [ $# -ge 2 ]; then OUT="$2"; mkdir -p "$OUT"; else OUT="$(mktemp -d)"; trap 'rm -rf "$OUT"' EXIT; fi

models="$(/usr/bin/python3 - "$CORPUS/manifest.tsv" <<'EOF'
import sys
share = {"cad": 6, "sculpture": 6, "scan": 4, "dirty": 4, "large": 2, "degenerate": 2}
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]).readlines()[1:] if l.strip()]
for category, count in share.items():
    members = sorted((r for r in rows if r[1] == category), key=lambda r: (int(r[3]), r[0]))
    for i in range(count):
        print(members[int((i + 0.5) * len(members) / count)][0], category)
EOF
)"

echo "| model | category | triangles | both thin | both thick | only Toolbox (as a face hit) | only fabvdb" \
  "| off surface (Toolbox thin) | fabvdb s | Toolbox s |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
while read -r model category; do
  dir="$OUT/${model%.*}"
  mkdir -p "$dir"
  "$CHECKER" obj "$CORPUS/$model" "$dir/input.obj" --fit "$FIT" >"$dir/obj.json"
  start=$(date +%s.%N)
  code=0
  "$FABVDB" check "$dir/input.obj" --process sla --thickness-map "$dir/map.ply" --report "$dir/check.json" \
    --quiet >/dev/null 2>"$dir/check.err" || code=$?
  fabvdb_seconds=$(/usr/bin/python3 -c 'import sys; print("%.1f" % (float(sys.argv[2]) - float(sys.argv[1])))' \
    "$start" "$(date +%s.%N)")
  if [ "$code" -ne 0 ] && [ "$code" -ne 5 ]; then
    echo "| \`$model\` | $category | | fabvdb exit $code: $(head -c 160 "$dir/check.err" | tr '\n|' ' /') | | | | | | |"
    continue
  fi
  blender -b --factory-startup --python "$SOURCE/bench/check_vs_blender_toolbox.py" --python-exit-code 1 -- \
    "$dir/input.obj" "$THRESHOLD" "$dir/toolbox.json" >"$dir/blender.log" 2>&1
  voxel=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["voxel_size"])' "$dir/check.json")
  /usr/bin/python3 "$SOURCE/bench/check_vs_blender_compare.py" "$dir/input.obj" "$dir/map.ply" "$dir/toolbox.json" \
    "$THRESHOLD" "$voxel" "$dir/classes.txt" >"$dir/compare.json"
  /usr/bin/python3 - "$dir/compare.json" "$dir/toolbox.json" "$model" "$category" "$fabvdb_seconds" <<'EOF'
import json, sys
c, t = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
p = lambda x: "%.1f%%" % (100 * x)
print("| `%s` | %s | %d | %s | %s | %s (%s) | %s | %s (%s) | %s | %.1f |" % (
    sys.argv[3], sys.argv[4], c["triangles"], p(c["both_thin"]), p(c["both_thick"]), p(c["only_toolbox"]),
    p(c["only_toolbox_hit_only"]), p(c["only_fabvdb"]), p(c["off_surface"]), p(c["off_surface_toolbox_thin"]),
    sys.argv[5], t["seconds"]))
EOF
done <<<"$models"
