# batch_resume_test.sh — a batch killed with SIGKILL mid-run leaves no
# half-written output and loses only the task that was running; --resume
# reruns exactly the tasks without a current record (never the finished ones)
# and completes the batch; a changed input or a lost output reruns its task;
# --status says done / failed / pending and writes status.json.
source "$(dirname "$0")/lib.sh"

mkdir -p "$WORK/orders"
for n in 1 2 3 4 5 6; do cp "$MESHES/sphere.obj" "$WORK/orders/part$n.obj"; done
cat > "$WORK/recipe.job" <<'JOB'
fabvdb-job 1
repair {input} --fit 50mm --voxel 0.5mm -o {out}/repaired.stl --report {out}/repair.json
hollow {prev} --wall 2mm --voxel 0.5mm -o {out}/hollow.stl
JOB
state="$WORK/recipe.state"

# One task at a time, killed with SIGKILL as soon as the first record is written.
setsid "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/out" --jobs 1 --quiet &
batch_pid=$!
disown "$batch_pid"
for _ in $(seq 1 600); do
  [ -f "$state/tasks/part1.json" ] && break
  sleep 0.05
done
expect_exit 0 kill -KILL "$batch_pid"
# The commands it was running die with it (they get SIGTERM and cancel).
for _ in $(seq 1 200); do
  pgrep -s "$batch_pid" >/dev/null || break
  sleep 0.05
done
if pgrep -s "$batch_pid" >/dev/null; then fail "processes of the killed batch still run"; else passed=$((passed + 1)); fi
expect_exit 0 test -f "$state/tasks/part1.json"
expect_no_file "$state/tasks/part6.json"
if find "$WORK/out" "$state" -name '*.partial-*' | grep -q .; then
  fail "half-written files after the kill: $(find "$WORK/out" "$state" -name '*.partial-*')"
else
  passed=$((passed + 1))
fi
# What is there is whole: every mesh written reads back closed.
for mesh in $(find "$WORK/out" -name '*.stl'); do
  expect_exit 0 "$FABVDB" info "$mesh" --report "$WORK/info.json" --quiet
  expect_match "$(cat "$WORK/info.json")" '"closed": true'
done
expect_exit 0 "$FABVDB" batch --status "$state"
expect_match "$STDOUT" '6 task(s): 1 done, 0 failed, 5 pending'
expect_match "$STDOUT" 'pending  part6'
expect_match "$(cat "$state/status.json")" '"pending": 5'
cp "$state/tasks/part1.json" "$WORK/part1.before"

expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/out" --resume --jobs 2
expect_match "$STDERR" '1 of 6 task(s) are done already and unchanged'
expect_match "$STDERR" 'batch: 6 done, 0 failed, 0 pending'
expect_exit 0 cmp "$WORK/part1.before" "$state/tasks/part1.json"
for n in 2 3 4 5 6; do expect_exit 0 test -f "$WORK/out/part$n/hollow.stl"; done
expect_exit 0 "$FABVDB" batch --status "$state"
expect_match "$STDOUT" '6 task(s): 6 done, 0 failed, 0 pending'
for n in 1 2 3 4 5 6; do cp "$state/tasks/part$n.json" "$WORK/part$n.before"; done

# Nothing changed: nothing runs.
expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/out" --resume
expect_match "$STDERR" '6 of 6 task(s) are done already'
for n in 1 2 3 4 5 6; do expect_exit 0 cmp "$WORK/part$n.before" "$state/tasks/part$n.json"; done

# A changed input reruns its task, a lost output its own; the others stay.
cp "$MESHES/torus.obj" "$WORK/orders/part2.obj"
rm "$WORK/out/part4/repair.json"
expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/out" --resume --quiet
for n in 1 3 5 6; do expect_exit 0 cmp "$WORK/part$n.before" "$state/tasks/part$n.json"; done
for n in 2 4; do
  if cmp -s "$WORK/part$n.before" "$state/tasks/part$n.json"; then fail "part$n was not run again"; else passed=$((passed + 1)); fi
done
expect_match "$(cat "$state/tasks/part2.json")" "\"sha256\": \"$(sha256sum "$WORK/orders/part2.obj" | cut -d' ' -f1)\""
expect_exit 0 test -f "$WORK/out/part4/repair.json"

# A changed recipe reruns every task.
sed -i 's/--wall 2mm/--wall 2.5mm/' "$WORK/recipe.job"
expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/out" --resume --dry-run
expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/out" --resume
if printf '%s' "$STDERR" | grep -q 'done already'; then fail "tasks skipped after the recipe changed"; else passed=$((passed + 1)); fi
expect_match "$(cat "$state/tasks/part3.json")" '"2.5mm"'
finish
