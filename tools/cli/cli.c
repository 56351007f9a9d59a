/* cli.c — option parsing from the per-command tables, value units, help text,
 * the progress bar (stderr, only on a terminal), Ctrl-C as cancellation, the
 * mapping of statuses to exit codes, warnings read from reports, and
 * --save-job. */
#define _DEFAULT_SOURCE /* POSIX: sigaction, getcwd */
#include "cli.h"

#include <ctype.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/atomic_file.h"
#include "common/job.h"
#include "common/status_text.h"

const cli_option cli_common_options[] = {
    {"--help", 'h', CLI_FLAG, NULL, NULL, "show this help and exit"},
    {"--quiet", 'q', CLI_FLAG, NULL, NULL, "no progress bar and no notes on stderr (errors are still printed)"},
    {"--threads", 0, CLI_INT, "N", "0", "worker threads; 0 uses every core"},
    {"--scale", 0, CLI_NUMBER, "F", NULL, "multiply the input's coordinates by F first (a file in metres: 1000)"},
    {"--fit", 0, CLI_LENGTH, "LEN", NULL, "scale the input uniformly first so its longest side is LEN, e.g. 100mm"},
    {"--save-job", 0, CLI_STRING, "FILE.job", NULL,
     "also write this command line as a job file that 'fabvdb batch' replays exactly"},
    {"--max-memory", 0, CLI_SIZE, "SIZE", NULL,
     "memory budget, e.g. 8G or 512M (default: half the physical memory); work that would exceed it is refused "
     "with exit code 3"},
};
const size_t cli_common_option_count = sizeof(cli_common_options) / sizeof(cli_common_options[0]);

/* Options are looked up in the command's table, then in the common table;
 * values[] holds the command's options first. */
static const cli_option* option_at(const cli_command* command, size_t index) {
    return index < command->option_count ? &command->options[index]
                                         : &cli_common_options[index - command->option_count];
}

static size_t option_total(const cli_command* command) { return command->option_count + cli_common_option_count; }

static int find_option(const cli_command* command, const char* name, size_t length, char short_name) {
    for (size_t i = 0; i < option_total(command); ++i) {
        const cli_option* option = option_at(command, i);
        if (short_name ? option->short_name == short_name
                       : (strlen(option->name) == length && strncmp(option->name, name, length) == 0))
            return (int)i;
    }
    return -1;
}

const cli_option* cli_option_named(const cli_command* command, const char* name, size_t length, char short_name) {
    const int index = find_option(command, name, length, short_name);
    return index < 0 ? NULL : option_at(command, (size_t)index);
}

const cli_value* cli_get(const cli_run* run, const char* name) {
    int index = find_option(run->command, name, strlen(name), 0);
    if (index < 0) {
        fprintf(stderr, "fabvdb: internal error: option %s is not in the table of '%s'\n", name,
                run->command->name);
        abort();
    }
    return &run->values[index];
}

double cli_length_mm(const cli_run* run, const char* name, double diagonal) {
    const cli_value* value = cli_get(run, name);
    return value->relative ? value->number * diagonal : value->number;
}

/* --- values with units ---------------------------------------------------- */

static int unit_is(const char* unit, const char* name) { return strcasecmp(unit, name) == 0; }

