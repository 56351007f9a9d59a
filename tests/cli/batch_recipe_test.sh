# batch_recipe_test.sh — recipes: one task per input of --inputs (a glob or a
# folder), placeholders replaced ({input} {name} {stem} {out} {prev}), each task
# writing into its own folder; the outputs are the bytes the same commands
# give when run by hand, and the records' SHA-256 are sha256sum's; bad recipes
# and placeholders are refused with exit 2 naming the line, a recipe without
# --inputs or --out with exit 1.
source "$(dirname "$0")/lib.sh"

field() {  # field FILE KEY: the first string value of "KEY" in a JSON file
  sed -n "s/.*\"$2\": \"\([^\"]*\)\".*/\1/p" "$1" | head -n 1
}

mkdir -p "$WORK/orders" "$WORK/folder"
cp "$MESHES/sphere.obj" "$WORK/orders/ball.obj"
cp "$MESHES/torus.obj" "$WORK/orders/ring.obj"
cp "$MESHES/sphere.obj" "$WORK/folder/ball.obj"
printf 'not a mesh\n' > "$WORK/folder/notes.txt"
cat > "$WORK/recipe.job" <<'JOB'
fabvdb-job 1
# repair each order, then hollow what the repair wrote
repair {input} --fit 40mm --voxel 1mm -o {out}/{stem}_repaired.stl --report {out}/repair.json
hollow {prev} --wall 3mm --voxel 1mm -o {out}/hollow.stl --report {out}/hollow.json
JOB

# Dry run: the expanded commands of every task, nothing written.
expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/results" --dry-run
expect_match "$STDOUT" '^# task ball$'
expect_match "$STDOUT" "^fabvdb repair $WORK/orders/ball.obj --fit 40mm --voxel 1mm -o $WORK/results/ball/ball_repaired.stl"
expect_match "$STDOUT" "^fabvdb hollow $WORK/results/ring/ring_repaired.stl --wall 3mm"
expect_no_file "$WORK/recipe.state"

expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj" --out "$WORK/results" --threads 2 \
  --jobs 2
expect_match "$STDERR" 'batch: 2 done, 0 failed, 0 pending'
for part in ball ring; do
  expect_exit 0 test -f "$WORK/results/$part/hollow.stl"
  record="$WORK/recipe.state/tasks/$part.json"
  expect_match "$(cat "$record")" '"status": "done"'
  expect_match "$(cat "$record")" "\"input\": \"$WORK/orders/$part.obj\""
  expect_match "$(cat "$record")" '"threads": 1'
  # The same commands by hand (one thread, as the batch gave each) write the same bytes.
  expect_exit 0 "$FABVDB" repair "$WORK/orders/$part.obj" --fit 40mm --voxel 1mm -o "$WORK/$part.stl" --threads 1 --quiet
  expect_exit 0 "$FABVDB" hollow "$WORK/$part.stl" --wall 3mm --voxel 1mm -o "$WORK/${part}_hollow.stl" --threads 1 --quiet
  expect_exit 0 cmp "$WORK/$part.stl" "$WORK/results/$part/${part}_repaired.stl"
  expect_exit 0 cmp "$WORK/${part}_hollow.stl" "$WORK/results/$part/hollow.stl"
  # Every input and output with sha256sum's hash.
  for file in "$WORK/orders/$part.obj" "$WORK/results/$part/hollow.stl" "$WORK/results/$part/repair.json"; do
    expect_match "$(tr -d '\n' < "$record")" "\"path\": \"$file\", \"sha256\": \"$(sha256sum "$file" | cut -d' ' -f1)\""
  done
  expect_match "$(cat "$record")" "\"command\": \"hollow\", \"path\": \"$WORK/results/$part/hollow.json\""
done
expect_exit 0 "$FABVDB" info "$WORK/results/ball/hollow.stl" --report "$WORK/info.json" --quiet
expect_match "$(cat "$WORK/info.json")" '"closed": true'

