# batch_test.sh — --save-job writes a job that `fabvdb batch` replays to the
# same result; a job file's lines run in order (a failing line ends the task
# unless --keep-going), their output goes to the task's log in the state
# folder; malformed job files are refused with exit 2 and the line.
source "$(dirname "$0")/lib.sh"

expect_exit 0 "$FABVDB" info "$MESHES/sphere.obj" --fit 50mm --report "$WORK/first.json" \
  --save-job "$WORK/info.job" --quiet
expect_exit 0 test -f "$WORK/info.job"
expect_match "$(head -n 1 "$WORK/info.job")" '^fabvdb-job 1$'
expect_match "$(cat "$WORK/info.job")" '"--fit" "50mm"'
rm -f "$WORK/first.json"
expect_exit 0 "$FABVDB" batch "$WORK/info.job" --quiet
expect_exit 0 test -f "$WORK/first.json"
expect_match "$(cat "$WORK/first.json")" '"triangles": 1280'

expect_exit 0 "$FABVDB" batch "$WORK/info.job" --dry-run --quiet
expect_match "$STDOUT" '^fabvdb info'

printf 'fabvdb-job 1\ninfo "%s"\ninfo "%s/missing.obj"\ninfo "%s"\n' "$MESHES/sphere.obj" "$WORK" \
  "$MESHES/torus.obj" > "$WORK/mixed.job"
expect_exit 2 "$FABVDB" batch "$WORK/mixed.job"
expect_match "$STDERR" 'missing.obj'
expect_match "$(cat "$WORK/mixed.state/logs/mixed.log")" 'sphere.obj'
if grep -q 'torus.obj' "$WORK/mixed.state/logs/mixed.log"; then fail "batch went on after a failure"; else passed=$((passed + 1)); fi
expect_match "$(cat "$WORK/mixed.state/tasks/mixed.json")" '"failed_line": 3'
expect_exit 2 "$FABVDB" batch "$WORK/mixed.job" --keep-going
expect_match "$(cat "$WORK/mixed.state/logs/mixed.log")" 'torus.obj'
expect_match "$(cat "$WORK/mixed.state/tasks/mixed.json")" '"status": "failed"'

printf 'info "x.obj"\n' > "$WORK/no_header.job"
expect_exit 2 "$FABVDB" batch "$WORK/no_header.job"
expect_match "$STDERR" 'no_header.job:1: not a fabvdb job file'
printf 'fabvdb-job 99\n' > "$WORK/future.job"
expect_exit 2 "$FABVDB" batch "$WORK/future.job"
printf 'fabvdb-job 1\nexplode "x.obj"\n' > "$WORK/unknown.job"
expect_exit 2 "$FABVDB" batch "$WORK/unknown.job"
expect_match "$STDERR" "unknown.job:2: no command 'explode'"
printf 'fabvdb-job 1\ninfo "x.obj\n' > "$WORK/quote.job"
expect_exit 2 "$FABVDB" batch "$WORK/quote.job"
expect_match "$STDERR" 'quote.job:2: a quoted word is not closed'
expect_exit 2 "$FABVDB" batch "$WORK/none.job"
finish
