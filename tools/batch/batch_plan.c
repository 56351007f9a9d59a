/* batch_plan.c — reading a job file or a recipe into tasks, and writing the
 * plan (batch_plan.h). */
#define _DEFAULT_SOURCE /* POSIX: realpath, glob with GLOB_BRACE, strdup */
#include "batch_plan.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <glob.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "batch_files.h"
#include "cli/commands.h"
#include "common/atomic_file.h"
#include "common/status_text.h"

/* A line of the job file as read, before placeholders. */
typedef struct source_line {
    job_line line;
    int number;
    char* directory;
    int task_start; /* a 'task' line: tokens[1] the name, [2] input, [3] out */
} source_line;

typedef struct reader {
    source_line* lines;
    int count, capacity;
    int uses_input; /* a placeholder of an input ({input}, {name}, {stem}, {out}) occurs */
    int uses_out;
    int has_tasks;
} reader;

/* A defect of the job or its inputs: "<status>: <message>" into error
 * (tools/common/status_text.h); returns the status's exit code. */
static int failf(char* error, size_t size, fabvdb_status status, const char* format, ...) {
    va_list args;
    va_start(args, format);
    status_vtext(error, size, status, format, args);
    va_end(args);
    return cli_exit_code(status);
}

/* A usage error (the options, not the job): the message alone; returns 1. */
static int usage(char* error, size_t size, const char* format, ...) {
    va_list args;
    va_start(args, format);
    vsnprintf(error, size, format, args);
    va_end(args);
    return CLI_EXIT_USAGE;
}

/* Checks the placeholders of one token; sets which kinds occur. */
static const char* scan_placeholders(const char* token, reader* r) {
    for (const char* p = token; *p; ++p) {
        if (*p == '}') {
            if (p[1] != '}') return "a '}' without its '{' (write }} for a brace)";
            ++p;
            continue;
        }
        if (*p != '{') continue;
        if (p[1] == '{') {
            ++p;
            continue;
        }
        const char* close = strchr(p, '}');
        if (!close) return "a '{' is not closed (write {{ for a brace)";
        const size_t length = (size_t)(close - p - 1);
        if (length == 3 && strncmp(p + 1, "out", 3) == 0) r->uses_out = r->uses_input = 1;
        else if ((length == 5 && strncmp(p + 1, "input", 5) == 0) || (length == 4 && strncmp(p + 1, "stem", 4) == 0) ||
                 (length == 4 && strncmp(p + 1, "name", 4) == 0))
            r->uses_input = 1;
        else if (!(length == 4 && strncmp(p + 1, "prev", 4) == 0))
            return "an unknown placeholder (known: {input} {name} {stem} {out} {prev})";
        p = close;
    }
    return NULL;
}

