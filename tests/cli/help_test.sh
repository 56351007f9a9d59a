# help_test.sh — the CLI skeleton: help, version, usage errors with exit 1.
# The generated reference (README, docs/, man page) is reference_test.sh's.
source "$(dirname "$0")/lib.sh"

expect_exit 0 "$FABVDB" --version
expect_match "$STDOUT" '^fabvdb [0-9]\+\.[0-9]\+\.[0-9]\+'
expect_exit 0 "$FABVDB" help
expect_match "$STDOUT" 'info'
expect_exit 1 "$FABVDB"
expect_exit 0 "$FABVDB" help info
expect_match "$STDOUT" 'Usage: fabvdb info'
expect_match "$STDOUT" '--report'
expect_exit 0 "$FABVDB" info --help
expect_match "$STDOUT" 'Exit codes'
expect_exit 1 "$FABVDB" no-such-command
expect_match "$STDERR" "no command 'no-such-command'"
expect_exit 1 "$FABVDB" help no-such-command
expect_exit 1 "$FABVDB" info
expect_match "$STDERR" 'missing input file'
expect_exit 1 "$FABVDB" info "$MESHES/sphere.obj" --no-such-option
expect_match "$STDERR" "unknown option '--no-such-option'"
expect_exit 1 "$FABVDB" info "$MESHES/sphere.obj" --threads -2
expect_exit 1 "$FABVDB" info "$MESHES/sphere.obj" --threads many
expect_match "$STDERR" 'takes a whole number'
expect_exit 1 "$FABVDB" info "$MESHES/sphere.obj" --max-memory 12parsecs
expect_exit 1 "$FABVDB" info "$MESHES/sphere.obj" --report
expect_match "$STDERR" 'needs a value'
expect_exit 1 "$FABVDB" info "$MESHES/sphere.obj" "$MESHES/torus.obj"
expect_match "$STDERR" 'unexpected argument'

finish
