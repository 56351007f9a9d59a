# batch_parallel_test.sh — tasks run --jobs at a time under one memory budget:
# a task refused under its share of the budget waits and runs alone with the
# whole budget (its record shows the retry, and no other task ran meanwhile);
# one that can never fit fails with exit 3 and the command's message; a failing
# task, or one whose process crashes, does not stop the others.
source "$(dirname "$0")/lib.sh"

line_times() {  # line_times RECORD: "start end" of each line that ran
  grep '"command"' "$1" | sed -n 's/.*"started_epoch": \([0-9.]*\).*"ended_epoch": \([0-9.]*\).*/\1 \2/p'
}

mkdir -p "$WORK/parts"
expect_exit 0 "$FABVDB" repair "$MESHES/sphere.obj" --fit 60mm --voxel 1mm -o "$WORK/parts/big.stl" --quiet
for n in 1 2 3; do
  expect_exit 0 "$FABVDB" repair "$MESHES/sphere.obj" --fit 20mm --voxel 1mm -o "$WORK/parts/small$n.stl" --quiet
done
cat > "$WORK/hollow.job" <<'JOB'
fabvdb-job 1
hollow {input} --wall 2mm --voxel 0.5mm -o {out}/hollow.stl
JOB

# What the big part needs, by the command's own estimate ("needs ~X GiB").
expect_exit 3 "$FABVDB" hollow "$WORK/parts/big.stl" --wall 2mm --voxel 0.5mm -o "$WORK/probe.stl" --max-memory 1M
needed_gib="$(printf '%s' "$STDERR" | sed -n 's/.*needs ~\([0-9.e+-]*\) GiB.*/\1/p')"
expect_match "$needed_gib" '^[0-9]'
# A budget of 1.5 x that: over half of it (the share of two jobs) the big
# part is refused, under all of it it fits; the small parts fit their share.
budget="$(awk -v g="$needed_gib" 'BEGIN { printf "%.0f", g * 1.5 * 1073741824 }')"
expect_exit 0 "$FABVDB" batch "$WORK/hollow.job" --inputs "$WORK/parts/*.stl" --out "$WORK/out" --jobs 2 \
  --threads 2 --max-memory "$budget"
for part in big small1 small2 small3; do
  expect_exit 0 test -f "$WORK/out/$part/hollow.stl"
  expect_match "$(cat "$WORK/hollow.state/tasks/$part.json")" '"status": "done"'
done
big="$WORK/hollow.state/tasks/big.json"
expect_match "$(cat "$big")" '"budget_retries": 1'
expect_match "$(cat "$big")" "\"max_memory\": $budget,"
expect_match "$(cat "$big")" '"threads": 1'
expect_match "$(cat "$WORK/hollow.state/tasks/small1.json")" '"budget_retries": 0'
expect_match "$(cat "$WORK/hollow.state/logs/big.log")" 'needs ~'
read -r big_start big_end <<< "$(line_times "$big")"
for part in small1 small2 small3; do
  read -r start end <<< "$(line_times "$WORK/hollow.state/tasks/$part.json")"
  if awk -v s="$start" -v e="$end" -v bs="$big_start" -v be="$big_end" 'BEGIN { exit !(e <= bs || s >= be) }'; then
    passed=$((passed + 1))
  else
    fail "$part ran ($start-$end) while big ran with the whole budget ($big_start-$big_end)"
  fi
done
expect_match "$(cat "$WORK/hollow.state/tasks/small2.json")" '"peak_memory_bytes": [1-9]'

# Under a budget nothing fits, every task fails with exit 3 and its message.
expect_exit 3 "$FABVDB" batch "$WORK/hollow.job" --inputs "$WORK/parts/small*.stl" --out "$WORK/tight" --max-memory 64K \
  --state "$WORK/tight.state"
expect_match "$STDERR" 'small1 failed.*memory budget exceeded.*needs ~'
expect_match "$(cat "$WORK/tight.state/tasks/small3.json")" '"exit_code": 3'
expect_exit 0 "$FABVDB" batch --status "$WORK/tight.state"
expect_match "$STDOUT" '3 task(s): 0 done, 3 failed, 0 pending'
expect_match "$STDOUT" 'failed   small2 (exit 3, job line 2): fabvdb hollow: memory budget exceeded'
expect_no_file "$WORK/tight/small1/hollow.stl"

# A bad input fails its task, the others are done; the batch exits with its code.
printf 'solid nothing\nendsolid\n' > "$WORK/parts/broken.stl"
expect_exit 2 "$FABVDB" batch "$WORK/hollow.job" --inputs "$WORK/parts/*.stl" --out "$WORK/mixed" --jobs 2 \
  --state "$WORK/mixed.state"
expect_match "$(cat "$WORK/mixed.state/tasks/broken.json")" '"status": "failed"'
expect_match "$(cat "$WORK/mixed.state/tasks/broken.json")" '"message": "fabvdb hollow: .*broken.stl'
for part in big small1 small2 small3; do expect_exit 0 test -f "$WORK/mixed/$part/hollow.stl"; done
rm "$WORK/parts/broken.stl"

# A command that crashes (here: the big part's hollow, killed with SIGSEGV
# while it runs) fails its own task only.
"$FABVDB" batch "$WORK/hollow.job" --inputs "$WORK/parts/*.stl" --out "$WORK/crash" --jobs 2 \
  --state "$WORK/crash.state" > "$WORK/crash.out" 2>&1 &
batch_pid=$!
child=""
for _ in $(seq 1 600); do
  for pid in $(pgrep -P "$batch_pid"); do
    grep -q 'big.stl' "/proc/$pid/cmdline" 2>/dev/null && child="$pid"
  done
  [ -n "$child" ] && break
  sleep 0.02
done
expect_match "$child" '^[0-9]'
kill -SEGV "$child" 2>/dev/null
code=0
wait "$batch_pid" || code=$?
expect_match "$code" '^4$'
expect_match "$(cat "$WORK/crash.state/tasks/big.json")" '"message": "killed by signal 11 (Segmentation fault)'
expect_match "$(cat "$WORK/crash.state/tasks/big.json")" '"exit_code": 4'
for part in small1 small2 small3; do
  expect_match "$(cat "$WORK/crash.state/tasks/$part.json")" '"status": "done"'
done
finish