static int read_source(const char* path, reader* r, char* error, size_t error_size) {
    FILE* in = fopen(path, "r");
    if (!in) return failf(error, error_size, FABVDB_ERR_IO, "%s: cannot open the job file", path);
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) {
        fclose(in);
        return failf(error, error_size, FABVDB_ERR_IO, "cannot read the current directory");
    }
    char* directory = strdup(cwd);
    static char text[65536];
    int number = 0, header_seen = 0, code = 0, source_number = 0;
    while (!code && fgets(text, sizeof text, in)) {
        ++number;
        if (!strchr(text, '\n') && !feof(in)) {
            code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: line too long", path, number);
            break;
        }
        job_line line;
        const char* defect = NULL;
        if (job_tokenize(text, &line, &defect) != 0) {
            code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: %s", path, number, defect);
            break;
        }
        if (line.count == 0) continue;
        if (!header_seen) {
            const int version = line.count == 2 && strcmp(line.tokens[0], "fabvdb-job") == 0 ? atoi(line.tokens[1]) : 0;
            job_line_free(&line);
            if (version < 1 || version > JOB_FORMAT_VERSION) {
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT,
                             "%s:%d: not a fabvdb job file of a version this fabvdb reads (the first line "
                             "must be 'fabvdb-job %d')",
                             path, number, JOB_FORMAT_VERSION);
                break;
            }
            header_seen = 1;
            continue;
        }
        const char* keyword = line.tokens[0];
        if (strcmp(keyword, "directory") == 0) {
            struct stat info;
            char* next = line.count == 2 ? batch_files_absolute(directory, line.tokens[1]) : NULL;
            if (!next || stat(next, &info) != 0 || !S_ISDIR(info.st_mode)) {
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: cannot enter the directory '%s'", path, number,
                             line.count > 1 ? line.tokens[1] : "");
                free(next);
            } else {
                free(directory);
                directory = next;
            }
            job_line_free(&line);
            continue;
        }
        if (strcmp(keyword, "line") == 0) {
            /* In a plan: the next command line is line N of the job it came from. */
            source_number = line.count == 2 ? atoi(line.tokens[1]) : 0;
            if (source_number < 1)
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: 'line' takes a line number", path, number);
            job_line_free(&line);
            continue;
        }
        const int task_start = strcmp(keyword, "task") == 0;
        if (task_start) {
            if (line.count < 2 || line.count > 4) {
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: 'task' takes a name (then optionally the input "
                             "and the output folder)", path, number);
                job_line_free(&line);
                continue;
            }
            r->has_tasks = 1;
        } else {
            const cli_command* command = command_named(keyword);
            if (!command || command == &cmd_batch) {
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: no command '%s'", path, number, keyword);
                job_line_free(&line);
                continue;
            }
            for (int t = 1; t < line.count && !code; ++t) {
                const char* problem = scan_placeholders(line.tokens[t], r);
                if (problem) code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: '%s': %s", path, number,
                                          line.tokens[t], problem);
            }
            batch_line_files files;
            const char* problem = NULL;
            if (!code && batch_line_files_of(&line, 0, &files, &problem) != 0)
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: %s: %s (see 'fabvdb help %s')", path, number,
                             keyword, problem, keyword);
            if (code) {
                job_line_free(&line);
                continue;
            }
        }
        if (r->count == r->capacity) {
            r->capacity = r->capacity ? 2 * r->capacity : 16;
            r->lines = realloc(r->lines, (size_t)r->capacity * sizeof *r->lines);
            if (!r->lines) {
                code = failf(error, error_size, FABVDB_ERR_INTERNAL, "out of memory");
                break;
            }
        }
        r->lines[r->count++] = (source_line){line, source_number && !task_start ? source_number : number,
                                             strdup(directory), task_start};
        if (!task_start) source_number = 0;
    }
    if (!code && ferror(in)) code = failf(error, error_size, FABVDB_ERR_IO, "%s: cannot read the job file", path);
    fclose(in);
    free(directory);
    if (!code && !header_seen) code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s: empty job file", path);
    return code;
}

static void free_source(reader* r) {
    for (int i = 0; i < r->count; ++i) {
        job_line_free(&r->lines[i].line);
        free(r->lines[i].directory);
    }
    free(r->lines);
}

/* The task name of an input: its stem with every other character than
 * letters, digits and . _ - + made '_'. */
static char* task_name_of(const char* path) {
    const char* base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char* dot = strrchr(base, '.');
    size_t length = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    char* name = malloc(length + 1);
    if (!name) return NULL;
    for (size_t i = 0; i < length; ++i) {
        const unsigned char c = (unsigned char)base[i];
        name[i] = isalnum(c) || c == '.' || c == '_' || c == '-' || c == '+' ? (char)c : '_';
    }
    name[length] = 0;
    return name;
}

static int is_mesh_name(const char* name) {
    static const char* const extensions[] = {".stl", ".obj", ".ply", ".off", ".3mf"};
    const char* dot = strrchr(name, '.');
    for (size_t i = 0; dot && i < sizeof extensions / sizeof extensions[0]; ++i)
        if (strcasecmp(dot, extensions[i]) == 0) return 1;
    return 0;
}