int cli_parse_value(cli_option_type type, const char* text, double* number, int* relative) {
    *relative = 0;
    if (type == CLI_FLAG || type == CLI_STRING) return 0;
    char* end = NULL;
    double value = strtod(text, &end);
    if (end == text || !isfinite(value)) return -1;
    const char* unit = end;
    switch (type) {
        case CLI_NUMBER:
            if (*unit) return -1;
            break;
        case CLI_INT:
            if (*unit || value != floor(value)) return -1;
            break;
        case CLI_LENGTH:
            if (!*unit || unit_is(unit, "mm")) {
            } else if (unit_is(unit, "cm")) {
                value *= 10.0;
            } else if (unit_is(unit, "m")) {
                value *= 1000.0;
            } else if (unit_is(unit, "in")) {
                value *= 25.4;
            } else if (unit_is(unit, "%")) {
                value /= 100.0;
                *relative = 1;
            } else {
                return -1;
            }
            break;
        case CLI_ANGLE:
            if (!*unit || unit_is(unit, "deg")) {
            } else if (unit_is(unit, "rad")) {
                value *= 180.0 / M_PI;
            } else {
                return -1;
            }
            break;
        case CLI_SIZE: {
            double scale = 1.0;
            if (!*unit || unit_is(unit, "B")) scale = 1.0;
            else if (unit_is(unit, "K") || unit_is(unit, "KB") || unit_is(unit, "KiB")) scale = 1024.0;
            else if (unit_is(unit, "M") || unit_is(unit, "MB") || unit_is(unit, "MiB")) scale = 1024.0 * 1024.0;
            else if (unit_is(unit, "G") || unit_is(unit, "GB") || unit_is(unit, "GiB")) scale = 1024.0 * 1024.0 * 1024.0;
            else return -1;
            value *= scale;
            break;
        }
        default:
            return -1;
    }
    *number = value;
    return 0;
}

const char* cli_type_hint(cli_option_type type) {
    switch (type) {
        case CLI_LENGTH: return "a length such as 3mm, 0.3cm, 0.1in or 2% (of the bounding-box diagonal)";
        case CLI_ANGLE: return "an angle such as 35deg or 0.6rad";
        case CLI_SIZE: return "a size such as 512M or 8G";
        case CLI_INT: return "a whole number";
        case CLI_NUMBER: return "a number";
        default: return "a value";
    }
}

/* --- messages and exit codes -------------------------------------------- */

const cli_exit_doc cli_exit_docs[] = {
    {CLI_EXIT_OK, "done"},
    {CLI_EXIT_USAGE, "usage error: unknown option, bad or out-of-range value, missing argument"},
    {CLI_EXIT_BAD_INPUT, "bad input: a file is missing, unreadable or malformed (the message names the file and the defect)"},
    {CLI_EXIT_BUDGET, "resource budget exceeded (--max-memory; the message proposes what fits)"},
    {CLI_EXIT_INTERNAL, "internal error (a bug: please report it with the input)"},
    {CLI_EXIT_VERDICT, "check only: the verdict reached --fail-on (the part will not print as it is; the output says why)"},
    {CLI_EXIT_CANCELLED, "cancelled (Ctrl-C, SIGTERM); no output is left behind"},
};
const size_t cli_exit_doc_count = sizeof(cli_exit_docs) / sizeof(cli_exit_docs[0]);

int cli_exit_code(fabvdb_status status) {
    switch (status) {
        case FABVDB_OK: return CLI_EXIT_OK;
        case FABVDB_ERR_INVALID_ARGUMENT: return CLI_EXIT_USAGE;
        case FABVDB_ERR_IO:
        case FABVDB_ERR_BAD_INPUT:
        case FABVDB_ERR_NOT_FOUND: return CLI_EXIT_BAD_INPUT;
        case FABVDB_ERR_OUT_OF_BUDGET:
        case FABVDB_ERR_OUT_OF_MEMORY: return CLI_EXIT_BUDGET;
        case FABVDB_ERR_CANCELLED: return CLI_EXIT_CANCELLED;
        case FABVDB_ERR_INTERNAL: return CLI_EXIT_INTERNAL;
    }
    return CLI_EXIT_INTERNAL;
}

static int progress_shown = 0;

static void clear_progress_line(void) {
    if (progress_shown) {
        fputs("\r\033[K", stderr);
        progress_shown = 0;
    }
}

int cli_fail(const cli_run* run, fabvdb_status status) {
    clear_progress_line();
    status_print(run->command->name, status, "%s", fabvdb_last_error(run->ctx));
    return cli_exit_code(status);
}

