#!/usr/bin/env bash
# Installs the dependencies, builds fabvdb, and runs the main job on the
# bundled sample (data/spot.obj), writing the results to demo-output/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
out=demo-output
mkdir -p "$out"
echo "== fabvdb info data/spot.obj"
build/fabvdb info data/spot.obj --fit 80mm --report "$out/spot_info.json"
echo
echo "Results are in $out/: spot_info.json (every figure of the inspection)."