/* The input files of --inputs, absolute and sorted. */
static int list_inputs(const char* pattern, char*** out, int* count, char* error, size_t error_size) {
    struct stat info;
    char** names = NULL;
    size_t n = 0;
    if (stat(pattern, &info) == 0 && S_ISDIR(info.st_mode)) {
        DIR* folder = opendir(pattern);
        if (!folder) return failf(error, error_size, FABVDB_ERR_IO, "--inputs %s: cannot list the folder", pattern);
        struct dirent* entry;
        while ((entry = readdir(folder))) {
            if (entry->d_name[0] == '.' || !is_mesh_name(entry->d_name)) continue;
            char* path = batch_files_absolute(pattern, entry->d_name);
            if (path && stat(path, &info) == 0 && S_ISREG(info.st_mode)) {
                names = realloc(names, (n + 1) * sizeof *names);
                names[n++] = path;
            } else {
                free(path);
            }
        }
        closedir(folder);
    } else {
        glob_t found;
        if (glob(pattern, GLOB_BRACE | GLOB_TILDE, NULL, &found) == 0) {
            for (size_t i = 0; i < found.gl_pathc; ++i) {
                /* Whatever the pattern names but folders: a file, or a pipe a part arrives through. */
                if (stat(found.gl_pathv[i], &info) != 0 || S_ISDIR(info.st_mode)) continue;
                names = realloc(names, (n + 1) * sizeof *names);
                names[n++] = strdup(found.gl_pathv[i]);
            }
        }
        globfree(&found);
    }
    if (n == 0) {
        free(names);
        return failf(error, error_size, FABVDB_ERR_BAD_INPUT, "--inputs '%s': no input file matches", pattern);
    }
    for (size_t i = 0; i < n; ++i) {
        char* absolute = realpath(names[i], NULL);
        if (absolute) {
            free(names[i]);
            names[i] = absolute;
        }
    }
    batch_files_sort(names, n);
    *out = names;
    *count = (int)n;
    return 0;
}

typedef struct expansion {
    const char* input, *stem, *name, *out, *prev;
} expansion;

/* Replaces the placeholders of `token`; NULL with *problem on a defect. */
static char* expand(const char* token, const expansion* x, const char** problem) {
    size_t capacity = strlen(token) + 1;
    for (const char* p = token; *p; ++p)
        if (*p == '{') capacity += 4096;
    char* out = malloc(capacity);
    if (!out) {
        *problem = "out of memory";
        return NULL;
    }
    size_t n = 0;
    for (const char* p = token; *p; ++p) {
        if ((*p == '{' && p[1] == '{') || (*p == '}' && p[1] == '}')) {
            out[n++] = *p++;
            continue;
        }
        if (*p != '{') {
            out[n++] = *p;
            continue;
        }
        const char* close = strchr(p, '}');
        const size_t length = (size_t)(close - p - 1);
        const char* value = NULL;
        if (length == 5 && strncmp(p + 1, "input", 5) == 0) value = x->input;
        else if (length == 4 && strncmp(p + 1, "stem", 4) == 0) value = x->stem;
        else if (length == 4 && strncmp(p + 1, "name", 4) == 0) value = x->name;
        else if (length == 3 && strncmp(p + 1, "out", 3) == 0) value = x->out;
        else if (length == 4 && strncmp(p + 1, "prev", 4) == 0) value = x->prev;
        if (!value) {
            *problem = length == 4 && strncmp(p + 1, "prev", 4) == 0
                           ? "{prev} needs a line above with an --output"
                           : "a placeholder of an input in a job without inputs";
            free(out);
            return NULL;
        }
        const size_t value_length = strlen(value);
        if (n + value_length + 1 > capacity) {
            free(out);
            *problem = "a placeholder's value is too long";
            return NULL;
        }
        memcpy(out + n, value, value_length);
        n += value_length;
        p = close;
    }
    out[n] = 0;
    return out;
}

static batch_task* add_task(batch_plan* plan, const char* name, const char* input, const char* out) {
    batch_task* grown = realloc(plan->tasks, (size_t)(plan->task_count + 1) * sizeof *grown);
    if (!grown) return NULL;
    plan->tasks = grown;
    batch_task* task = &plan->tasks[plan->task_count++];
    memset(task, 0, sizeof *task);
    task->name = strdup(name);
    task->input = input && *input ? strdup(input) : NULL;
    task->out = out && *out ? strdup(out) : NULL;
    return task;
}

/* Appends source line `s` to `task`, expanded. */
static int add_line(batch_task* task, const source_line* s, const expansion* x, const char* job_path, char* error,
                    size_t error_size) {
    batch_plan_line* grown = realloc(task->lines, (size_t)(task->line_count + 1) * sizeof *grown);
    if (!grown) return failf(error, error_size, FABVDB_ERR_INTERNAL, "out of memory");
    task->lines = grown;
    batch_plan_line* line = &task->lines[task->line_count];
    memset(line, 0, sizeof *line);
    line->source_line = s->number;
    line->directory = strdup(s->directory);
    for (int t = 0; t < s->line.count; ++t) {
        const char* problem = NULL;
        char* token = t == 0 ? strdup(s->line.tokens[0]) : expand(s->line.tokens[t], x, &problem);
        if (!token) {
            job_line_free(&line->line);
            free(line->directory);
            return failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: '%s': %s", job_path, s->number, s->line.tokens[t],
                         problem ? problem : "out of memory");
        }
        line->line.tokens[line->line.count++] = token;
    }
    ++task->line_count;
    return 0;
}

