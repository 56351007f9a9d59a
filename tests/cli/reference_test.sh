# reference_test.sh — the command reference stays in step with the option
# tables everywhere it is written: the README's command table, the generated
# block of every docs/COMMAND.md and of docs/README.md, the man page built into
# the build folder, and `--help`. Each checked-in copy must equal what `fabvdb
# help --markdown ...` prints now; independently of that generator, every
# option `--help` lists must appear in the command's docs page and in its
# section of the man page, which must render without warnings.
source "$(dirname "$0")/lib.sh"
BUILD="$(dirname "$FABVDB")"

# The block between two markers of a file, markers excluded.
block() { sed -n "/<!-- $2:begin -->/,/<!-- $2:end -->/p" "$1" | sed '1d;$d'; }

# Compares a checked-in block with the generator's output; on a difference,
# says how to regenerate it.
same_block() {
  local file="$1" marker="$2" generated="$3" how="$4"
  local documented
  documented="$(block "$file" "$marker")"
  if [ -z "$documented" ]; then
    fail "$file has no '<!-- $marker:begin -->' ... '<!-- $marker:end -->' block (fill it with '$how')"
  elif [ "$generated" = "$documented" ]; then
    passed=$((passed + 1))
  else
    fail "$file is stale: replace the part between the $marker markers with '$how'"
    diff <(printf '%s\n' "$documented") <(printf '%s\n' "$generated") >&2 || true
  fi
}

expect_exit 0 "$FABVDB" help --markdown
same_block "$SOURCE/README.md" commands "$STDOUT" "fabvdb help --markdown"
expect_exit 0 "$FABVDB" help --markdown --common
same_block "$SOURCE/docs/README.md" reference "$STDOUT" "fabvdb help --markdown --common"
expect_exit 1 "$FABVDB" help --markdown no-such-command

# The commands, as the overview lists them (two-space indent, name, summary).
expect_exit 0 "$FABVDB" help
commands="$(printf '%s\n' "$STDOUT" | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p')"
[ -n "$commands" ] && passed=$((passed + 1)) || fail "no commands in 'fabvdb help'"

man_page="$BUILD/fabvdb.1"
expect_exit 0 test -f "$man_page"
expect_exit 0 "$FABVDB" help --man
if [ "$STDOUT" = "$(cat "$man_page")" ]; then
  passed=$((passed + 1))
else
  fail "$man_page differs from 'fabvdb help --man': the build did not regenerate it"
fi
# groff reports unknown macros, bad escapes and the like with -ww.
expect_exit 0 groff -man -Tutf8 -ww -z "$man_page"
[ -z "$STDERR" ] && passed=$((passed + 1)) || fail "the man page renders with warnings: $STDERR"
rendered="$(groff -man -Tutf8 -P-c "$man_page" 2>/dev/null | sed 's/\x1b\[[0-9;]*m//g; s/.\x08//g')"
expect_match "$rendered" 'EXIT STATUS'

for command in $commands; do
  page="$SOURCE/docs/$command.md"
  expect_exit 0 "$FABVDB" help --markdown "$command"
  same_block "$page" reference "$STDOUT" "fabvdb help --markdown $command"
  expect_match "$(cat "$SOURCE/README.md")" "docs/$command.md"
  # The man page's section of this command: from its .SS line to the next.
  section="$(sed -n "/^\.SS \"fabvdb $command\"/,/^\.S[SH] /p" "$man_page" | sed 's/\\-/-/g')"
  [ -n "$section" ] && passed=$((passed + 1)) || fail "the man page has no section for $command"
  expect_exit 0 "$FABVDB" "$command" --help
  options="$(printf '%s\n' "$STDOUT" | sed -n '/^Options:/,/^$/p' | grep -o -- '--[a-z][a-z-]*' | sort -u)"
  for option in $options; do
    if grep -q -- "\`$option\b\|\`-[a-z], $option\b" "$page"; then passed=$((passed + 1)); else
      fail "docs/$command.md does not document $option"; fi
    if printf '%s\n' "$section" | grep -q -- "$option"; then passed=$((passed + 1)); else
      fail "the man page's section of $command does not document $option"; fi
  done
done
finish
