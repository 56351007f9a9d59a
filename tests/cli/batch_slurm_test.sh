# batch_slurm_test.sh — `fabvdb batch --slurm` on a real single-node Slurm
# brought up here by tests/slurm/local_slurm.sh (munged, slurmctld, slurmd
# from Debian's packages, under a temporary folder, stopped by PID at the end):
# a recipe over five parts goes out as one job array (two tasks per index, the
# cluster's MaxArraySize being 4); one part is broken (its
# task fails and says why in its record), one hangs (its command is stopped
# with SIGSTOP, as on a dead file server) and is killed by Slurm at --time 1,
# which --status reports from Slurm since that task wrote no record; the good
# parts' outputs are checked; --resume --slurm resubmits exactly the two
# failed tasks and completes the batch.
source "$(dirname "$0")/lib.sh"

slurm_dir="$WORK/slurm"
cleanup() {
  bash "$SOURCE/tests/slurm/local_slurm.sh" stop "$slurm_dir"
  rm -rf "$WORK"
}
trap cleanup EXIT

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: batch_slurm_test needs root to start slurmd (CI runs as root)" >&2
  finish
  exit 0
fi
code=0
# A small MaxArraySize, so the five tasks go out in chunks of two per index.
started="$(LOCAL_SLURM_CONF_EXTRA="MaxArraySize=4" bash "$SOURCE/tests/slurm/local_slurm.sh" start "$slurm_dir" \
  2>"$WORK/slurm.err")" || code=$?
if [ "$code" -eq 3 ]; then
  echo "######## SKIPPED: Slurm's daemons cannot start on this machine:" >&2
  cat "$WORK/slurm.err" >&2
  echo "########" >&2
  finish
  exit 0
fi
expect_match "$code" '^0$'
[ "$code" -eq 0 ] || { cat "$WORK/slurm.err" >&2; finish; exit 1; }
eval "$started"
expect_match "$SLURM_CONF" "^$slurm_dir/slurm.conf$"

mkdir -p "$WORK/orders"
cp "$MESHES/sphere.obj" "$WORK/orders/ball.obj"
cp "$MESHES/torus.obj" "$WORK/orders/ring.obj"
cp "$MESHES/bunny.off" "$WORK/orders/bunny.off"
printf 'solid nothing\nendsolid\n' > "$WORK/orders/broken.stl"
cp "$MESHES/armadillo_86k.obj" "$WORK/orders/slow.obj"
cat > "$WORK/recipe.job" <<'JOB'
fabvdb-job 1
repair {input} --fit 40mm --voxel 1mm -o {out}/repaired.stl --report {out}/repair.json
hollow {prev} --wall 2mm --voxel 1mm -o {out}/hollow.stl --report {out}/hollow.json
JOB
state="$WORK/state"
run_batch() {  # run_batch EXPECTED_EXIT ARGS...: the recipe through Slurm, waiting for it
  local want="$1"
  shift
  expect_exit "$want" "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*" --out "$WORK/out" \
    --state "$state" --slurm --time 1 --max-running 3 --wait "$@"
}

# The first failed task in job order is 'broken' (exit 2). The hanging task:
# its repair is stopped as soon as it runs.
# Polled by time, not by count: on a loaded machine Slurm may take long to
# start the task, and the repair itself lasts under a second.
(
  deadline=$((SECONDS + 600))
  while [ "$SECONDS" -lt "$deadline" ]; do
    pid="$(pgrep -f "fabvdb repair .*$WORK/orders/slow.obj" | head -n 1)"
    [ -n "$pid" ] && { kill -STOP "$pid"; echo "$pid" > "$WORK/stopped"; break; }
    sleep 0.01
  done
) &
stopper=$!
run_batch 2
wait "$stopper"
expect_match "$STDERR" 'submitted 5 task(s) as Slurm job array [0-9]* (indices 0-2%3, 2 task(s) per index)'
expect_match "$STDOUT" '5 task(s): 3 done, 2 failed, 0 pending'
job="$(cut -f1 "$state/slurm/submissions.tsv" | head -n 1)"
expect_match "$STDOUT" "failed   broken (exit 2, job line 2): fabvdb repair: .*broken.stl"
expect_match "$STDOUT" "failed   slow: Slurm job ${job}_2 TIMEOUT (reason TimeLimit), no record"
# Index 0 ran ball and broken, one after the other.
expect_match "$(cat "$state/tasks/ball.json")" "\"slurm_job\": \"${job}_0\""
expect_match "$(cat "$state/tasks/broken.json")" "\"slurm_job\": \"${job}_0\""
expect_exit 0 test -s "$WORK/stopped"
for part in ball ring bunny; do
  record="$state/tasks/$part.json"
  expect_match "$(cat "$record")" '"status": "done"'
  expect_match "$(cat "$record")" "\"slurm_job\": \"${job}_[0-9]\""
  expect_exit 0 "$FABVDB" info "$WORK/out/$part/hollow.stl" --report "$WORK/info.json" --quiet
  expect_match "$(cat "$WORK/info.json")" '"closed": true'
  expect_match "$(tr -d '\n' < "$record")" "\"sha256\": \"$(sha256sum "$WORK/out/$part/hollow.stl" | cut -d' ' -f1)\""
  cp "$record" "$WORK/$part.before"
done
expect_no_file "$state/tasks/slow.json"
expect_no_file "$WORK/out/slow/repaired.stl"
if running "$(cat "$WORK/stopped")"; then fail "Slurm left the hanging command"; else passed=$((passed + 1)); fi
expect_exit 0 "$FABVDB" batch --status "$state"
expect_match "$STDOUT" 'slow: Slurm job .* TIMEOUT'
expect_match "$(cat "$state/status.json")" '"message": "Slurm job [0-9_]* TIMEOUT (reason TimeLimit), no record"'
# Slurm's own account agrees: the job-completion log holds the time-out.
expect_match "$(cat "$slurm_dir/jobcomp.log")" "JobState=TIMEOUT.*ArrayJobId=$job "

# Mend the broken part and resume: only the two failed tasks go out again,
# the others stay as they were.
"$FABVDB" repair "$MESHES/spot.obj" -o "$WORK/orders/broken.stl" --voxel 1mm --fit 40mm --quiet
run_batch 0 --resume
expect_match "$STDERR" '3 of 5 task(s) are done already and unchanged'
expect_match "$STDERR" 'submitted 2 task(s)'
expect_match "$STDOUT" '5 task(s): 5 done, 0 failed, 0 pending'
expect_match "$(wc -l < "$state/slurm/submissions.tsv")" '^7$'
for part in ball ring bunny; do expect_exit 0 cmp "$WORK/$part.before" "$state/tasks/$part.json"; done
expect_exit 0 test -f "$WORK/out/slow/hollow.stl"

# Every daemon stops, by PID (a zombie waiting for init to reap it has
# stopped).
pids="$(awk '{ print $2 }' "$slurm_dir/pids")"
expect_exit 0 bash "$SOURCE/tests/slurm/local_slurm.sh" stop "$slurm_dir"
for pid in $pids; do
  if running "$pid"; then fail "daemon $pid still runs"; else passed=$((passed + 1)); fi
done
finish