/* The --output of a line (placeholders replaced), made absolute, or NULL. */
static char* output_of(const batch_plan_line* line) {
    batch_line_files files;
    const char* problem;
    if (batch_line_files_of(&line->line, 0, &files, &problem) != 0 || !files.output) return NULL;
    return batch_files_absolute(line->directory, files.output);
}

static char* job_stem(const char* job_path) { return task_name_of(job_path); }

int batch_plan_read(const char* job_path, const char* inputs, const char* out, batch_plan* plan, char* error,
                    size_t error_size) {
    memset(plan, 0, sizeof *plan);
    reader r;
    memset(&r, 0, sizeof r);
    int code = read_source(job_path, &r, error, error_size);
    if (!code && r.uses_input && r.has_tasks)
        code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s: a recipe (with placeholders of an input) has no 'task' lines",
                     job_path);
    if (!code && r.uses_input && !inputs)
        code = usage(error, error_size, "%s is a recipe (its lines use placeholders of an input): give --inputs",
                     job_path);
    if (!code && !r.uses_input && inputs)
        code = usage(error, error_size, "--inputs needs a recipe: %s uses no {input}, {name}, {stem} or {out}",
                     job_path);
    if (!code && r.uses_out && !out)
        code = usage(error, error_size, "the recipe %s uses {out}: give --out FOLDER", job_path);
    char** names = NULL;
    int name_count = 0;
    char* out_root = NULL;
    if (!code && r.uses_input) code = list_inputs(inputs, &names, &name_count, error, error_size);
    if (!code && r.uses_input && out) {
        if (mkdir(out, 0777) != 0 && errno != EEXIST)
            code = failf(error, error_size, FABVDB_ERR_IO, "--out %s: cannot create the folder", out);
        else if (!(out_root = realpath(out, NULL)))
            code = failf(error, error_size, FABVDB_ERR_IO, "--out %s: not a folder", out);
    }
    plan->recipe = r.uses_input;
    const int task_total = r.uses_input ? name_count : 1;
    for (int k = 0; !code && k < task_total; ++k) {
        batch_task* task = NULL;
        expansion x = {0};
        char* stem = NULL, *task_out = NULL;
        if (r.uses_input) {
            stem = task_name_of(names[k]);
            if (stem && batch_plan_find(plan, stem) >= 0) {
                code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "--inputs: %s and %s both make the task '%s' (the same stem)",
                             plan->tasks[batch_plan_find(plan, stem)].input, names[k], stem);
            } else if (stem) {
                task_out = out_root ? batch_files_absolute(out_root, stem) : NULL;
                const char* base = strrchr(names[k], '/');
                const char* raw_stem_end = strrchr(base + 1, '.');
                char raw_stem[4096];
                snprintf(raw_stem, sizeof raw_stem, "%.*s", raw_stem_end && raw_stem_end != base + 1
                                                                ? (int)(raw_stem_end - base - 1)
                                                                : (int)strlen(base + 1), base + 1);
                x.input = names[k];
                x.name = base + 1;
                x.stem = raw_stem;
                x.out = task_out;
                task = add_task(plan, stem, names[k], task_out);
                for (int i = 0; task && !code && i < r.count; ++i) {
                    char* previous = task->line_count ? output_of(&task->lines[task->line_count - 1]) : NULL;
                    x.prev = previous;
                    code = add_line(task, &r.lines[i], &x, job_path, error, error_size);
                    free(previous);
                }
            }
            free(stem);
            free(task_out);
            if (!code && !task) code = failf(error, error_size, FABVDB_ERR_INTERNAL, "out of memory");
            continue;
        }
        for (int i = 0; !code && i < r.count; ++i) {
            const source_line* s = &r.lines[i];
            if (s->task_start) {
                if (batch_plan_find(plan, s->line.tokens[1]) >= 0) {
                    code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: a second task called '%s'", job_path,
                                 s->number, s->line.tokens[1]);
                    break;
                }
                char* name = task_name_of(s->line.tokens[1]);
                if (!name || strcmp(name, s->line.tokens[1]) != 0) {
                    code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: a task name takes letters, digits and . _ - + "
                                 "only, not '%s'", job_path, s->number, s->line.tokens[1]);
                    free(name);
                    break;
                }
                free(name);
                task = add_task(plan, s->line.tokens[1], s->line.count > 2 ? s->line.tokens[2] : NULL,
                                s->line.count > 3 ? s->line.tokens[3] : NULL);
                if (!task) code = failf(error, error_size, FABVDB_ERR_INTERNAL, "out of memory");
                continue;
            }
            if (!task) {
                if (r.has_tasks) {
                    code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s:%d: a command line before the first 'task' line",
                                 job_path, s->number);
                    break;
                }
                char* name = job_stem(job_path);
                task = add_task(plan, name ? name : "job", NULL, NULL);
                free(name);
            }
            char* previous = task->line_count ? output_of(&task->lines[task->line_count - 1]) : NULL;
            x.prev = previous;
            code = add_line(task, s, &x, job_path, error, error_size);
            free(previous);
        }
    }
    for (int k = 0; !code && k < plan->task_count; ++k)
        if (plan->tasks[k].line_count == 0)
            code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s: the task '%s' has no command line", job_path,
                         plan->tasks[k].name);
    if (!code && plan->task_count == 0) code = failf(error, error_size, FABVDB_ERR_BAD_INPUT, "%s: no command line", job_path);
    for (int k = 0; k < name_count; ++k) free(names[k]);
    free(names);
    free(out_root);
    free_source(&r);
    if (code) batch_plan_free(plan);
    return code;
}