int cli_part_count(const cli_run* run, const char* name, int* parts) {
    const char* text = cli_get(run, name)->text;
    *parts = 0;
    if (strcmp(text, "auto") == 0) return CLI_EXIT_OK;
    char* end = NULL;
    const long count = strtol(text, &end, 10);
    if (*text == '\0' || *end != '\0' || count < 1 || count > 1000)
        return cli_usage_error(run, "%s must be auto or a whole number from 1 to 1000", name);
    *parts = (int)count;
    return CLI_EXIT_OK;
}

int cli_usage_error(const cli_run* run, const char* format, ...) {
    clear_progress_line();
    va_list args;
    va_start(args, format);
    fprintf(stderr, "fabvdb %s: ", run->command->name);
    vfprintf(stderr, format, args);
    fprintf(stderr, "\n(see 'fabvdb help %s')\n", run->command->name);
    va_end(args);
    return CLI_EXIT_USAGE;
}

void cli_note(const cli_run* run, const char* format, ...) {
    if (run->quiet) return;
    clear_progress_line();
    va_list args;
    va_start(args, format);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
}

/* --- input and reports ------------------------------------------------- */

/* Bounds of all vertices; an empty mesh gives a zero box. */
static void mesh_bounds(const fabvdb_mesh* mesh, double lo[3], double hi[3]) {
    const double* v = fabvdb_mesh_vertices(mesh);
    const size_t n = fabvdb_mesh_vertex_count(mesh);
    for (int k = 0; k < 3; ++k) {
        lo[k] = n ? INFINITY : 0.0;
        hi[k] = n ? -INFINITY : 0.0;
    }
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            if (v[3 * i + k] < lo[k]) lo[k] = v[3 * i + k];
            if (v[3 * i + k] > hi[k]) hi[k] = v[3 * i + k];
        }
}

double cli_mesh_diagonal(const fabvdb_mesh* mesh) {
    double lo[3], hi[3], sum = 0;
    mesh_bounds(mesh, lo, hi);
    for (int k = 0; k < 3; ++k) sum += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return sqrt(sum);
}

int cli_voxel_size(const cli_run* run, const fabvdb_mesh* mesh, double* voxel) {
    *voxel = 0.0;
    if (cli_get(run, "--voxel")->set) {
        *voxel = cli_length_mm(run, "--voxel", cli_mesh_diagonal(mesh));
        if (!(*voxel > 0.0)) return cli_usage_error(run, "--voxel must be a positive length");
    }
    if (cli_option_named(run->command, "--resolution", strlen("--resolution"), 0) && cli_get(run, "--resolution")->set) {
        const double resolution = cli_get(run, "--resolution")->number;
        if (!(resolution >= 8.0)) return cli_usage_error(run, "--resolution must be >= 8");
        double lo[3], hi[3], longest = 0.0;
        mesh_bounds(mesh, lo, hi);
        for (int k = 0; k < 3; ++k)
            if (hi[k] - lo[k] > longest) longest = hi[k] - lo[k];
        *voxel = longest / resolution;
    }
    return CLI_EXIT_OK;
}

int cli_is_level_set_path(const char* path) {
    const size_t n = strlen(path);
    return n >= 4 && strcasecmp(path + n - 4, ".vdb") == 0;
}

int cli_write_report(const cli_run* run, const fabvdb_report* report) {
    const cli_value* path = cli_get(run, "--report");
    if (!path->set || !report) return CLI_EXIT_OK;
    fabvdb_status status = fabvdb_report_write(run->ctx, report, path->text);
    if (status != FABVDB_OK) return cli_fail(run, status);
    cli_note(run, "wrote %s", path->text);
    return CLI_EXIT_OK;
}

void cli_print_warnings(const cli_run* run, const fabvdb_report* report) {
    size_t count = 0;
    if (!report || fabvdb_report_count(run->ctx, report, "/warnings", &count) != FABVDB_OK) return;
    for (size_t i = 0; i < count; ++i) {
        char pointer[64];
        const char* text = NULL;
        snprintf(pointer, sizeof pointer, "/warnings/%zu", i);
        if (fabvdb_report_string(run->ctx, report, pointer, &text) != FABVDB_OK) continue;
        clear_progress_line();
        fprintf(stderr, "fabvdb %s: warning: %s\n", run->command->name, text);
    }
}

