/* reference.c — prints the command reference (markdown for README.md and
 * docs/, roff for the man page) from the option tables of the commands (tools/cli/commands.c) and
 * cli.c; see reference.h. Text is escaped for its target: '|' in markdown
 * table cells, '\', '-' and leading dots in roff. */
#include "reference.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "fabvdb.h"

/* --- markdown ------------------------------------------------------------- */

/* A table cell: newlines and the spaces after them become one space, '|' is
 * escaped (GitHub tables split cells on it, even inside code spans). */
static void markdown_cell(const char* text) {
    for (const char* c = text; *c; ++c) {
        if (*c == '\n') {
            while (c[1] == ' ') ++c;
            putchar(' ');
        } else if (*c == '|') {
            fputs("\\|", stdout);
        } else {
            putchar(*c);
        }
    }
}

static void markdown_option_rows(const cli_option* options, size_t count) {
    printf("| option | meaning | default |\n|---|---|---|\n");
    for (size_t k = 0; k < count; ++k) {
        const cli_option* option = &options[k];
        fputs("| `", stdout);
        if (option->short_name) printf("-%c, ", option->short_name);
        markdown_cell(option->name);
        if (option->value_name) {
            putchar(' ');
            markdown_cell(option->value_name);
        }
        fputs("` | ", stdout);
        markdown_cell(option->help);
        fputs(" | ", stdout);
        if (option->default_text) markdown_cell(option->default_text);
        fputs(" |\n", stdout);
    }
}

static void markdown_exit_codes(void) {
    printf("| exit code | meaning |\n|---|---|\n");
    for (size_t i = 0; i < cli_exit_doc_count; ++i) {
        printf("| %d | ", cli_exit_docs[i].code);
        markdown_cell(cli_exit_docs[i].meaning);
        fputs(" |\n", stdout);
    }
}

void reference_markdown_commands(const cli_command* const* commands, size_t count) {
    printf("| command | what it does | reference |\n|---|---|---|\n");
    for (size_t i = 0; i < count; ++i) {
        printf("| `fabvdb %s ", commands[i]->name);
        markdown_cell(commands[i]->usage);
        fputs("` | ", stdout);
        markdown_cell(commands[i]->summary);
        printf(" | [docs/%s.md](docs/%s.md) |\n", commands[i]->name, commands[i]->name);
    }
}

void reference_markdown_command(const cli_command* command) {
    printf("## Synopsis\n\n```\nfabvdb %s %s\n```\n\n%c%s.\n\n## Options\n\n", command->name, command->usage,
           toupper((unsigned char)command->summary[0]), command->summary + 1);
    markdown_option_rows(command->options, command->option_count);
    printf("\nEvery command also takes the [common options](README.md#options-of-every-command).\n\n## Exit codes\n\n");
    markdown_exit_codes();
}

static const cli_option_type unit_types[] = {CLI_LENGTH, CLI_ANGLE, CLI_SIZE};

/* The rule of options that share a name (tests/tools/cli/cli_test.c checks
 * the tables keep it; cli_voxel_size applies the voxel's). */
static const char shared_names[] =
    "An option's name means one thing, with one kind of value, in every command that has it. --voxel LEN is the "
    "voxel edge (> 0; a % is of the bounding-box diagonal) and --resolution N makes it the longest bounding-box "
    "side / N (N >= 8); without either, each command's default voxel is the one its --voxel line gives.";

void reference_markdown_common(void) {
    printf("## Options of every command\n\n");
    markdown_option_rows(cli_common_options, cli_common_option_count);
    printf("\n## Options that set one thing two ways\n\nGive one or the other, never both (a usage error); a "
           "default of one applies only when neither is given:\n\n");
    for (size_t i = 0; i < cli_alternative_count; ++i)
        printf("- `%s` or `%s`\n", cli_alternatives[i][0], cli_alternatives[i][1]);
    printf("\n%s\n", shared_names);
    printf("\n## Values with units\n\n| value | written as |\n|---|---|\n");
    printf("| `LEN` | %s; a bare number is millimetres |\n", cli_type_hint(CLI_LENGTH));
    printf("| `ANGLE` | %s; a bare number is degrees |\n", cli_type_hint(CLI_ANGLE));
    printf("| `SIZE` | %s; a bare number is bytes |\n", cli_type_hint(CLI_SIZE));
    printf("\n## Exit codes\n\n");
    markdown_exit_codes();
}

/* --- roff ----------------------------------------------------------------- */

/* Text for a roff line: backslashes and hyphens escaped, and a line that
 * would start with '.' or '\'' (a request) protected with \&. */
static void roff_text(const char* text) {
    int line_start = 1;
    for (const char* c = text; *c; ++c) {
        if (line_start && (*c == '.' || *c == '\'')) fputs("\\&", stdout);
        line_start = 0;
        if (*c == '\\') {
            fputs("\\e", stdout);
        } else if (*c == '-') {
            fputs("\\-", stdout);
        } else if (*c == '\n') {
            putchar('\n');
            while (c[1] == ' ') ++c;
            line_start = 1;
        } else {
            putchar(*c);
        }
    }
}

