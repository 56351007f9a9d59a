/* commands.c — the table of the subcommands of `fabvdb`, in the order the
 * overview and the reference list them, and the lookup by name that the
 * entry point and batch (to read a job line's options) share. */
#include "commands.h"

#include <string.h>

const cli_command* const fabvdb_commands[] = {
    &cmd_info,
    &cmd_check,
    &cmd_repair,
    &cmd_hollow,
    &cmd_drain,
    &cmd_powder_sim,
    &cmd_decompose,
    &cmd_mold,
    &cmd_studio,
    &cmd_batch,
};
const size_t fabvdb_command_count = sizeof(fabvdb_commands) / sizeof(fabvdb_commands[0]);

const cli_command* command_named(const char* name) {
    for (size_t i = 0; i < fabvdb_command_count; ++i)
        if (strcmp(fabvdb_commands[i]->name, name) == 0) return fabvdb_commands[i];
    return NULL;
}
