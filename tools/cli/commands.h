/* commands.h — the subcommands of `fabvdb`, one file each: the CLI's in
 * tools/cli/cmd_*.c, batch's in tools/batch/cmd_batch.c, the studio's in
 * tools/studio/cmd_studio.c; their table is commands.c. */
#ifndef FABVDB_COMMANDS_H
#define FABVDB_COMMANDS_H

#include "cli.h"

extern const cli_command cmd_info;
extern const cli_command cmd_check;
extern const cli_command cmd_hollow;
extern const cli_command cmd_decompose;
extern const cli_command cmd_mold;
extern const cli_command cmd_repair;
extern const cli_command cmd_batch;
extern const cli_command cmd_drain;
extern const cli_command cmd_powder_sim;
extern const cli_command cmd_studio;

/* Every command, in the order `fabvdb help` lists them. */
extern const cli_command* const fabvdb_commands[];
extern const size_t fabvdb_command_count;

/* The command called `name`, or NULL. */
const cli_command* command_named(const char* name);

#endif
