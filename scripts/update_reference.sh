#!/usr/bin/env bash
# Regenerates the command reference checked into README.md and docs/ from the
# option tables: the part between each file's begin/end markers is replaced by
# what `fabvdb help --markdown ...` prints (tests/cli/reference_test.sh fails
# until it is). Usage: bash scripts/update_reference.sh [BUILD_DIR (build)]
set -euo pipefail
cd "$(dirname "$0")/.."
FABVDB="${1:-build}/fabvdb"

# replace FILE MARKER ARGS...: the block between the markers becomes `fabvdb help ARGS...`.
replace() {
  local file="$1" marker="$2"
  shift 2
  "$FABVDB" help "$@" >"$file.generated"
  python3 - "$file" "$marker" "$file.generated" <<'PY'
import sys
path, marker, generated = sys.argv[1:]
text = open(path).read()
begin, end = f'<!-- {marker}:begin -->\n', f'<!-- {marker}:end -->'
if begin not in text or end not in text:
    sys.exit(f'{path}: no {marker} markers')
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(path, 'w').write(head + begin + open(generated).read() + end + tail)
PY
  rm -f "$file.generated"
}

replace README.md commands --markdown
replace docs/README.md reference --markdown --common
for command in $("$FABVDB" help | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p'); do
  [ -f "docs/$command.md" ] || { echo "docs/$command.md is missing: write its page with reference markers" >&2; exit 1; }
  replace "docs/$command.md" reference --markdown "$command"
done
