# bad_input_test.sh — every kind of broken input file gives exit code 2 and a
# message that names the file and the defect, and no partial output.
source "$(dirname "$0")/lib.sh"

check_bad() {  # check_bad FILE PATTERN: info on FILE exits 2, names it and matches PATTERN
  expect_exit 2 "$FABVDB" info "$1" --report "$WORK/report.json"
  expect_match "$STDERR" "^fabvdb info: "
  expect_match "$STDERR" "$(basename "$1")"
  expect_match "$STDERR" "$2"
  expect_no_file "$WORK/report.json"
}

: > "$WORK/empty.stl"
check_bad "$WORK/empty.stl" 'empty'

# A binary STL whose header says 1000 triangles but holds one.
{ head -c 80 /dev/zero; printf '\xe8\x03\x00\x00'; head -c 50 /dev/zero; } > "$WORK/truncated.stl"
check_bad "$WORK/truncated.stl" 'truncated\|triangles'

printf 'v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n' > "$WORK/nan.obj"
check_bad "$WORK/nan.obj" 'finite\|nan\|NaN'
printf 'v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n' > "$WORK/inf.obj"
check_bad "$WORK/inf.obj" 'finite\|inf'
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n' > "$WORK/index.obj"
check_bad "$WORK/index.obj" 'index\|range'
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n' > "$WORK/index.off"
check_bad "$WORK/index.off" 'index\|range'
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' > "$WORK/no_triangles.obj"
check_bad "$WORK/no_triangles.obj" 'triangle'
printf 'this is not a zip archive' > "$WORK/not_a_zip.3mf"
check_bad "$WORK/not_a_zip.3mf" '3MF\|3mf\|zip\|archive'
printf 'solid x\n' > "$WORK/model.xyz"
check_bad "$WORK/model.xyz" 'extension\|format'
mkdir -p "$WORK/folder.stl"
check_bad "$WORK/folder.stl" 'directory\|folder'
check_bad "$WORK/missing.stl" 'No such file\|not found\|missing\|cannot open'
finish
