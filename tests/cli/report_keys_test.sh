# report_keys_test.sh — every command's --report follows the one key
# convention of docs/reports.md, checked on real output: snake_case keys, no
# unit suffix (_mm, _mm3, _s, seconds: the unit comes from the quantity),
# fractions in [0, 1], angles in degrees, and a top-level `timings` object of
# non-negative seconds with `total` (nested `timings` objects hold numbers
# too), the batch summary included. Small inputs and coarse settings keep it
# quick.
source "$(dirname "$0")/lib.sh"
SPHERE="$SOURCE/data/sphere.obj"

expect_exit 0 "$FABVDB" info "$SPHERE" --report "$WORK/info.json" --quiet
expect_exit 0 "$FABVDB" check "$SPHERE" --fit 40mm --process fdm --build-volume 250x210x220mm \
  --thickness-map "$WORK/walls.ply" --report "$WORK/check.json" --quiet
expect_exit 0 "$FABVDB" repair "$SPHERE" --fit 40mm --resolution 60 -o "$WORK/repaired.stl" --report "$WORK/repair.json" --quiet
expect_exit 0 "$FABVDB" hollow "$SPHERE" --fit 40mm --wall 3mm -o "$WORK/hollow.stl" --report "$WORK/hollow.json" --quiet
expect_exit 0 "$FABVDB" drain "$WORK/hollow.stl" --holes 2 --patches 300 -o "$WORK/drained.stl" \
  --report "$WORK/drain.json" --quiet
expect_exit 0 "$FABVDB" powder-sim "$WORK/drained.stl" --holes-from "$WORK/drain.json" --turns 2 \
  --report "$WORK/powder-sim.json" --quiet
expect_exit 0 "$FABVDB" decompose "$SPHERE" --fit 40mm --low-res 800 --smoothing 1 -o "$WORK/decomposition" \
  --report "$WORK/decompose.json" --quiet
expect_exit 0 "$FABVDB" mold "$SPHERE" --fit 40mm --decomposition "$WORK/decomposition/decomposition.json" \
  --voxel 0.8mm --mold-margin 6mm -o "$WORK/molds" --report "$WORK/mold.json" --quiet
printf 'fabvdb-job 1\ninfo "%s" --report "%s/batch-info.json"\n' "$SPHERE" "$WORK" > "$WORK/keys.job"
expect_exit 0 "$FABVDB" batch "$WORK/keys.job" --report "$WORK/batch.json" --quiet

expect_exit 0 python3 - "$WORK"/{info,check,repair,hollow,drain,powder-sim,decompose,mold,batch}.json <<'PY'
import json, re, sys

NAME = re.compile(r'^[a-z][a-z0-9_]*$')
UNIT_SUFFIX = re.compile(r'(_mm|_mm2|_mm3|_cm3|_s|_ms|_sec|_seconds)$')
problems = []

def check(value, path, in_timings=False):
    if isinstance(value, dict):
        for key, item in value.items():
            where = f'{path}/{key}'
            if in_timings:
                if not (isinstance(item, (int, float)) and not isinstance(item, bool) and item >= 0):
                    problems.append(f'{where}: a timing must be a number of seconds >= 0, not {item!r}')
                continue
            if not NAME.match(key):
                problems.append(f'{where}: not snake_case')
            if UNIT_SUFFIX.search(key) or key == 'seconds':
                problems.append(f'{where}: a unit suffix (the unit comes from the quantity, docs/reports.md)')
            if key.endswith('fraction') and isinstance(item, (int, float)) and not 0 <= item <= 1:
                problems.append(f'{where}: a fraction outside [0, 1]: {item}')
            if key.endswith('degrees') and isinstance(item, (int, float)) and not 0 <= item <= 360:
                problems.append(f'{where}: degrees outside [0, 360]: {item}')
            if key == 'timings' and not isinstance(item, dict):
                problems.append(f'{where}: timings must be an object')
            check(item, where, key == 'timings')
    elif isinstance(value, list):
        for i, item in enumerate(value):
            check(item, f'{path}/{i}', in_timings)

for name in sys.argv[1:]:
    with open(name) as f:
        report = json.load(f)
    label = name.rsplit('/', 1)[-1]
    timings = report.get('timings')
    if not isinstance(timings, dict) or 'total' not in timings:
        problems.append(f'{label}: no top-level timings with a total')
    check(report, label)
for problem in problems:
    print(problem, file=sys.stderr)
sys.exit(1 if problems else 0)
PY
[ -z "$STDERR" ] || printf '%s\n' "$STDERR" >&2
finish
