#!/usr/bin/env bash
# bench/fidelity_cost.sh BUILD_DIR [MODEL...] — what the fidelity gate
# (src/volume/input_fidelity.h) costs `fabvdb repair`: each model (a file of
# the shared meshes folder, or a path) repaired at 60 mm with the default
# voxel, and the gate's stage time (report timings.fidelity) against the
# whole repair (timings.total), per model and over all. RUNS=N (default 1)
# repeats each repair and keeps its fastest total.
set -euo pipefail
BUILD="${1:?usage: bench/fidelity_cost.sh BUILD_DIR [MODEL...]}"
shift
SOURCE="$(cd "$(dirname "$0")/.." && pwd)"
MESHES="$SOURCE/../shared/data/meshes"
RUNS="${RUNS:-1}"
MODELS=("$@")
if [ ${#MODELS[@]} -eq 0 ]; then
  for f in "$MESHES"/*.{obj,off,ply,stl}; do MODELS+=("$(basename "$f")"); done
fi
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
printf '%-30s %-10s %10s %10s %7s\n' model path total_s gate_s share
for model in "${MODELS[@]}"; do
  path="$model"; [ -f "$path" ] || path="$MESHES/$model"
  best=""
  for _ in $(seq "$RUNS"); do
    if "$BUILD/fabvdb" repair "$path" --fit 60mm -o "$WORK/out.stl" --report "$WORK/r.json" --quiet 2>/dev/null; then
      run=$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); t=r["timings"]; print(r["path"], t["total"], t.get("fidelity", 0.0))' "$WORK/r.json")
      set -- $run
      if [ -z "$best" ] || python3 -c "import sys; sys.exit(0 if $2 < $best_total else 1)"; then
        best="$run"; best_total="$2"
      fi
    fi
  done
  if [ -z "$best" ]; then printf '%-30s refused\n' "$model"; continue; fi
  set -- $best
  printf '%-30s %-10s %10.3f %10.3f %6.1f%%\n' "$model" "$1" "$2" "$3" "$(python3 -c "print(100*$3/$2)")"
  echo "$2 $3" >> "$WORK/sums"
done
python3 - "$WORK/sums" <<'PY'
import sys
rows = [tuple(map(float, l.split())) for l in open(sys.argv[1])]
total, gate = sum(r[0] for r in rows), sum(r[1] for r in rows)
print("all %d repairs: %.2f s, the gate %.2f s: %.1f%%; largest share %.1f%%" %
      (len(rows), total, gate, 100 * gate / total, max(100 * g / t for t, g in rows)))
PY