/* One option as a tagged paragraph: the option in bold, its value in italics,
 * then the help and the default. */
static void roff_option(const cli_option* option) {
    fputs(".TP\n", stdout);
    if (option->short_name) printf("\\fB\\-%c\\fR, ", option->short_name);
    fputs("\\fB", stdout);
    roff_text(option->name);
    fputs("\\fR", stdout);
    if (option->value_name) {
        fputs(" \\fI", stdout);
        roff_text(option->value_name);
        fputs("\\fR", stdout);
    }
    putchar('\n');
    roff_text(option->help);
    if (option->default_text) {
        fputs(" (default: ", stdout);
        roff_text(option->default_text);
        putchar(')');
    }
    putchar('\n');
}

void reference_man_page(const cli_command* const* commands, size_t count) {
    printf(".\\\" fabvdb.1 \\- generated by 'fabvdb help \\-\\-man' from the option tables; do not edit.\n");
    printf(".TH FABVDB 1 \"\" \"fabvdb %s\" \"User Commands\"\n", fabvdb_version_string());
    printf(".SH NAME\nfabvdb \\- prepare 3D models for fabrication: repair, hollow, drain holes, molds\n");
    printf(".SH SYNOPSIS\n");
    for (size_t i = 0; i < count; ++i) {
        printf(".B fabvdb %s\n", commands[i]->name);
        roff_text(commands[i]->usage);
        printf("\n.br\n");
    }
    printf(".B fabvdb help\n[\\fICOMMAND\\fR]\n.br\n.B fabvdb \\-\\-version\n");
    printf(".SH DESCRIPTION\n"
           "fabvdb prepares 3D models for fabrication. It repairs dirty scans into clean solids, hollows parts\n"
           "before printing, finds where trapped powder can get out and drills drain holes, and cuts free\\-form\n"
           "objects into parts that each cast in a two\\-piece rigid mold. Inputs are STL, OBJ, PLY, OFF or\n"
           "3MF, read as millimetres. Outputs are written to a temporary file beside the target and renamed\n"
           "when complete, so a failed or cancelled run leaves no half\\-written file. A progress bar is drawn\n"
           "on standard error when it is a terminal.\n");
    printf(".SH COMMANDS\n");
    for (size_t i = 0; i < count; ++i) {
        const cli_command* command = commands[i];
        printf(".SS \"fabvdb %s\"\n", command->name);
        roff_text(command->summary);
        printf(".\n.PP\n");
        if (command->description && *command->description) {
            roff_text(command->description);
            printf("\n.PP\n");
        }
        printf("Options:\n.RS\n");
        for (size_t k = 0; k < command->option_count; ++k) roff_option(&command->options[k]);
        printf(".RE\n");
    }
    printf(".SH \"COMMON OPTIONS\"\nEvery command also takes:\n");
    for (size_t k = 0; k < cli_common_option_count; ++k) roff_option(&cli_common_options[k]);
    printf(".PP\nOptions that set one thing two ways take one or the other, never both (a usage error); a default\n"
           "of one applies only when neither is given:\n");
    for (size_t i = 0; i < cli_alternative_count; ++i) {
        printf(".br\n");
        roff_text(cli_alternatives[i][0]);
        printf(" or ");
        roff_text(cli_alternatives[i][1]);
        putchar('\n');
    }
    printf(".PP\n");
    roff_text(shared_names);
    putchar('\n');
    printf(".SH UNITS\n");
    static const char* const names[] = {"LEN", "ANGLE", "SIZE"};
    static const char* const bare[] = {"millimetres", "degrees", "bytes"};
    for (size_t k = 0; k < sizeof unit_types / sizeof unit_types[0]; ++k) {
        printf(".TP\n\\fI%s\\fR\n", names[k]);
        roff_text(cli_type_hint(unit_types[k]));
        printf("; a bare number is %s.\n", bare[k]);
    }
    printf(".SH \"EXIT STATUS\"\n");
    for (size_t i = 0; i < cli_exit_doc_count; ++i) {
        printf(".TP\n%d\n", cli_exit_docs[i].code);
        roff_text(cli_exit_docs[i].meaning);
        putchar('\n');
    }
    printf(".PP\nErrors are printed as \\fBfabvdb\\fR \\fIcommand\\fR: \\fIstatus\\fR: \\fImessage\\fR.\n");
    printf(".SH \"SEE ALSO\"\n"
           "The full reference of each command (method, report keys with units, known limits) is in\n"
           ".I docs/COMMAND.md\n"
           "of the source tree; the C API is documented in\n"
           ".IR fabvdb.h .\n");
}
