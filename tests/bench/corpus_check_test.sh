# corpus_check_test.sh — bench/corpus/run.py's verdict on `fabvdb check`
# on a corpus of three meshes (the shared open cube and joined tetrahedra,
# and two clean cubes apart written here): each run is ok, with its verdict
# and every check's status in the record; a report whose figures contradict
# the checker (one shell more, a box not the size asked for) or itself (a
# verdict that is not the worst check), or a crash, is a FAIL. The
# contradictions come from a wrapper that runs the real fabvdb and then
# edits its report, or kills itself.
# Arguments: the fabvdb binary, the shared data folder, the source folder,
# the corpus_check binary.
source "$(dirname "$0")/../cli/lib.sh"
CHECKER="$4"
RUN=(python3 "$SOURCE/bench/corpus/run.py" --corpus "$WORK/corpus" --checker "$CHECKER" --commands check
     --jobs 1 --time-cap 120 --check-cap 120)

mkdir -p "$WORK/corpus"
cp "$MESHES/cube_no_bottom.obj" "$MESHES/joined_tetrahedra.obj" "$WORK/corpus/"
# Two 10 mm cubes 10 mm apart, each face two triangles facing out.
python3 - "$WORK/corpus/two_cubes.obj" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    for x0 in (0, 20):
        for i in range(8):
            f.write("v %d %d %d\n" % (x0 + 10 * (i >> 2 & 1), 10 * (i >> 1 & 1), 10 * (i & 1)))
    for base in (0, 8):
        for a, b, c, d in ((0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)):
            f.write("f %d %d %d\nf %d %d %d\n" % tuple(base + 1 + i for i in (a, b, c, a, c, d)))
PY
printf 'file\tcategory\tsha256\ttriangles\tclosed\n' >"$WORK/corpus/manifest.tsv"
for mesh in cube_no_bottom.obj:40 two_cubes.obj:24 joined_tetrahedra.obj:8; do
  file="$WORK/corpus/${mesh%:*}"
  printf '%s\tdirty\t%s\t%s\tno\n' "${mesh%:*}" "$(sha256sum "$file" | cut -d' ' -f1)" "${mesh#*:}" \
    >>"$WORK/corpus/manifest.tsv"
done
cell() {  # the check cell's result and figure of a model in OUT ($1)
  python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["runs"]["check"]; print(c["result"], c["figure"])' \
    "$WORK/$1/runs/$2/record.json"
}

# The real fabvdb: every model ok, with a verdict and eight statuses.
expect_exit 0 "${RUN[@]}" --fabvdb "$FABVDB" --out "$WORK/real"
for model in cube_no_bottom.obj two_cubes.obj joined_tetrahedra.obj; do
  expect_match "$(cell real "$model")" '^ok '
  expect_match "$(cat "$WORK/real/runs/$model/record.json")" '"overhangs": "\(pass\|warn\|fail\)"'
  expect_match "$(cat "$WORK/real/runs/$model/record.json")" '"cups": "\(pass\|warn\|fail\)"'
done
expect_match "$(cat "$WORK/real/results.md")" '| wall_thickness | [0-9]'

# A wrapper: the real fabvdb, then its check report edited by the Python
# expression $EDIT (r: the report), or a crash when EDIT is "crash".
cat >"$WORK/fabvdb" <<EOF
#!/usr/bin/env bash
[ "\$EDIT" = crash ] && kill -SEGV \$\$
code=0
"$FABVDB" "\$@" || code=\$?
python3 -c 'import json, os; r = json.load(open("check.json")); exec(os.environ["EDIT"]); json.dump(r, open("check.json", "w"))'
exit \$code
EOF
chmod +x "$WORK/fabvdb"

# One shell more than the checker counts in the two closed bodies.
EDIT='r["checks"]["mesh"]["shells"] += 1' expect_exit 1 "${RUN[@]}" --fabvdb "$WORK/fabvdb" --out "$WORK/shells"
expect_match "$(cell shells two_cubes.obj)" '^FAIL mesh: 3 shells, the checker 2'
expect_match "$(cell shells cube_no_bottom.obj)" '^ok '

# A verdict that is not the worst of the checks (the open cube warns).
EDIT='r["verdict"] = "pass"' expect_exit 1 "${RUN[@]}" --fabvdb "$WORK/fabvdb" --out "$WORK/verdict" \
  --only cube_no_bottom.obj
expect_match "$(cell verdict cube_no_bottom.obj)" '^FAIL verdict pass, worst check warn'

# A box that is not the size asked for.
EDIT='r["checks"]["units"]["size"][0] *= 1.01' expect_exit 1 "${RUN[@]}" --fabvdb "$WORK/fabvdb" --out "$WORK/size" \
  --only two_cubes.obj
expect_match "$(cell size two_cubes.obj)" 'units: '

# A crash.
EDIT=crash expect_exit 1 "${RUN[@]}" --fabvdb "$WORK/fabvdb" --out "$WORK/crash" --only joined_tetrahedra.obj
expect_match "$(cell crash joined_tetrahedra.obj)" '^FAIL crashed'
finish