/* Writes a token with its braces doubled, so reading it back replaces none. */
static void write_literal(FILE* out, const char* token) {
    size_t length = strlen(token), extra = 0;
    for (const char* p = token; *p; ++p) extra += *p == '{' || *p == '}';
    char* doubled = malloc(length + extra + 1);
    if (!doubled) return;
    size_t n = 0;
    for (const char* p = token; *p; ++p) {
        doubled[n++] = *p;
        if (*p == '{' || *p == '}') doubled[n++] = *p;
    }
    doubled[n] = 0;
    job_write_token(out, doubled);
    free(doubled);
}

int batch_plan_write(const batch_plan* plan, const char* source, const char* path) {
    atomic_file file;
    if (atomic_file_open(&file, path) != 0) return -1;
    FILE* out = file.out;
    fprintf(out, "fabvdb-job %d\n# the %d task(s) of %s, written by fabvdb batch; an array task runs one with --task\n",
            JOB_FORMAT_VERSION, plan->task_count, source);
    const char* directory = NULL;
    for (int k = 0; k < plan->task_count; ++k) {
        const batch_task* task = &plan->tasks[k];
        fputs("task ", out);
        job_write_token(out, task->name);
        if (task->input || task->out) {
            fputc(' ', out);
            job_write_token(out, task->input ? task->input : "");
        }
        if (task->out) {
            fputc(' ', out);
            job_write_token(out, task->out);
        }
        fputc('\n', out);
        for (int i = 0; i < task->line_count; ++i) {
            const batch_plan_line* line = &task->lines[i];
            if (!directory || strcmp(directory, line->directory) != 0) {
                fputs("directory ", out);
                job_write_token(out, line->directory);
                fputc('\n', out);
                directory = line->directory;
            }
            fprintf(out, "line %d\n%s", line->source_line, line->line.tokens[0]);
            for (int t = 1; t < line->line.count; ++t) {
                fputc(' ', out);
                write_literal(out, line->line.tokens[t]);
            }
            fputc('\n', out);
        }
    }
    return atomic_file_commit(&file);
}

void batch_plan_free(batch_plan* plan) {
    for (int k = 0; k < plan->task_count; ++k) {
        batch_task* task = &plan->tasks[k];
        for (int i = 0; i < task->line_count; ++i) {
            job_line_free(&task->lines[i].line);
            free(task->lines[i].directory);
        }
        free(task->lines);
        free(task->name);
        free(task->input);
        free(task->out);
    }
    free(plan->tasks);
    memset(plan, 0, sizeof *plan);
}

int batch_plan_find(const batch_plan* plan, const char* name) {
    for (int k = 0; k < plan->task_count; ++k)
        if (strcmp(plan->tasks[k].name, name) == 0) return k;
    return -1;
}
