# hollow_test.sh — `fabvdb hollow`: outputs checked by `fabvdb info` (closed,
# no self-intersection, one outer and one cavity shell, volume equal to the
# reported shell), reports with their keys, a part too thin for a cavity
# returned solid with a warning, bad parameters refused with exit 1 or 3 and
# no output file.
source "$(dirname "$0")/lib.sh"

number() {  # number FILE KEY: the first number after "KEY": in a JSON file
  sed -n "s/.*\"$2\": *\(-\{0,1\}[0-9.eE+-]*\).*/\1/p" "$1" | head -n 1
}

near() {  # near A B TOLERANCE: |A - B| <= TOLERANCE
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'
}

check_hollowed() {  # check_hollowed OUT REPORT: closed, clean, two shells, volume as reported
  expect_exit 0 "$FABVDB" info "$1" --report "$WORK/info.json"
  expect_match "$(cat "$WORK/info.json")" '"closed": true'
  expect_match "$(cat "$WORK/info.json")" '"self_intersecting_pairs": 0'
  local volume shell
  volume="$(number "$WORK/info.json" volume)"
  shell="$(number "$2" volume_shell)"
  if near "$volume" "$shell" "$(awk -v s="$shell" 'BEGIN { print 0.001 * s }')"; then
    passed=$((passed + 1))
  else
    fail "volume of $1 is $volume, report says $shell"
  fi
}

# A clean model keeps its outer surface; wall 3 mm, closing 2 mm.
expect_exit 0 "$FABVDB" hollow "$MESHES/bunny.off" --fit 60mm -o "$WORK/bunny.stl" --wall 3mm --closing 2mm --voxel 1mm \
  --report "$WORK/bunny.json"
for key in voxel_size wall closing volume_solid volume_shell material_saved_fraction cavities output_triangles timings; do
  expect_match "$(cat "$WORK/bunny.json")" "\"$key\""
done
expect_match "$(cat "$WORK/bunny.json")" '"outer_surface": "input"'
expect_match "$(cat "$WORK/bunny.json")" '"cavity_count": 1'
check_hollowed "$WORK/bunny.stl" "$WORK/bunny.json"
expect_match "$(cat "$WORK/info.json")" '"components": 2'

# A dirty model (holes, self-intersections) goes through the repair.
expect_exit 0 "$FABVDB" hollow "$MESHES/teapot.obj" --fit 40mm -o "$WORK/teapot.ply" --wall 1.5mm --voxel 0.75mm \
  --min-cavity 10 --report "$WORK/teapot.json"
expect_match "$(cat "$WORK/teapot.json")" '"outer_surface": "repaired"'
check_hollowed "$WORK/teapot.ply" "$WORK/teapot.json"

# The shell level set with -o .vdb.
expect_exit 0 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/sphere.vdb" --wall 3mm --voxel 1mm -q
[ -s "$WORK/sphere.vdb" ] && passed=$((passed + 1)) || fail "no VDB written"

# Gyroid infill: one solid (struts joined to the wall) around one void.
expect_exit 0 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/lattice.stl" --wall 2mm --voxel 0.5mm \
  --infill gyroid --cell 10mm --strut 2mm --report "$WORK/lattice.json"
expect_match "$(cat "$WORK/lattice.json")" '"pattern": "gyroid"'
expect_match "$(cat "$WORK/lattice.json")" '"cavity_count": 1'
check_hollowed "$WORK/lattice.stl" "$WORK/lattice.json"
expect_match "$(cat "$WORK/info.json")" '"components": 2'

# A part nowhere thicker than twice the wall comes back solid: exit 0, a
# warning, cavity_count 0, the output one closed clean shell.
expect_exit 0 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/thin.stl" --wall 25mm --report "$WORK/thin.json"
expect_match "$STDERR" "warning: .*no cavity"
expect_match "$(cat "$WORK/thin.json")" '"cavity_count": 0'
check_hollowed "$WORK/thin.stl" "$WORK/thin.json"
expect_match "$(cat "$WORK/info.json")" '"components": 1'

# Solid that the closed cavity leaves floating inside it would print loose:
# it becomes void, with a warning (3DBenchy at 100 mm: a 0.27 mm³ piece
# beside the cabin floor, 0.46 mm from the cavity around it). The output is
# the outer surface and one cavity, nothing else.
expect_exit 0 "$FABVDB" hollow "$SHARED/corpus/3DBenchy.3mf" --fit 100mm -o "$WORK/benchy.stl" --wall 3mm \
  --closing 2mm --report "$WORK/benchy.json"
expect_match "$STDERR" "warning: .*floating inside it"
check_hollowed "$WORK/benchy.stl" "$WORK/benchy.json"
expect_match "$(cat "$WORK/info.json")" '"components": 2'

# Bad parameters: exit 1 (or 3 for the budget) and no output.
expect_exit 1 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/bad.stl" --wall 0mm
expect_match "$STDERR" "wall"
expect_no_file "$WORK/bad.stl"
expect_exit 3 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/bad.stl" --wall 2mm --voxel 0.002mm \
  --max-memory 64M
expect_match "$STDERR" "voxel"
expect_no_file "$WORK/bad.stl"
expect_exit 1 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/bad.stl" --wall 2mm --voxel 3mm
expect_no_file "$WORK/bad.stl"
expect_exit 1 "$FABVDB" hollow "$MESHES/sphere.obj" --wall 2mm
expect_exit 1 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/bad.stl" --infill honeycomb
expect_match "$STDERR" "gyroid"
expect_exit 1 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/bad.stl" --cell 5mm
expect_exit 1 "$FABVDB" hollow "$MESHES/sphere.obj" --fit 40mm -o "$WORK/bad.vdb" --infill gyroid --cell 4mm \
  --strut 2mm
expect_no_file "$WORK/bad.vdb"
expect_no_file "$WORK/bad.stl"
finish
