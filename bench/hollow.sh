#!/usr/bin/env bash
# bench/hollow.sh BUILD_DIR [MODEL...] — fabvdb hollow against PrusaSlicer's
# SLA hollowing, in the same run, on the shared models (a MODEL is a file of
# the shared meshes folder, or a path, e.g. a corpus mesh) scaled to 60 and
# 100 mm, wall 3 mm, closing 2 mm. SUBDIVIDE=N splits each model's triangles
# in four N times first (the surface does not move: large scans from small
# ones, e.g. a 100k-triangle model at N=2 has 1.6M). PrusaSlicer's hollowing time is the span
# between its "Hollowing model" and "Drilling holes" log lines, its memory the
# peak it logs at "Drilling holes"; fabvdb's time is the hollowing operation
# (report timings.total) and its memory the peak RSS of the whole command.
# Quality (measured by bench_hollow_quality, independently of the hollowing):
# the thinnest wall at closing 2 mm and at closing 0, the median wall at
# closing 0, and the largest distance of the output's outer surface to the
# input. Both programs read the same copy of the model scaled to the size (an
# STL: PrusaSlicer reads no OFF). Installs Debian's prusa-slicer if missing.
# RUNS=N (default 1) runs both programs N times in turn and keeps each one's
# fastest time, for a machine that others load unevenly.
set -euo pipefail
BUILD="${1:?usage: bench/hollow.sh BUILD_DIR [MODEL...]}"
shift
SOURCE="$(cd "$(dirname "$0")/.." && pwd)"
MESHES="$SOURCE/../shared/data/meshes"
FABVDB="$BUILD/fabvdb"
QUALITY="$BUILD/bench/bench_hollow_quality"
[ -x "$QUALITY" ] || QUALITY="$BUILD/bench_hollow_quality"
RUNS="${RUNS:-1}"
MODELS=("$@")
[ ${#MODELS[@]} -gt 0 ] || MODELS=(bunny.off spot.obj fertility.off kitten.obj max-planck_decimated.obj
  dragon_20k.obj rocker-arm.obj armadillo_86k.obj)
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

if ! command -v prusa-slicer >/dev/null; then
  apt-get install -y prusa-slicer >/dev/null
fi

seconds_of() {  # the time of day of a PrusaSlicer log line, in seconds
  sed -n 's/^\[[0-9-]* \([0-9]*\):\([0-9]*\):\([0-9.]*\)\].*/\1 \2 \3/p' | awk '{ print $1 * 3600 + $2 * 60 + $3 }'
}

json_number() {  # json_number FILE KEY: the first number after "KEY":
  sed -n "s/.*\"$2\": *\(-\{0,1\}[0-9.eE+-]*\).*/\1/p" "$1" | head -n 1
}

printf '%-26s %8s %4s | %8s %8s %6s | %7s %7s %5s | %8s %8s %8s %9s\n' model tris mm ps_s fab_s ratio ps_MB fab_MB mem \
  wmin_c2 wmin_c0 wmed_c0 outer_dev
for model in "${MODELS[@]}"; do
  for size in 60 100; do
    log="$WORK/prusa.log"
    part="$WORK/part.stl"
    case "$model" in */*) path="$model" ;; *) path="$MESHES/$model" ;; esac
    "$QUALITY" --scaled "$path" "$size" "$part" "${SUBDIVIDE:-0}"
    prusa_seconds=""
    fab_seconds=""
    for _ in $(seq "$RUNS"); do
      prusa-slicer --export-sla --printer-technology SLA --hollowing-enable --no-supports-enable --no-pad-enable \
        --loglevel 4 --display-width 200 --display-height 200 --display-pixels-x 1440 --display-pixels-y 1440 \
        --bed-shape 0x0,200x0,200x200,0x200 --center 100,100 --max-print-height 200 \
        --hollowing-min-thickness 3 --hollowing-closing-distance 2 \
        --datadir "$WORK/prusa-data" -o "$WORK/out.sl1" "$part" >"$log" 2>&1 || true
      start="$(grep -m1 'Hollowing model' "$log" | seconds_of || true)"
      end="$(grep -m1 'Drilling holes' "$log" | seconds_of || true)"
      if [ -z "$start" ] || [ -z "$end" ]; then
        echo "$model $size: PrusaSlicer did not hollow (see its log below)" >&2
        tail -n 3 "$log" >&2
        prusa_seconds=""
        break
      fi
      prusa_seconds="$(awk -v a="$start" -v b="$end" -v best="$prusa_seconds" \
        'BEGIN { t = b - a; if (best != "" && best < t) t = best; printf "%.3f", t }')"
      prusa_mb="$(grep -m1 'Drilling holes' "$log" | sed -n 's/.*Peak memory usage: \([0-9]*\)MB.*/\1/p')"

      /usr/bin/time -f '%M' -o "$WORK/rss" "$FABVDB" hollow "$part" -o "$WORK/c2.stl" \
        --wall 3mm --closing 2mm --report "$WORK/c2.json" -q
      fab_seconds="$(sed -n '/"timings"/,/}/p' "$WORK/c2.json" | json_number /dev/stdin total |
        awk -v best="$fab_seconds" '{ t = $1; if (best != "" && best < t) t = best; print t }')"
      fab_mb="$(awk '{ printf "%.0f", $1 / 1024 }' "$WORK/rss")"
    done
    [ -n "$prusa_seconds" ] || continue
    "$FABVDB" hollow "$part" -o "$WORK/c0.stl" --wall 3mm --closing 0mm -q
    read -r wmin2 _ _ _ < <("$QUALITY" "$part" "$size" "$WORK/c2.stl")
    read -r wmin0 wmed0 dev _ < <("$QUALITY" "$part" "$size" "$WORK/c0.stl")
    triangles=$(( ($(stat -c %s "$part") - 84) / 50 ))  # the scaled copy is a binary STL
    printf '%-26s %8s %4s | %8s %8.3f %6.1f | %7s %7s %5.2f | %8s %8s %8s %9s\n' "$(basename "$model")" "$triangles" \
      "$size" "$prusa_seconds" \
      "$fab_seconds" "$(awk -v a="$prusa_seconds" -v b="$fab_seconds" 'BEGIN { print a / b }')" "$prusa_mb" "$fab_mb" \
      "$(awk -v a="$fab_mb" -v b="$prusa_mb" 'BEGIN { print a / b }')" "$wmin2" "$wmin0" "$wmed0" "$dev"
  done
done
echo "ratio = PrusaSlicer time / fabvdb time (each the fastest of $RUNS runs; target >= 10); mem = fabvdb peak / PrusaSlicer peak (target <= 1)"
echo "targets: wmin >= 2.78 mm, wmed_c0 within 0.1 mm of 3, outer_dev <= 0.05 mm"
