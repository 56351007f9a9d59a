/* batch_slurm.c — submitting a batch as a Slurm job array, waiting for it,
 * and explaining the tasks Slurm ended (batch_slurm.h). */
#define _GNU_SOURCE /* readlink, strdup, getline */
#include "batch_slurm.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "batch_record.h"
#include "cli/cli.h"
#include "common/atomic_file.h"
#include "common/spawn.h"
#include "common/status_text.h"

/* The value of "Key=value" or "Key = value" in Slurm's output, up to a space or line end. */
static int field(const char* text, const char* key, char* value, size_t size) {
    const size_t length = strlen(key);
    for (const char* p = text; (p = strstr(p, key)); p += length) {
        if (p != text && p[-1] != ' ' && p[-1] != '\n' && p[-1] != '\t') continue;
        const char* q = p + length;
        while (*q == ' ') ++q;
        if (*q != '=') continue;
        ++q;
        while (*q == ' ') ++q;
        size_t n = strcspn(q, " \n\t");
        if (n >= size) n = size - 1;
        memcpy(value, q, n);
        value[n] = 0;
        return 1;
    }
    return 0;
}

static void shell_quote(FILE* out, const char* text) {
    fputc('\'', out);
    for (const char* p = text; *p; ++p) {
        if (*p == '\'') fputs("'\\''", out);
        else fputc(*p, out);
    }
    fputc('\'', out);
}

/* Prints "cannot write" for `path` and gives the exit code. */
static int cannot_write(const char* path) {
    status_print("batch", FABVDB_ERR_IO, "%s: cannot write", path);
    return cli_exit_code(FABVDB_ERR_IO);
}

/* One submission: its array's shape and its files in STATE/slurm/. */
typedef struct submission_files {
    int chunk, array_size;  /* tasks per array index, array indices */
    char folder[4096];      /* STATE/slurm */
    char tasks[8192];       /* submit-N.tasks: line i+1 names the tasks of index i */
    char script[8192];      /* submit-N.sh: what each array task runs */
} submission_files;

/* Phase 1: asks Slurm for its configuration: the largest array it takes
 * (so the tasks are chunked to fit) and where its job-completion log is
 * (noted in STATE/slurm/jobcomp, read when a task is explained later). */
static int read_cluster(int todo_count, const char* state, submission_files* files) {
    char config[65536], value[4096];
    char* show_config[] = {"scontrol", "show", "config", NULL};
    if (spawn_capture(show_config[0], show_config, config, sizeof config) != 0) {
        status_print("batch", FABVDB_ERR_IO, "cannot reach Slurm (scontrol show config): %s", config);
        return cli_exit_code(FABVDB_ERR_IO);
    }
    const long max_array = field(config, "MaxArraySize", value, sizeof value) ? atol(value) : 1001;
    const int indices = todo_count < max_array ? todo_count : (int)max_array;
    files->chunk = (todo_count + indices - 1) / indices;
    files->array_size = (todo_count + files->chunk - 1) / files->chunk;
    snprintf(files->folder, sizeof files->folder, "%s/slurm", state);
    if (mkdir(files->folder, 0777) != 0 && errno != EEXIST) {
        status_print("batch", FABVDB_ERR_IO, "%s: cannot create the folder", files->folder);
        return cli_exit_code(FABVDB_ERR_IO);
    }
    char type[256], path[8192];
    if (field(config, "JobCompType", type, sizeof type) && strcmp(type, "jobcomp/filetxt") == 0 &&
        field(config, "JobCompLoc", value, sizeof value)) {
        snprintf(path, sizeof path, "%s/jobcomp", files->folder);
        atomic_file note;
        if (atomic_file_open(&note, path) == 0) {
            fprintf(note.out, "%s\n", value);
            atomic_file_commit(&note);
        }
    }
    return CLI_EXIT_OK;
}