int cli_read_input(const cli_run* run, const char* path, fabvdb_mesh** out) {
    fabvdb_mesh* mesh = NULL;
    fabvdb_status status = fabvdb_mesh_read(run->ctx, path, &mesh);
    if (status != FABVDB_OK) return cli_fail(run, status);
    const cli_value* scale = cli_get(run, "--scale");
    const cli_value* fit = cli_get(run, "--fit"); /* not both: cli_main refused that */
    double factor = 1.0;
    if (scale->set) {
        if (!(scale->number > 0)) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--scale must be positive");
        }
        factor = scale->number;
    }
    if (fit->set) {
        double lo[3], hi[3], longest = 0;
        mesh_bounds(mesh, lo, hi);
        for (int k = 0; k < 3; ++k)
            if (hi[k] - lo[k] > longest) longest = hi[k] - lo[k];
        const double target = fit->relative ? fit->number * cli_mesh_diagonal(mesh) : fit->number;
        if (!(longest > 0) || !(target > 0)) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--fit needs a positive length and a model that is not flat to a point");
        }
        factor = target / longest;
    }
    if (factor != 1.0) {
        fabvdb_mesh* scaled = NULL;
        status = fabvdb_mesh_scale(run->ctx, mesh, factor, &scaled);
        fabvdb_mesh_free(mesh);
        if (status != FABVDB_OK) return cli_fail(run, status);
        mesh = scaled;
    }
    *out = mesh;
    return CLI_EXIT_OK;
}

/* --- progress bar and Ctrl-C -------------------------------------------- */

static fabvdb_ctx* running_ctx = NULL;

static void on_interrupt(int signal_number) {
    (void)signal_number;
    if (running_ctx) fabvdb_ctx_cancel(running_ctx);
}

static int draw_progress(void* user, const char* stage, double fraction) {
    (void)user;
    const int width = 30;
    int filled = (int)(fraction * width + 0.5);
    char bar[64];
    for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
    bar[width] = 0;
    fprintf(stderr, "\r\033[K%-24.24s [%s] %3d%%", stage, bar, (int)(fraction * 100 + 0.5));
    fflush(stderr);
    progress_shown = 1;
    return 0;
}

/* --- help --------------------------------------------------------------- */

static void print_option_help(FILE* out, const cli_option* option) {
    char left[96];
    if (option->short_name)
        snprintf(left, sizeof left, "-%c, %s%s%s", option->short_name, option->name, option->value_name ? " " : "",
                 option->value_name ? option->value_name : "");
    else
        snprintf(left, sizeof left, "    %s%s%s", option->name, option->value_name ? " " : "",
                 option->value_name ? option->value_name : "");
    fprintf(out, "  %-28s %s", left, option->help);
    if (option->default_text) fprintf(out, " [default: %s]", option->default_text);
    fputc('\n', out);
}

void cli_print_command_help(const cli_command* command) {
    printf("Usage: fabvdb %s %s\n\n%s\n", command->name, command->usage, command->summary);
    if (command->description && *command->description) printf("\n%s\n", command->description);
    printf("\nOptions:\n");
    for (size_t i = 0; i < command->option_count; ++i) print_option_help(stdout, &command->options[i]);
    printf("\nCommon options:\n");
    for (size_t i = 0; i < cli_common_option_count; ++i) print_option_help(stdout, &cli_common_options[i]);
    printf("\nExit codes:\n");
    for (size_t i = 0; i < cli_exit_doc_count; ++i) printf("  %-4d %s\n", cli_exit_docs[i].code, cli_exit_docs[i].meaning);
}

/* --- parsing and running ------------------------------------------------ */

static int set_value(cli_run* run, int index, const char* text, int given) {
    const cli_option* option = option_at(run->command, (size_t)index);
    cli_value* value = &run->values[index];
    if (option->type == CLI_FLAG) {
        value->set = value->given = 1;
        value->number = 1;
        return 0;
    }
    if (cli_parse_value(option->type, text, &value->number, &value->relative) != 0)
        return cli_usage_error(run, "%s takes %s, not '%s'", option->name, cli_type_hint(option->type), text);
    value->text = text;
    value->set = 1;
    value->given = given;
    return 0;
}

