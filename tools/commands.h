/* commands.h — the subcommands of `fabvdb`, one file each (tools/cmd_*.c). */
#ifndef FABVDB_COMMANDS_H
#define FABVDB_COMMANDS_H

#include "cli.h"

extern const cli_command cmd_info;
extern const cli_command cmd_hollow;
extern const cli_command cmd_decompose;
extern const cli_command cmd_mold;
extern const cli_command cmd_repair;
extern const cli_command cmd_batch;
extern const cli_command cmd_drain;
extern const cli_command cmd_powder_sim;
extern const cli_command cmd_studio;

/* The command called `name`, or NULL (tools/fabvdb.c). */
const cli_command* command_named(const char* name);

#endif
