/* cli.h — the command-line framework of the `fabvdb` tool: each subcommand
 * declares its options once in a table (name, type, default, help), from which
 * parsing, `--help` and the README's command table come. Values with units
 * (lengths, angles, sizes) are parsed here; exit codes are mapped here, in one
 * place (cli_exit_docs, printed into docs/README.md and the man page). Uses only the public header fabvdb.h. */
#ifndef FABVDB_CLI_H
#define FABVDB_CLI_H

#include <stddef.h>

#include "fabvdb.h"

/* Exit codes of the `fabvdb` command. */
enum {
    CLI_EXIT_OK = 0,
    CLI_EXIT_USAGE = 1,
    CLI_EXIT_BAD_INPUT = 2,
    CLI_EXIT_BUDGET = 3,
    CLI_EXIT_INTERNAL = 4,
    CLI_EXIT_VERDICT = 5, /* `check`: the verdict reached --fail-on */
    CLI_EXIT_CANCELLED = 130
};

/* What each exit code means: the one table that `--help`, the man page and
 * docs/README.md print. */
typedef struct cli_exit_doc {
    int code;
    const char* meaning;
} cli_exit_doc;
extern const cli_exit_doc cli_exit_docs[];
extern const size_t cli_exit_doc_count;

typedef enum cli_option_type {
    CLI_FLAG,   /* no value */
    CLI_STRING, /* any text: a path, a name */
    CLI_NUMBER, /* a plain number */
    CLI_INT,    /* a whole number */
    CLI_LENGTH, /* 3mm, 0.3cm, 0.1in, 2% (of the bounding-box diagonal); bare numbers are mm */
    CLI_ANGLE,  /* 35deg, 0.6rad; bare numbers are degrees */
    CLI_SIZE    /* bytes: 512M, 4G, 2GiB; bare numbers are bytes */
} cli_option_type;

typedef struct cli_option {
    const char* name;       /* "--wall" */
    char short_name;        /* 'o', or 0 */
    cli_option_type type;
    const char* value_name; /* "LEN", shown in help; NULL for flags */
    const char* default_text; /* parsed as if given; NULL: unset unless given */
    const char* help;
} cli_option;

typedef struct cli_value {
    int given;        /* set on the command line */
    int set;          /* given, or has a default */
    const char* text; /* the text given (or the default text) */
    double number;    /* the parsed value: mm, degrees, bytes, or the number */
    int relative;     /* a length given in %: number is the fraction of the bbox diagonal */
} cli_value;

struct cli_run;
typedef struct cli_command {
    const char* name;
    const char* summary;     /* one line */
    const char* usage;       /* "INPUT -o OUTPUT [options]" */
    const char* description; /* paragraphs for `fabvdb help NAME` */
    const cli_option* options;
    size_t option_count;
    size_t positional_min, positional_max;
    int (*run)(struct cli_run* run);
} cli_command;

#define CLI_MAX_OPTIONS 64
#define CLI_MAX_POSITIONAL 8

typedef struct cli_run {
    const cli_command* command;
    fabvdb_ctx* ctx;
    cli_value values[CLI_MAX_OPTIONS];
    const char* positional[CLI_MAX_POSITIONAL];
    size_t positional_count;
    int quiet;
} cli_run;

/* The options every command has (--help, --quiet, --scale, --fit, --save-job, --threads, --max-memory). */
extern const cli_option cli_common_options[];
extern const size_t cli_common_option_count;

/* The option of `command` (its own table, then the common one) called by the
 * first `length` bytes of `name` ("--wall" of "--wall=3mm"), or, when
 * short_name is not 0, by that letter; NULL when it has none. */
const cli_option* cli_option_named(const cli_command* command, const char* name, size_t length, char short_name);
/* Options that set one thing in two ways (a voxel by its size or by a count
 * along the model; a scale by its factor or by the size it gives). The one
 * rule for them, in every command that has both: give one or the other,
 * never both (a usage error before any work); a default of one applies only
 * when neither is given. The reference prints this list. */
extern const char* const cli_alternatives[][2];
extern const size_t cli_alternative_count;

/* The value of option `name` of the running command (aborts on a name the
 * table does not have: a programming error). */
const cli_value* cli_get(const cli_run* run, const char* name);
/* A length option in mm: relative ones are resolved against `diagonal`. */
double cli_length_mm(const cli_run* run, const char* name, double diagonal);
/* A part-count option "auto|N": 0 into *parts for auto, else N (1 to 1000).
 * Returns CLI_EXIT_OK, or the usage error it printed. */
int cli_part_count(const cli_run* run, const char* name, int* parts);

/* Prints "fabvdb <command>: <status string>: <last error>"
 * (tools/common/status_text.h) and returns the exit code for `status`. */
int cli_fail(const cli_run* run, fabvdb_status status);
/* Prints "fabvdb <command>: <message>" for a usage error and returns 1. */
int cli_usage_error(const cli_run* run, const char* format, ...);
/* The exit code for a status. */
int cli_exit_code(fabvdb_status status);

/* Reads the input mesh at path and applies the common --scale / --fit options.
 * Returns CLI_EXIT_OK with *out set (the caller frees it), or the exit code
 * after printing the error. */
int cli_read_input(const cli_run* run, const char* path, fabvdb_mesh** out);

/* The bounding-box diagonal of all the mesh's vertices (0 for none): what a
 * length given in % is relative to. */
double cli_mesh_diagonal(const fabvdb_mesh* mesh);

/* The one rule of --voxel and --resolution, in every command that has them:
 * --voxel LEN is the voxel edge, > 0 (a % is of the bounding-box diagonal);
 * --resolution N (where the command has it) makes the voxel the mesh's
 * longest bounding-box side / N, N >= 8; never both (cli_alternatives);
 * neither leaves *voxel at 0, the command's own default. Returns
 * CLI_EXIT_OK, or the usage error it printed. */
int cli_voxel_size(const cli_run* run, const fabvdb_mesh* mesh, double* voxel);

/* Writes the report to the --report path of the running command, if one was
 * given, and notes it. Returns CLI_EXIT_OK, or the exit code after printing the
 * error. The caller still owns (and frees) the report. */
int cli_write_report(const cli_run* run, const fabvdb_report* report);

/* Prints each text of the report's "warnings" array on stderr, even with
 * --quiet: "fabvdb <command>: warning: <text>". Read through the report API
 * (fabvdb_report_count, fabvdb_report_string); a report without the array
 * prints nothing. */
void cli_print_warnings(const cli_run* run, const fabvdb_report* report);

/* Whether an output path names a level set (ends in .vdb, any case) rather
 * than a mesh. */
int cli_is_level_set_path(const char* path);

/* What a value of this type looks like, e.g. "an angle such as 35deg or
 * 0.6rad" (usage errors, the reference's units). */
const char* cli_type_hint(cli_option_type type);
/* Parses the units of one value; returns 0 on success. */
int cli_parse_value(cli_option_type type, const char* text, double* number, int* relative);

/* Runs `command` with argv (argv[0] is the command name). */
int cli_main(const cli_command* command, int argc, char** argv);
/* Prints the help of one command to stdout. */
void cli_print_command_help(const cli_command* command);

/* Writes a job file (tools/common/job.h) holding one command line:
 * `command_name` with argv[1..argc-1], less any --save-job option, and the
 * current directory; atomically (tools/common/atomic_file.h). Returns 0 on
 * success. */
int cli_write_job(const char* path, const char* command_name, int argc, char** argv);

/* Prints a line on stderr unless quiet (for "wrote FILE" messages). */
void cli_note(const cli_run* run, const char* format, ...);

#endif
