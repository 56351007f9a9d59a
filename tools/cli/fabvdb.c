/* fabvdb.c — entry point of the `fabvdb` command: dispatches to a subcommand
 * (the table of commands.c), and answers `help`, `help COMMAND`, `--help`,
 * `--version`, and the generated reference (reference.h): `help --markdown
 * [COMMAND|--common]` and `help --man`. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "commands.h"
#include "reference.h"

static void print_overview(void) {
    printf("fabvdb %s — prepares 3D models for fabrication.\n\n"
           "Usage: fabvdb COMMAND INPUT [options]\n\nCommands:\n",
           fabvdb_version_string());
    for (size_t i = 0; i < fabvdb_command_count; ++i)
        printf("  %-12s %s\n", fabvdb_commands[i]->name, fabvdb_commands[i]->summary);
    printf("\n'fabvdb help COMMAND' (or 'fabvdb COMMAND --help') explains a command and its options.\n"
           "Lengths take units: 3mm, 0.3cm, 0.1in, or 2%% of the model's bounding-box diagonal.\n"
           "Outputs appear only when complete. The full reference: 'man fabvdb' and docs/ in the sources.\n"
           "\nExit codes:\n");
    for (size_t i = 0; i < cli_exit_doc_count; ++i) printf("  %-4d %s\n", cli_exit_docs[i].code, cli_exit_docs[i].meaning);
}

int main(int argc, char** argv) {
    if (argc < 2) {
        print_overview();
        return CLI_EXIT_USAGE;
    }
    const char* first = argv[1];
    if (strcmp(first, "--version") == 0 || strcmp(first, "version") == 0) {
        printf("fabvdb %s\n", fabvdb_version_string());
        return CLI_EXIT_OK;
    }
    if (strcmp(first, "help") == 0 || strcmp(first, "--help") == 0 || strcmp(first, "-h") == 0) {
        if (argc < 3) {
            print_overview();
            return CLI_EXIT_OK;
        }
        if (strcmp(argv[2], "--man") == 0 && argc == 3) {
            reference_man_page(fabvdb_commands, fabvdb_command_count);
            return CLI_EXIT_OK;
        }
        if (strcmp(argv[2], "--markdown") == 0 && argc <= 4) {
            if (argc == 3) {
                reference_markdown_commands(fabvdb_commands, fabvdb_command_count);
            } else if (strcmp(argv[3], "--common") == 0) {
                reference_markdown_common();
            } else if (command_named(argv[3])) {
                reference_markdown_command(command_named(argv[3]));
            } else {
                fprintf(stderr, "fabvdb: no command '%s' (see 'fabvdb help')\n", argv[3]);
                return CLI_EXIT_USAGE;
            }
            return CLI_EXIT_OK;
        }
        const cli_command* command = command_named(argv[2]);
        if (!command) {
            fprintf(stderr, "fabvdb: no command '%s' (see 'fabvdb help')\n", argv[2]);
            return CLI_EXIT_USAGE;
        }
        cli_print_command_help(command);
        return CLI_EXIT_OK;
    }
    const cli_command* command = command_named(first);
    if (!command) {
        fprintf(stderr, "fabvdb: no command '%s' (see 'fabvdb help')\n", first);
        return CLI_EXIT_USAGE;
    }
    return cli_main(command, argc - 1, argv + 1);
}
