#!/usr/bin/env bash
# Installs the dependencies, builds fabvdb, and runs the whole chain on the
# bundled sample (data/spot.obj scaled to 80 mm): repair into a clean solid,
# hollow it with a 2.5 mm wall, place and drill two drain holes in the hollow
# part, check it with the reference powder simulation, then cut the model into
# two-piece-moldable parts and generate their cast parts and molds. Results go
# to demo-output/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
out=demo-output
mkdir -p "$out"
fabvdb=build/fabvdb
echo "== inspect the input"
$fabvdb info data/spot.obj --fit 80mm --report "$out/spot_info.json"
echo "== repair into a clean solid"
$fabvdb repair data/spot.obj --fit 80mm -o "$out/spot_repaired.stl" --report "$out/repair.json"
echo "== hollow with a 2.5 mm wall"
$fabvdb hollow "$out/spot_repaired.stl" --wall 2.5mm -o "$out/spot_hollow.stl" --report "$out/hollow.json"
echo "== place and drill two drain holes in the hollow part"
$fabvdb drain "$out/spot_hollow.stl" --holes 2 -o "$out/spot_drained.stl" --heatmap "$out/drainability.ply" \
  --report "$out/drain.json"
echo "== check with the reference powder simulation: the recommended cleaning routine, then random turns"
$fabvdb powder-sim "$out/spot_drained.stl" --holes-from "$out/drain.json" --routine "$out/drain.json" \
  --report "$out/powder_sim.json"
$fabvdb powder-sim "$out/spot_drained.stl" --holes-from "$out/drain.json" --report "$out/powder_sim_random.json"
echo "== decompose into two-piece-moldable parts and generate the molds"
$fabvdb mold data/spot.obj --fit 80mm -o "$out/spot_molds" --report "$out/mold.json"
echo
echo "Results are in $out/:"
echo "  spot_repaired.stl   the clean watertight solid      (repair.json)"
echo "  spot_hollow.stl     the hollowed part               (hollow.json)"
echo "  spot_drained.stl    the part with its drain holes   (drain.json: holes, predicted residual powder)"
echo "  drainability.ply    the cavity coloured by the share of powder that drains (MeshLab, Blender;"
echo "                      legend drainability.png); drainability_left.ply: where powder is left"
echo "  powder_sim.json     the powder left inside by the reference simulation, cleaning routine"
echo "                      (powder_sim_random.json: random turns)"
echo "  spot_molds/         parts/part_NN.stl (cast parts), molds/part_NN_top.stl and _bottom.stl,"
echo "                      decomposition/ (parts and parting lines)   (mold.json)"
