# info_test.sh — `fabvdb info`: figures of a clean part, and the warnings its
# size and place give about units: under 1 mm across (metres or inches),
# over 2 m (micrometres), far from the origin (STL precision); none for a
# part in millimetres.
source "$(dirname "$0")/lib.sh"

tetra() {  # tetra FILE SIZE OFFSET: a closed tetrahedron of edge SIZE at OFFSET
  awk -v s="$2" -v o="$3" 'BEGIN {
    printf "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\n", o, o, o, o + s, o, o
    printf "v %.17g %.17g %.17g\nv %.17g %.17g %.17g\n", o, o + s, o, o, o, o + s
    print "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4" }' >"$1"
}

tetra "$WORK/mm.obj" 40 0
expect_exit 0 "$FABVDB" info "$WORK/mm.obj" --report "$WORK/mm.json"
expect_match "$STDOUT" "closed (watertight) *yes"
expect_match "$(cat "$WORK/mm.json")" '"warnings": \[\]'
if printf '%s' "$STDERR" | grep -q warning; then fail "warning for a part in millimetres: $STDERR"; else passed=$((passed + 1)); fi

tetra "$WORK/metres.obj" 0.045 0
expect_exit 0 "$FABVDB" info "$WORK/metres.obj"
expect_match "$STDERR" "warning: the model is only 0.045 mm across"
expect_match "$STDERR" "--scale 1000"
expect_exit 0 "$FABVDB" info "$WORK/metres.obj" --scale 1000
if printf '%s' "$STDERR" | grep -q warning; then fail "warning after --scale 1000: $STDERR"; else passed=$((passed + 1)); fi

tetra "$WORK/micrometres.obj" 40000 0
expect_exit 0 "$FABVDB" info "$WORK/micrometres.obj"
expect_match "$STDERR" "warning: the model is 4e+04 mm across"

tetra "$WORK/survey.obj" 40 3980578
expect_exit 0 "$FABVDB" info "$WORK/survey.obj" --report "$WORK/survey.json"
expect_match "$STDERR" "warning: the model lies .* from the origin"
expect_match "$(cat "$WORK/survey.json")" '"warnings": \['
finish
