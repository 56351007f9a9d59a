# layout_test.sh — the shape of tools/ (issue 51): three programs (cli,
# batch, studio) over one folder of helpers (common). Checks that
#  - no file's includes lead back to it (tools/ has no include cycle), and
#    the folders depend one way: common on none of the others, the programs
#    on cli and common only, never on each other;
#  - each shared helper is written once: fork and exec only in
#    common/spawn.c, rename and fsync only in common/atomic_file.c, JSON
#    string escaping only in common/json.c, and no status's words typed by
#    hand (they come from fabvdb_status_string, common/status_text.c);
#  - every C file of tools/ is mapped to its test in tests/tools/README.md.
# Usage: bash layout_test.sh SOURCE_DIR
set -u
SOURCE="$1"
cd "$SOURCE" || exit 1
passed=0
failed=0
fail() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }
pass() { passed=$((passed + 1)); }

# The include graph: python3 is already a dependency (scripts/setup.sh).
if python3 - <<'PY'
import os, re, sys
files = {}
for folder, _, names in os.walk('tools'):
    for name in names:
        if name.endswith(('.c', '.h')):
            path = os.path.join(folder, name)
            files[path] = re.findall(r'^#include "([^"]+)"', open(path).read(), re.M)
def resolve(including, name):
    for candidate in (os.path.join(os.path.dirname(including), name), os.path.join('tools', name)):
        if os.path.normpath(candidate) in files:
            return os.path.normpath(candidate)
    return None  # fabvdb.h, civetweb.h: outside tools/
module = lambda path: os.path.splitext(path)[0]
edges = {}
for path, includes in files.items():
    for name in includes:
        target = resolve(path, name)
        if target and module(target) != module(path):
            edges.setdefault(module(path), set()).add(module(target))
# A cycle: a depth-first search that meets a module still on its path.
state, bad = {}, []
def visit(node, trail):
    state[node] = 'open'
    for nxt in sorted(edges.get(node, ())):
        if state.get(nxt) == 'open':
            bad.append(' -> '.join(trail[trail.index(nxt):] + [nxt]) if nxt in trail else node + ' -> ' + nxt)
        elif nxt not in state:
            visit(nxt, trail + [nxt])
    state[node] = 'done'
for node in sorted(edges):
    if node not in state:
        visit(node, [node])
allowed = {'common': {'common'}, 'cli': {'cli', 'common'}, 'batch': {'batch', 'cli', 'common'},
           'studio': {'studio', 'cli', 'common'}}
for source, targets in edges.items():
    for target in targets:
        a, b = source.split('/')[1], target.split('/')[1]
        if b not in allowed[a]:
            bad.append(f'{source} includes {target}: {a}/ may include only {sorted(allowed[a])}')
for line in bad:
    print('  ' + line, file=sys.stderr)
sys.exit(1 if bad else 0)
PY
then pass; else fail "tools/ has an include cycle or a folder that includes another it must not"; fi

# only_in PATTERN FILE WHAT: PATTERN (extended regex) occurs in tools/ only in FILE.
only_in() {
  local found
  found="$(grep -rlE --include='*.c' -e "$1" tools | grep -vx "$2" || true)"
  if [ -z "$found" ]; then pass; else fail "$3 outside $2: $found"; fi
}
only_in '\bfork\(' tools/common/spawn.c "fork"
only_in '\bexec[lv]p?e?\(' tools/common/spawn.c "exec"
only_in '\brename\(' tools/common/atomic_file.c "rename"
only_in '\bfsync\(' tools/common/atomic_file.c "fsync"
only_in 'mkstemp\(' tools/common/atomic_file.c "a temporary file of its own"
only_in '\\\\u%04x' tools/common/json.c "JSON string escaping"
typed="$(grep -rnE --include='*.c' -e '"(input/output error|io error|bad input|internal error|out of memory|not found): ' \
         tools | grep -v 'CLI_EXIT_' || true)"
[ -z "$typed" ] && pass || fail "a status's words typed by hand (use tools/common/status_text.h): $typed"

# Every C file of tools/ has its line in the map of tests.
for file in $(find tools -name '*.c' | sort); do
  if grep -q "\`$file\`" tests/tools/README.md; then pass; else fail "$file has no line in tests/tools/README.md"; fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