const char* const cli_alternatives[][2] = {{"--voxel", "--resolution"}, {"--scale", "--fit"}, {"--up", "--orientation"}};
const size_t cli_alternative_count = sizeof(cli_alternatives) / sizeof(cli_alternatives[0]);

/* The rule of cli_alternatives. Returns 0, or the usage error after printing it. */
static int check_alternatives(const cli_run* run) {
    for (size_t i = 0; i < cli_alternative_count; ++i) {
        const char* a = cli_alternatives[i][0], *b = cli_alternatives[i][1];
        if (find_option(run->command, a, strlen(a), 0) < 0 || find_option(run->command, b, strlen(b), 0) < 0) continue;
        if (cli_get(run, a)->given && cli_get(run, b)->given)
            return cli_usage_error(run, "give %s or %s, not both", a, b);
    }
    return 0;
}

/* Every file or directory a run writes (-o, --report, --heatmap, --save-job)
 * must go into an existing, writable directory. Checked before any work, so
 * that a typo in one path does not fail the run after another output was
 * written. Returns 0, or the exit code after printing the path and why. */
static int check_output_directories(const cli_run* run) {
    static const char* const outputs[] = {"--output", "--report", "--heatmap", "--save-job"};
    for (size_t i = 0; i < sizeof outputs / sizeof outputs[0]; ++i) {
        if (find_option(run->command, outputs[i], strlen(outputs[i]), 0) < 0) continue;
        const cli_value* value = cli_get(run, outputs[i]);
        if (!value->set) continue;
        char directory[4096];
        const char* slash = strrchr(value->text, '/');
        size_t length = slash ? (size_t)(slash - value->text) : 1;
        if (length == 0) length = 1; /* a file in / */
        if (length >= sizeof directory) length = sizeof directory - 1;
        memcpy(directory, slash ? value->text : ".", length);
        directory[length] = 0;
        struct stat info;
        const char* problem = NULL;
        if (stat(directory, &info) != 0) problem = "does not exist";
        else if (!S_ISDIR(info.st_mode)) problem = "is not a directory";
        else if (access(directory, W_OK | X_OK) != 0) problem = "is not writable";
        if (problem) {
            status_print(run->command->name, FABVDB_ERR_IO, "%s %s: directory %s %s", outputs[i], value->text,
                         directory, problem);
            return cli_exit_code(FABVDB_ERR_IO);
        }
    }
    return 0;
}

