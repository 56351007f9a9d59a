# lib.sh — helpers for the command-line tests, sourced by tests/cli/*_test.sh.
# Each test script gets: $1 the fabvdb binary, $2 the shared data folder,
# $3 the source folder. `expect_exit CODE CMD...` runs CMD, keeps its stderr in
# $STDERR and stdout in $STDOUT, and counts a pass when the exit code is CODE;
# `expect_match TEXT PATTERN` and `expect_no_file PATH` check outputs;
# `running PID` tells whether a process exists and is not a zombie (a child
# of a process that ended waits as one until init reaps it);
# `finish` prints "N passed, N failed" and exits non-zero on a failure.
set -u
FABVDB="$1"
SHARED="$2"
SOURCE="$3"
MESHES="$SHARED/meshes"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
passed=0
failed=0
STDOUT=""
STDERR=""

fail() {
  failed=$((failed + 1))
  echo "FAIL: $*" >&2
}

expect_exit() {
  local want="$1"
  shift
  local code=0
  "$@" >"$WORK/stdout" 2>"$WORK/stderr" || code=$?
  STDOUT="$(cat "$WORK/stdout")"
  STDERR="$(cat "$WORK/stderr")"
  if [ "$code" -eq "$want" ]; then
    passed=$((passed + 1))
  else
    fail "exit $code (wanted $want): $*"
    echo "  stderr: $STDERR" >&2
  fi
}

expect_match() {
  if printf '%s' "$1" | grep -q -- "$2"; then
    passed=$((passed + 1))
  else
    fail "'$2' not found in: $1"
  fi
}

expect_no_file() {
  if [ -e "$1" ] || compgen -G "$1.partial-*" >/dev/null; then
    fail "a file was left at $1"
  else
    passed=$((passed + 1))
  fi
}

running() {
  local state
  state=$(sed -n 's/^.*) \([A-Za-z]\).*/\1/p' "/proc/$1/stat" 2>/dev/null)
  [ -n "$state" ] && [ "$state" != Z ] && [ "$state" != X ]
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
