# studio_test.sh — `fabvdb studio` on the command line: its help, usage errors
# (exit 1) and a missing model (exit 2) before any server starts. The server
# itself is tested by studio/tests/*_test.mjs (ctest studio/...).
source "$(dirname "$0")/lib.sh"

expect_exit 0 "$FABVDB" studio --help
expect_match "$STDOUT" 'token'
expect_match "$STDOUT" '--no-browser'
expect_exit 1 "$FABVDB" studio "$MESHES/sphere.obj" --port 70000 --no-browser
expect_match "$STDERR" 'port'
expect_exit 1 "$FABVDB" studio "$MESHES/sphere.obj" --parts many --no-browser
expect_exit 1 "$FABVDB" studio "$MESHES/sphere.obj" --draft 45deg --no-browser
expect_exit 1 "$FABVDB" studio --no-browser
expect_exit 2 "$FABVDB" studio "$WORK/missing.obj" --no-browser
expect_exit 2 "$FABVDB" studio "$MESHES/sphere.obj" -o "$WORK/no/such/folder" --no-browser
finish
