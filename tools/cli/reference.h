/* reference.h — the command reference, generated from the commands' option
 * tables so that it cannot drift from `--help`: the README's command table,
 * the synopsis/options/exit-code block of each docs/<command>.md, the common
 * options of docs/README.md, and the man page fabvdb.1 (written at build time
 * by `fabvdb help --man`, installed by `cmake --install`).
 * tests/cli/reference_test.sh keeps the checked-in copies in step. Each
 * function prints to stdout and costs nothing worth measuring. */
#ifndef FABVDB_REFERENCE_H
#define FABVDB_REFERENCE_H

#include <stddef.h>

#include "cli.h"

/* `fabvdb help --markdown`: the command table of README.md (one row per
 * command, each linking its docs/<command>.md). */
void reference_markdown_commands(const cli_command* const* commands, size_t count);

/* `fabvdb help --markdown COMMAND`: synopsis, options and exit codes of one
 * command, the generated block of docs/<command>.md. */
void reference_markdown_command(const cli_command* command);

/* `fabvdb help --markdown --common`: the options of every command, the units
 * of option values and the exit codes, the generated block of docs/README.md. */
void reference_markdown_common(void);

/* `fabvdb help --man`: the whole man page fabvdb.1 in roff (man macros). */
void reference_man_page(const cli_command* const* commands, size_t count);

#endif
