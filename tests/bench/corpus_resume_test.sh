# corpus_resume_test.sh — bench/corpus/run.py --resume on a corpus of two tiny
# shared meshes: a model whose record came from the same binaries (by
# digest) and recipe, with every wanted command, is kept as it is; a model
# run by another checker binary, a run with another recipe and a run that
# wants a command the record lacks are run again. Only `info` runs: quick.
# Arguments: the fabvdb binary, the shared data folder, the source folder,
# the corpus_check binary.
source "$(dirname "$0")/../cli/lib.sh"
CHECKER="$4"
RUN=(python3 "$SOURCE/bench/corpus/run.py" --fabvdb "$FABVDB" --corpus "$WORK/corpus" --out "$WORK/out"
     --jobs 1 --time-cap 120 --check-cap 120)

mkdir -p "$WORK/corpus"
cp "$MESHES/cube_no_bottom.obj" "$MESHES/joined_tetrahedra.obj" "$WORK/corpus/"
printf 'file\tcategory\tsha256\ttriangles\tclosed\n' >"$WORK/corpus/manifest.tsv"
for mesh in cube_no_bottom.obj:40 joined_tetrahedra.obj:8; do
  printf '%s\tdirty\t%s\t%s\tno\n' "${mesh%:*}" "$(sha256sum "$WORK/corpus/${mesh%:*}" | cut -d' ' -f1)" \
    "${mesh#*:}" >>"$WORK/corpus/manifest.tsv"
done
# The same checker with one byte more: another binary to the run's identity,
# the same program to the machine.
cp "$CHECKER" "$WORK/other_checker"
printf '\0' >>"$WORK/other_checker"

record() { printf '%s' "$WORK/out/runs/$1/record.json"; }
# The digests of the binaries a record was made with.
digests_of() {
  python3 -c 'import json, sys; print(" ".join(json.load(open(sys.argv[1]))["identity"]["binaries"].values()))' \
    "$(record "$1")"
}
kept() { expect_match "$STDOUT" "^$1 *kept (--resume)"; }
rerun() {
  if printf '%s' "$STDOUT" | grep -q "^$1 *info:"; then passed=$((passed + 1)); else fail "$1 was not run: $STDOUT"; fi
}

# Both models run; their records are written.
expect_exit 0 "${RUN[@]}" --checker "$CHECKER" --commands info
rerun cube_no_bottom.obj
rerun joined_tetrahedra.obj
cp "$(record cube_no_bottom.obj)" "$WORK/cube.json"
cp "$(record joined_tetrahedra.obj)" "$WORK/joined.json"

# Same binaries and recipe: both kept, their records untouched.
expect_exit 0 "${RUN[@]}" --checker "$CHECKER" --commands info --resume
kept cube_no_bottom.obj
kept joined_tetrahedra.obj
expect_exit 0 cmp "$(record cube_no_bottom.obj)" "$WORK/cube.json"
expect_exit 0 cmp "$(record joined_tetrahedra.obj)" "$WORK/joined.json"
expect_match "$(cat "$WORK/out/results.md")" 'joined_tetrahedra.obj'

# One model rerun by another checker: under --resume with the first one,
# that model runs again and the other is kept.
expect_exit 0 "${RUN[@]}" --checker "$WORK/other_checker" --commands info --only joined_tetrahedra.obj
other="$(sha256sum "$WORK/other_checker" | cut -d' ' -f1)"
expect_match "$(digests_of joined_tetrahedra.obj)" "$other"
expect_exit 0 "${RUN[@]}" --checker "$CHECKER" --commands info --resume
kept cube_no_bottom.obj
rerun joined_tetrahedra.obj
expect_exit 0 cmp "$(record cube_no_bottom.obj)" "$WORK/cube.json"
expect_match "$(digests_of joined_tetrahedra.obj)" "$(sha256sum "$CHECKER" | cut -d' ' -f1)"
if digests_of joined_tetrahedra.obj | grep -q "$other"; then fail "the rerun kept the other checker's digest"; else
  passed=$((passed + 1)); fi

# Another recipe (--fit): both run again.
expect_exit 0 "${RUN[@]}" --checker "$CHECKER" --commands info --resume --fit 50
rerun cube_no_bottom.obj
rerun joined_tetrahedra.obj
expect_match "$(cat "$(record cube_no_bottom.obj)")" '"fit_mm": 50'

# A wanted command the records lack: both run again. (powder-sim, wanted
# without drain, runs on nothing: a quick way to want one more command.)
expect_exit 0 "${RUN[@]}" --checker "$CHECKER" --commands info --resume --fit 50
kept cube_no_bottom.obj
expect_exit 0 "${RUN[@]}" --checker "$CHECKER" --commands info,powder-sim --resume --fit 50
rerun cube_no_bottom.obj
rerun joined_tetrahedra.obj
finish