# A folder as --inputs takes its meshes only; --state puts the records elsewhere.
expect_exit 0 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/folder" --out "$WORK/from_folder" \
  --state "$WORK/elsewhere" --quiet
expect_exit 0 test -f "$WORK/elsewhere/tasks/ball.json"
expect_no_file "$WORK/elsewhere/tasks/notes.json"
expect_match "$(cat "$WORK/elsewhere/plan.job")" '^task "ball"'

# The report: per task its figures from each command's report.
expect_exit 0 "$FABVDB" batch --status "$WORK/recipe.state" --report "$WORK/batch.json"
expect_match "$STDOUT" '2 task(s): 2 done, 0 failed, 0 pending'
expect_match "$(cat "$WORK/batch.json")" '"material_saved_fraction": 0\.[0-9]'
expect_match "$(cat "$WORK/batch.json")" '"command": "repair"'

# {name} and literal braces.
cat > "$WORK/names.job" <<'JOB'
fabvdb-job 1
info {input} --report "{out}/{{{name}}}.json"
JOB
expect_exit 0 "$FABVDB" batch "$WORK/names.job" --inputs "$WORK/orders/ring.obj" --out "$WORK/named" --quiet
expect_exit 0 test -f "$WORK/named/ring/{ring.obj}.json"

# Refusals, with the file and line.
bad() {  # bad NAME LINE: writes a recipe whose second line is LINE
  printf 'fabvdb-job 1\n%s\n' "$2" > "$WORK/$1.job"
}
bad typo 'info {inptu} --report {out}/i.json'
expect_exit 2 "$FABVDB" batch "$WORK/typo.job" --inputs "$WORK/orders/*.obj" --out "$WORK/r"
expect_match "$STDERR" 'typo.job:2: .{inptu}.: an unknown placeholder'
bad open 'info {input --report x.json'
expect_exit 2 "$FABVDB" batch "$WORK/open.job" --inputs "$WORK/orders/*.obj"
expect_match "$STDERR" "open.job:2: '{input': a '{' is not closed"
bad prev 'info {prev}'
expect_exit 2 "$FABVDB" batch "$WORK/prev.job"
expect_match "$STDERR" 'prev.job:2: .{prev}.: {prev} needs a line above with an --output'
bad option 'hollow {input} --wal 3mm -o {out}/h.stl'
expect_exit 2 "$FABVDB" batch "$WORK/option.job" --inputs "$WORK/orders/*.obj" --out "$WORK/r"
expect_match "$STDERR" 'option.job:2: hollow: an option the command does not have'
bad nested 'batch {input}'
expect_exit 2 "$FABVDB" batch "$WORK/nested.job" --inputs "$WORK/orders/*.obj"
expect_match "$STDERR" "nested.job:2: no command 'batch'"
printf 'fabvdb-job 1\ntask one\ninfo "%s"\ntask one\ninfo "%s"\n' "$MESHES/sphere.obj" "$MESHES/torus.obj" > "$WORK/twice.job"
expect_exit 2 "$FABVDB" batch "$WORK/twice.job"
expect_match "$STDERR" "twice.job:4: a second task called 'one'"
expect_exit 1 "$FABVDB" batch "$WORK/recipe.job"
expect_match "$STDERR" 'is a recipe .* give --inputs'
expect_exit 1 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.obj"
expect_match "$STDERR" 'uses {out}: give --out'
expect_exit 2 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/orders/*.stl" --out "$WORK/r"
expect_match "$STDERR" "no input file matches"
mkdir -p "$WORK/other"
cp "$MESHES/torus.obj" "$WORK/other/ball.obj"
expect_exit 2 "$FABVDB" batch "$WORK/recipe.job" --inputs "$WORK/{orders,other}/ball.obj" --out "$WORK/r"
expect_match "$STDERR" "both make the task 'ball'"
expect_exit 1 "$FABVDB" batch "$WORK/twice.job" --inputs "$WORK/orders/*.obj"
expect_match "$STDERR" '--inputs needs a recipe'
finish
