#!/usr/bin/env bash
# bench/check.sh BUILD_DIR [BUILD_DIR...] — the time of `fabvdb check` at its
# default resolution on the shared armadillo (86k triangles) and the corpus'
# lucy (100k) at 100 mm for resin, clean shells both; the corpus' aphrodite
# (111k, open: the winding-number path) likewise; and the rocker arm at
# 120 mm for FDM (its 3 mm pin minimum makes the deepest band). Per run: the model's triangles,
# the voxel, wall and user seconds and peak MiB of the whole command
# (/usr/bin/time -v), and the report's stage times over 0.05 s. With several
# builds (before and after a change) each model runs in every build in turn,
# RUNS=N times (default 1), so a machine others load unevenly weighs on
# both alike; compare user seconds as well as wall.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: bench/check.sh BUILD_DIR [BUILD_DIR...]" >&2; exit 1; }
BUILDS=("$@")
SOURCE="$(cd "$(dirname "$0")/.." && pwd)"
SHARED="${FABVDB_SHARED_DATA:-$SOURCE/../shared/data}"
RUNS="${RUNS:-1}"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT

# model path, size, process
CASES=("$SHARED/meshes/armadillo_86k.obj 100mm sla"
       "$SHARED/corpus/lucy.ply 100mm sla"
       "$SHARED/corpus/aphrodite.obj 100mm sla"
       "$SHARED/meshes/rocker-arm.obj 120mm fdm")

printf '%-18s %-5s %7s %5s %6s | %6s %6s %6s | %s\n' model build tris proc voxel wall_s user_s MiB stages
for case in "${CASES[@]}"; do
  read -r path size process <<<"$case"
  for run in $(seq "$RUNS"); do
    for b in "${!BUILDS[@]}"; do
      fabvdb="${BUILDS[$b]}/fabvdb"
      "$fabvdb" info "$path" --report "$WORK/info.json" --quiet >/dev/null 2>&1
      /usr/bin/time -v "$fabvdb" check "$path" --fit "$size" --process "$process" --report "$WORK/check.json" \
        --quiet >/dev/null 2>"$WORK/time.txt" || [ $? -eq 5 ]
      python3 - "$path" "$b" "$process" "$WORK/info.json" "$WORK/check.json" "$WORK/time.txt" <<'EOF'
import json, os, re, sys
path, build, process, info, check, timing = sys.argv[1:]
report = json.load(open(check))
text = open(timing).read()
def field(name):
    return re.search(re.escape(name) + r": *(.*)", text).group(1).strip()
clock = [float(x) for x in field("Elapsed (wall clock) time (h:mm:ss or m:ss)").split(":")]
wall = sum(v * 60 ** (len(clock) - 1 - i) for i, v in enumerate(clock))
user = float(field("User time (seconds)"))
peak = int(field("Maximum resident set size (kbytes)")) / 1024
stages = " ".join(f"{k} {v:.2f}" for k, v in report["timings"].items() if k != "total" and v >= 0.05)
print(f"{os.path.splitext(os.path.basename(path))[0][:18]:<18} {build:<5} {json.load(open(info))['triangles']:>7} "
      f"{process:>5} {report['voxel_size']:>6.3g} | {wall:>6.2f} {user:>6.2f} {peak:>6.0f} | {stages}")
EOF
    done
  done
done