/* Phase 2: writes submit-N.tasks and submit-N.sh for the next free N. */
static int write_submission(const batch_plan* plan, const int* todo, int todo_count, const batch_slurm_options* options,
                            submission_files* files) {
    for (int submission = 1;; ++submission) {
        snprintf(files->tasks, sizeof files->tasks, "%s/submit-%d.tasks", files->folder, submission);
        snprintf(files->script, sizeof files->script, "%s/submit-%d.sh", files->folder, submission);
        if (access(files->tasks, F_OK) != 0) break;
    }
    atomic_file map;
    if (atomic_file_open(&map, files->tasks) != 0) return cannot_write(files->tasks);
    for (int i = 0; i < files->array_size; ++i) {
        for (int k = i * files->chunk; k < (i + 1) * files->chunk && k < todo_count; ++k)
            fprintf(map.out, "%s%s", k == i * files->chunk ? "" : ",", plan->tasks[todo[k]].name);
        fputc('\n', map.out);
    }
    if (atomic_file_commit(&map) != 0) return cannot_write(files->tasks);
    char exe[4096], plan_path[8192];
    const ssize_t exe_length = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[exe_length > 0 ? exe_length : 0] = 0;
    snprintf(plan_path, sizeof plan_path, "%s/plan.job", options->state);
    atomic_file script;
    if (atomic_file_open(&script, files->script) != 0) return cannot_write(files->script);
    FILE* out = script.out;
    fprintf(out, "#!/bin/sh\n# written by fabvdb batch: array index i runs the tasks on line i+1 of\n# %s\n",
            files->tasks);
    fputs("tasks=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" ", out);
    shell_quote(out, files->tasks);
    fputs(")\nexec ", out);
    shell_quote(out, exe);
    fputs(" batch ", out);
    shell_quote(out, plan_path);
    fputs(" --state ", out);
    shell_quote(out, options->state);
    fputs(" --task \"$tasks\" --quiet", out);
    if (options->mem > 0) fprintf(out, " --max-memory %.0f", options->mem);
    fputc('\n', out);
    if (atomic_file_commit(&script) != 0) return cannot_write(files->script);
    chmod(files->script, 0755);
    return CLI_EXIT_OK;
}

/* Phase 3: sbatch. Returns its job id in `job`, or the exit code after
 * printing sbatch's refusal. */
static int run_sbatch(const batch_slurm_options* options, const submission_files* files, char* array,
                      size_t array_size, char* job, size_t job_size) {
    char output[8192], partition[256], time_limit[256], mem[64], job_name[64];
    if (options->max_running > 0)
        snprintf(array, array_size, "--array=0-%d%%%d", files->array_size - 1, options->max_running);
    else
        snprintf(array, array_size, "--array=0-%d", files->array_size - 1);
    snprintf(output, sizeof output, "--output=%s/%%A_%%a.out", files->folder);
    snprintf(job_name, sizeof job_name, "--job-name=fabvdb-batch");
    char* argv[16];
    int argc = 0;
    argv[argc++] = "sbatch";
    argv[argc++] = "--parsable";
    argv[argc++] = array;
    argv[argc++] = job_name;
    argv[argc++] = output;
    if (options->partition) {
        snprintf(partition, sizeof partition, "--partition=%s", options->partition);
        argv[argc++] = partition;
    }
    if (options->time) {
        snprintf(time_limit, sizeof time_limit, "--time=%s", options->time);
        argv[argc++] = time_limit;
    }
    if (options->mem > 0) {
        snprintf(mem, sizeof mem, "--mem=%.0fM", ceil(options->mem / (1024.0 * 1024.0)));
        argv[argc++] = mem;
    }
    argv[argc++] = (char*)files->script;
    argv[argc] = NULL;
    char answer[4096];
    if (spawn_capture(argv[0], argv, answer, sizeof answer) != 0) {
        answer[strcspn(answer, "\n")] = 0;
        status_print("batch", FABVDB_ERR_BAD_INPUT, "sbatch refused the job array: %s", answer);
        return cli_exit_code(FABVDB_ERR_BAD_INPUT);
    }
    snprintf(job, job_size, "%.*s", (int)strcspn(answer, ";\n"), answer);
    return CLI_EXIT_OK;
}

/* Phase 4: appends every submitted task to STATE/slurm/submissions.tsv (job,
 * array index, task), which explains a task without a record later. */
static int note_submission(const batch_plan* plan, const int* todo, int todo_count, const submission_files* files,
                           const char* job) {
    char path[8192];
    snprintf(path, sizeof path, "%s/submissions.tsv", files->folder);
    FILE* out = fopen(path, "a");
    int failed = !out;
    if (out) {
        for (int k = 0; k < todo_count; ++k)
            fprintf(out, "%s\t%d\t%s\n", job, k / files->chunk, plan->tasks[todo[k]].name);
        failed = fclose(out) != 0;
    }
    if (failed) {
        status_print("batch", FABVDB_ERR_IO, "%s: cannot note the submission of job %s", path, job);
        return cli_exit_code(FABVDB_ERR_IO);
    }
    return CLI_EXIT_OK;
}

int batch_slurm_submit(const batch_plan* plan, const int* todo, int todo_count, const batch_slurm_options* options,
                       char* job, size_t job_size) {
    job[0] = 0;
    if (todo_count == 0) {
        if (!options->quiet) fprintf(stderr, "batch: nothing to submit, every task is done\n");
        return CLI_EXIT_OK;
    }
    submission_files files;
    int code = read_cluster(todo_count, options->state, &files);
    if (!code) code = write_submission(plan, todo, todo_count, options, &files);
    if (code) return code;
    /* Records of the tasks that go out again go first, so none is read as theirs. */
    char path[8192];
    for (int k = 0; k < todo_count; ++k) {
        batch_record_path(options->state, plan->tasks[todo[k]].name, path, sizeof path);
        unlink(path);
    }
    char array[64];
    code = run_sbatch(options, &files, array, sizeof array, job, job_size);
    if (!code) code = note_submission(plan, todo, todo_count, &files, job);
    if (code) return code;
    if (!options->quiet)
        fprintf(stderr, "batch: submitted %d task(s) as Slurm job array %s (indices %s, %d task(s) per index)\n",
                todo_count, job, array + strlen("--array="), files.chunk);
    if (!options->wait && !options->quiet)
        fprintf(stderr, "batch: follow it with: fabvdb batch --status %s\n", options->state);
    return CLI_EXIT_OK;
}

int batch_slurm_wait(const char* job, const batch_slurm_options* options) {
    const double started = batch_now();
    for (;;) {
        char queue[65536];
        char* squeue[] = {"squeue", "-h", "-r", "-j", (char*)job, "-o", "%i %T", NULL};
        const int code = spawn_capture(squeue[0], squeue, queue, sizeof queue);
        if (code != 0 && !strstr(queue, "Invalid job id")) {
            status_print("batch", FABVDB_ERR_IO, "squeue failed while waiting for job %s: %s", job, queue);
            return cli_exit_code(FABVDB_ERR_IO);
        }
        int queued = 0;
        for (const char* p = queue; code == 0 && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : p + strlen(p))
            queued += *p != '\n';
        if (queued == 0) break;
        if (!options->quiet && isatty(STDERR_FILENO)) {
            fprintf(stderr, "\r\033[Kbatch: Slurm job %s: %d array task(s) queued or running, %.0f s", job, queued,
                    batch_now() - started);
            fflush(stderr);
        }
        sigset_t stop;
        sigemptyset(&stop);
        sigaddset(&stop, SIGINT);
        sigaddset(&stop, SIGTERM);
        const struct timespec second = {1, 0};
        if (sigtimedwait(&stop, NULL, &second) > 0) {
            if (isatty(STDERR_FILENO)) fputs("\r\033[K", stderr);
            fprintf(stderr, "fabvdb batch: stopped waiting; Slurm job %s goes on (fabvdb batch --status %s)\n", job,
                    options->state);
            return CLI_EXIT_CANCELLED;
        }
    }
    if (!options->quiet && isatty(STDERR_FILENO)) fputs("\r\033[K", stderr);
    return CLI_EXIT_OK;
}

/* --- explaining tasks without a record ----------------------------------- */

typedef struct submission {
    char job[32];
    int index;
    char* task;
} submission;

/* What Slurm says about the array tasks of one job: each entry covers the
 * array indices first..last (a pending remainder is one range). */
typedef struct array_state {
    int first, last;
    char state[64];
    char reason[128];
} array_state;

typedef struct job_states {
    char job[32];
    array_state* entries;
    int count;
} job_states;

struct batch_slurm_jobs {
    submission* entries;
    int count;
    char jobcomp[4096];
    job_states* known; /* one per array job asked about */
    int known_count;
};

batch_slurm_jobs* batch_slurm_jobs_read(const char* state) {
    char path[8192];
    snprintf(path, sizeof path, "%s/slurm/submissions.tsv", state);
    FILE* in = fopen(path, "r");
    if (!in) return NULL;
    batch_slurm_jobs* jobs = calloc(1, sizeof *jobs);
    char* text = NULL;
    size_t capacity = 0;
    while (jobs && getline(&text, &capacity, in) > 0) {
        char job[32], task[4096];
        int index;
        if (sscanf(text, "%31[^\t]\t%d\t%4095[^\n]", job, &index, task) != 3) continue;
        submission* grown = realloc(jobs->entries, (size_t)(jobs->count + 1) * sizeof *grown);
        if (!grown) break;
        jobs->entries = grown;
        snprintf(grown[jobs->count].job, sizeof grown[jobs->count].job, "%s", job);
        grown[jobs->count].index = index;
        grown[jobs->count].task = strdup(task);
        ++jobs->count;
    }
    free(text);
    fclose(in);
    snprintf(path, sizeof path, "%s/slurm/jobcomp", state);
    in = fopen(path, "r");
    if (in && jobs) {
        if (fgets(jobs->jobcomp, sizeof jobs->jobcomp, in)) jobs->jobcomp[strcspn(jobs->jobcomp, "\n")] = 0;
    }
    if (in) fclose(in);
    return jobs;
}

void batch_slurm_jobs_free(batch_slurm_jobs* jobs) {
    if (!jobs) return;
    for (int i = 0; i < jobs->count; ++i) free(jobs->entries[i].task);
    for (int i = 0; i < jobs->known_count; ++i) free(jobs->known[i].entries);
    free(jobs->entries);
    free(jobs->known);
    free(jobs);
}

static void add_state(job_states* states, const char* indices, const char* state, const char* reason) {
    char* end = NULL;
    const long first = strtol(indices, &end, 10);
    if (end == indices) return;
    long last = first;
    if (*end == '-') last = strtol(end + 1, NULL, 10);
    array_state* grown = realloc(states->entries, (size_t)(states->count + 1) * sizeof *grown);
    if (!grown) return;
    states->entries = grown;
    array_state* entry = &grown[states->count++];
    entry->first = (int)first;
    entry->last = (int)last;
    snprintf(entry->state, sizeof entry->state, "%s", state);
    snprintf(entry->reason, sizeof entry->reason, "%s", reason);
}

/* Asks Slurm once per array job: `scontrol show job JOB` lists each array
 * task that has started and one record for the pending rest; when Slurm has
 * forgotten the job, the job-completion log's lines for it. */
static job_states* states_of(batch_slurm_jobs* jobs, const char* job) {
    for (int i = 0; i < jobs->known_count; ++i)
        if (strcmp(jobs->known[i].job, job) == 0) return &jobs->known[i];
    job_states* grown = realloc(jobs->known, (size_t)(jobs->known_count + 1) * sizeof *grown);
    if (!grown) return NULL;
    jobs->known = grown;
    job_states* states = &grown[jobs->known_count++];
    memset(states, 0, sizeof *states);
    snprintf(states->job, sizeof states->job, "%s", job);
    static char answer[1 << 20];
    char* show_job[] = {"scontrol", "-o", "show", "job", (char*)job, NULL};
    if (spawn_capture(show_job[0], show_job, answer, sizeof answer) == 0) {
        for (char* line = strtok(answer, "\n"); line; line = strtok(NULL, "\n")) {
            char indices[64], state[64], reason[128] = "";
            if (!field(line, "ArrayTaskId", indices, sizeof indices) || !field(line, "JobState", state, sizeof state))
                continue;
            field(line, "Reason", reason, sizeof reason);
            add_state(states, indices, state, reason);
        }
    }
    if (states->count > 0 || !jobs->jobcomp[0]) return states;
    FILE* in = fopen(jobs->jobcomp, "r");
    if (!in) return states;
    char* text = NULL;
    size_t capacity = 0;
    while (getline(&text, &capacity, in) > 0) {
        char array_job[64], indices[64], state[64];
        if (field(text, "ArrayJobId", array_job, sizeof array_job) && strcmp(array_job, job) == 0 &&
            field(text, "ArrayTaskId", indices, sizeof indices) && field(text, "JobState", state, sizeof state))
            add_state(states, indices, state, "");
    }
    free(text);
    fclose(in);
    return states;
}

static int still_queued(const char* state) {
    static const char* const queued[] = {"PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "REQUEUED", "RESIZING",
                                         "SUSPENDED", "REQUEUE_HOLD", "REQUEUE_FED", "SIGNALING", "STAGE_OUT"};
    for (size_t i = 0; i < sizeof queued / sizeof queued[0]; ++i)
        if (strcmp(state, queued[i]) == 0) return 1;
    return 0;
}

int batch_slurm_reason(batch_slurm_jobs* jobs, const char* task, char* job, size_t job_size, char* reason,
                       size_t reason_size) {
    const submission* last = NULL;
    for (int i = 0; i < jobs->count; ++i)
        if (strcmp(jobs->entries[i].task, task) == 0) last = &jobs->entries[i];
    if (!last) return 0;
    snprintf(job, job_size, "%s_%d", last->job, last->index);
    const job_states* states = states_of(jobs, last->job);
    const array_state* found = NULL;
    for (int i = 0; states && i < states->count; ++i)
        if (states->entries[i].first <= last->index && last->index <= states->entries[i].last)
            found = &states->entries[i];
    if (!found) {
        snprintf(reason, reason_size, "Slurm job %s: no record, and Slurm no longer knows the job", job);
        return 1;
    }
    if (still_queued(found->state)) {
        snprintf(reason, reason_size, "Slurm job %s %s", job, found->state);
        return 2;
    }
    if (found->reason[0] && strcmp(found->reason, "None") != 0)
        snprintf(reason, reason_size, "Slurm job %s %s (reason %s), no record", job, found->state, found->reason);
    else
        snprintf(reason, reason_size, "Slurm job %s %s, no record", job, found->state);
    return 1;
}

int batch_slurm_exit_code(const char* reason) {
    if (strstr(reason, " TIMEOUT") || strstr(reason, " OUT_OF_MEMORY") || strstr(reason, " DEADLINE"))
        return CLI_EXIT_BUDGET;
    if (strstr(reason, " CANCELLED")) return CLI_EXIT_CANCELLED;
    return CLI_EXIT_INTERNAL;
}