int cli_main(const cli_command* command, int argc, char** argv) {
    cli_run run;
    memset(&run, 0, sizeof run);
    run.command = command;
    if (option_total(command) > CLI_MAX_OPTIONS) {
        fprintf(stderr, "fabvdb: internal error: too many options in '%s'\n", command->name);
        return CLI_EXIT_INTERNAL;
    }
    for (size_t i = 0; i < option_total(command); ++i)
        if (option_at(command, i)->default_text && set_value(&run, (int)i, option_at(command, i)->default_text, 0))
            return CLI_EXIT_INTERNAL;

    int only_positional = 0;
    for (int a = 1; a < argc; ++a) {
        const char* arg = argv[a];
        if (!only_positional && strcmp(arg, "--") == 0) {
            only_positional = 1;
            continue;
        }
        if (!only_positional && arg[0] == '-' && arg[1] != 0 && !isdigit((unsigned char)arg[1])) {
            const char* inline_value = NULL;
            int index;
            if (arg[1] == '-') {
                const char* equals = strchr(arg, '=');
                size_t length = equals ? (size_t)(equals - arg) : strlen(arg);
                index = find_option(command, arg, length, 0);
                if (equals) inline_value = equals + 1;
            } else {
                index = arg[2] == 0 ? find_option(command, NULL, 0, arg[1]) : -1;
            }
            if (index < 0) return cli_usage_error(&run, "unknown option '%s'", arg);
            const cli_option* option = option_at(command, (size_t)index);
            if (option->type == CLI_FLAG) {
                if (inline_value) return cli_usage_error(&run, "%s takes no value", option->name);
                set_value(&run, index, NULL, 1);
                continue;
            }
            if (!inline_value) {
                if (a + 1 >= argc) return cli_usage_error(&run, "%s needs a value (%s)", option->name,
                                                          option->value_name ? option->value_name : "VALUE");
                inline_value = argv[++a];
            }
            if (set_value(&run, index, inline_value, 1)) return CLI_EXIT_USAGE;
            continue;
        }
        if (run.positional_count >= CLI_MAX_POSITIONAL || run.positional_count >= command->positional_max)
            return cli_usage_error(&run, "unexpected argument '%s'", arg);
        run.positional[run.positional_count++] = arg;
    }
    if (cli_get(&run, "--help")->given) {
        cli_print_command_help(command);
        return CLI_EXIT_OK;
    }
    if (run.positional_count < command->positional_min)
        return cli_usage_error(&run, "missing %s (usage: fabvdb %s %s)",
                               run.positional_count == 0 ? "input file" : "argument", command->name, command->usage);
    run.quiet = cli_get(&run, "--quiet")->given;
    if (check_alternatives(&run)) return CLI_EXIT_USAGE;
    int output_problem = check_output_directories(&run);
    if (output_problem) return output_problem;
    const cli_value* save_job = cli_get(&run, "--save-job");
    if (save_job->set) {
        if (cli_write_job(save_job->text, command->name, argc, argv) != 0) {
            status_print(command->name, FABVDB_ERR_IO, "%s: cannot write the job file", save_job->text);
            return cli_exit_code(FABVDB_ERR_IO);
        }
        cli_note(&run, "wrote %s", save_job->text);
    }

    fabvdb_status status = fabvdb_ctx_new(&run.ctx);
    if (status != FABVDB_OK) {
        fprintf(stderr, "fabvdb %s: %s\n", command->name, fabvdb_status_string(status));
        return cli_exit_code(status);
    }
    const cli_value* threads = cli_get(&run, "--threads");
    if (threads->number < 0) {
        fabvdb_ctx_free(run.ctx);
        return cli_usage_error(&run, "--threads must be 0 or more");
    }
    fabvdb_ctx_set_threads(run.ctx, (int)threads->number);
    const cli_value* memory = cli_get(&run, "--max-memory");
    if (memory->set) {
        if (memory->number < 1) {
            fabvdb_ctx_free(run.ctx);
            return cli_usage_error(&run, "--max-memory must be positive");
        }
        fabvdb_ctx_set_memory_budget(run.ctx, (uint64_t)memory->number);
    }
    if (!run.quiet && isatty(STDERR_FILENO)) fabvdb_ctx_set_progress(run.ctx, draw_progress, NULL);

    running_ctx = run.ctx;
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);

    int code = command->run(&run);

    clear_progress_line();
    running_ctx = NULL;
    fabvdb_ctx_free(run.ctx);
    return code;
}

int cli_write_job(const char* path, const char* command_name, int argc, char** argv) {
    atomic_file file;
    if (atomic_file_open(&file, path) != 0) return -1;
    FILE* out = file.out;
    char directory[4096];
    if (!getcwd(directory, sizeof directory)) directory[0] = 0;
    fprintf(out, "fabvdb-job %d\n# written by fabvdb %s; replay with: fabvdb batch %s\ndirectory ",
            JOB_FORMAT_VERSION, fabvdb_version_string(), path);
    job_write_token(out, directory);
    fputc('\n', out);
    fputs(command_name, out);
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--save-job") == 0) {
            ++i;
            continue;
        }
        if (strncmp(argv[i], "--save-job=", 11) == 0) continue;
        fputc(' ', out);
        job_write_token(out, argv[i]);
    }
    fputc('\n', out);
    return atomic_file_commit(&file);
}
