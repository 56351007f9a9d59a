/* cmd_batch.c — `fabvdb batch`: runs a job file's tasks (tools/batch_plan.h:
 * explicit command lines, or a recipe applied to many inputs) on this machine
 * several at once under the memory budget (batch_local.h), or on a Slurm
 * cluster as one job array (batch_slurm.h); each task leaves an atomic record
 * in the state folder (batch_record.h), from which --resume, --status and
 * --report work (batch_summary.h). Docs: docs/batch.md. */
#define _GNU_SOURCE /* sched_getaffinity, realpath */
#include <ctype.h>
#include <errno.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "batch_local.h"
#include "batch_plan.h"
#include "batch_record.h"
#include "batch_slurm.h"
#include "batch_summary.h"
#include "cli/commands.h"
#include "common/job.h"
#include "common/status_text.h"

static const cli_option options[] = {
    {"--inputs", 'i', CLI_STRING, "PATTERN", NULL,
     "apply the recipe JOB to every file matching PATTERN ('orders/*.stl', braces allowed) or in a folder"},
    {"--out", 0, CLI_STRING, "FOLDER", NULL, "the recipe's output folder: task STEM writes into FOLDER/STEM ({out})"},
    {"--jobs", 'j', CLI_INT, "N", "0", "tasks at once on this machine; 0: one per core, as the memory budget admits"},
    {"--state", 0, CLI_STRING, "DIR", NULL, "the state folder of records and logs [default: JOB's folder/STEM.state]"},
    {"--resume", 0, CLI_FLAG, NULL, NULL,
     "skip the tasks whose record says done and whose inputs and outputs are unchanged (SHA-256)"},
    {"--keep-going", 'k', CLI_FLAG, NULL, NULL, "run a task's remaining lines after one fails"},
    {"--dry-run", 'n', CLI_FLAG, NULL, NULL, "check the job file and print the tasks' commands without running them"},
    {"--status", 0, CLI_STRING, "STATE", NULL,
     "print what the state folder says (done / failed with why / pending) and write STATE/status.json"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL,
     "write the batch summary: per task input, status, exit code, message, wall time, peak memory, key figures"},
    {"--slurm", 0, CLI_FLAG, NULL, NULL, "submit the tasks to Slurm as one job array instead of running them here"},
    {"--partition", 0, CLI_STRING, "P", NULL, "the Slurm partition (with --slurm)"},
    {"--max-running", 0, CLI_INT, "K", "0", "at most K array tasks at once (with --slurm; 0: as Slurm allows)"},
    {"--time", 0, CLI_STRING, "T", NULL, "Slurm's time limit per array task: minutes, MM:SS, HH:MM:SS or D-HH"},
    {"--mem", 0, CLI_SIZE, "SIZE", NULL, "Slurm's memory per array task, e.g. 4G; also each task's --max-memory"},
    {"--wait", 0, CLI_FLAG, NULL, NULL, "with --slurm: wait for the array (polling squeue) and print the status"},
    {"--task", 0, CLI_STRING, "NAMES", NULL,
     "run only these tasks (names or indices, comma-separated) of the plan JOB: what each Slurm array task runs"},
};

static int available_cores(void) {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    return online > 0 ? (int)online : 1;
}

static int make_folder(const char* path) {
    if (mkdir(path, 0777) == 0 || errno == EEXIST) return 0;
    status_print("batch", FABVDB_ERR_IO, "%s: cannot create the folder: %s", path, strerror(errno));
    return -1;
}

/* The state folder, absolute: --state, or STEM.state beside the job file. */
static int state_folder(const cli_run* run, const char* job, char* state, size_t size) {
    const cli_value* given = cli_get(run, "--state");
    char wanted[8192];
    if (given->set) {
        snprintf(wanted, sizeof wanted, "%s", given->text);
    } else {
        const char* slash = strrchr(job, '/');
        const char* base = slash ? slash + 1 : job;
        const char* dot = strrchr(base, '.');
        const int stem = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
        snprintf(wanted, sizeof wanted, "%.*s%.*s.state", slash ? (int)(slash - job + 1) : 0, job, stem, base);
    }
    if (make_folder(wanted) != 0) return -1;
    char* absolute = realpath(wanted, NULL);
    if (!absolute) {
        status_print("batch", FABVDB_ERR_IO, "%s: not a folder", wanted);
        return -1;
    }
    snprintf(state, size, "%s", absolute);
    free(absolute);
    char sub[8192 + 16];
    snprintf(sub, sizeof sub, "%s/tasks", state);
    if (make_folder(sub) != 0) return -1;
    snprintf(sub, sizeof sub, "%s/logs", state);
    return make_folder(sub);
}

/* The tasks named by --task (names or indices). Returns their count, or -1. */
static int named_tasks(const batch_plan* plan, const char* names, int* todo) {
    int count = 0;
    char* copy = strdup(names);
    for (char* name = strtok(copy, ", \t\n"); name; name = strtok(NULL, ", \t\n")) {
        int index = batch_plan_find(plan, name);
        if (index < 0) {
            char* end = NULL;
            const long number = strtol(name, &end, 10);
            if (*end == 0 && number >= 0 && number < plan->task_count) index = (int)number;
        }
        if (index < 0) {
            status_print("batch", FABVDB_ERR_BAD_INPUT, "the plan has no task '%s'", name);
            free(copy);
            return -1;
        }
        todo[count++] = index;
    }
    free(copy);
    return count;
}

static void print_dry_run(const batch_plan* plan) {
    for (int k = 0; k < plan->task_count; ++k) {
        const batch_task* task = &plan->tasks[k];
        if (plan->task_count > 1) printf("# task %s\n", task->name);
        for (int i = 0; i < task->line_count; ++i) {
            fputs("fabvdb", stdout);
            for (int t = 0; t < task->lines[i].line.count; ++t) {
                const char* token = task->lines[i].line.tokens[t];
                int bare = *token != 0;
                for (const char* p = token; *p; ++p) bare &= !isspace((unsigned char)*p) && *p != '"' && *p != '#';
                putchar(' ');
                if (bare) fputs(token, stdout);
                else job_write_token(stdout, token);
            }
            putchar('\n');
        }
    }
}

/* Submits the tasks; with --wait, waits for the array and prints the
 * status. Returns 0, the first failed task's exit code, or the error's. */
static int submit_to_slurm(const cli_run* run, const batch_plan* plan, const int* todo, int todo_count,
                           const batch_slurm_options* options) {
    char job[64];
    int code = batch_slurm_submit(plan, todo, todo_count, options, job, sizeof job);
    if (code || !job[0] || !options->wait) return code;
    code = batch_slurm_wait(job, options);
    if (code) return code;
    batch_counts counts;
    code = batch_summary(options->state, !run->quiet, NULL, &counts);
    return code ? code : counts.first_failure;
}

/* The usage errors of a run with a job file. Returns 0, or 1 after printing one. */
static int check_options(const cli_run* run) {
    const int slurm = cli_get(run, "--slurm")->given;
    if (run->positional_count == 0)
        return cli_usage_error(run, "missing the job file (usage: fabvdb batch %s)", run->command->usage);
    if (cli_get(run, "--jobs")->number < 0) return cli_usage_error(run, "--jobs must be 0 or more");
    if (cli_get(run, "--max-running")->number < 0) return cli_usage_error(run, "--max-running must be 0 or more");
    if (cli_get(run, "--task")->set && slurm) return cli_usage_error(run, "--task runs tasks here: not with --slurm");
    if (!slurm && (cli_get(run, "--wait")->given || cli_get(run, "--partition")->set || cli_get(run, "--time")->set ||
                   cli_get(run, "--mem")->set || cli_get(run, "--max-running")->given))
        return cli_usage_error(run, "--wait, --partition, --time, --mem and --max-running go with --slurm");
    if (cli_get(run, "--out")->set && !cli_get(run, "--inputs")->set)
        return cli_usage_error(run, "--out is the output folder of a recipe: give --inputs");
    return 0;
}

/* The tasks of the plan to run into todo (plan order), their count
 * returned: all of them, or with --resume those without a current record
 * (and, for Slurm, not still in its queue); *skipped counts the others. */
static int tasks_to_run(const cli_run* run, const batch_plan* plan, const char* state, int slurm, int* todo,
                        int* skipped) {
    const int resume = cli_get(run, "--resume")->given;
    batch_slurm_jobs* submitted = slurm && resume ? batch_slurm_jobs_read(state) : NULL;
    int count = 0;
    *skipped = 0;
    for (int k = 0; k < plan->task_count; ++k) {
        if (resume) {
            char path[8192 + 64];
            const char* why = NULL;
            batch_record_path(state, plan->tasks[k].name, path, sizeof path);
            if (batch_record_current(path, &plan->tasks[k], &why)) {
                ++*skipped;
                continue;
            }
            char slurm_job[64], reason[1024];
            if (submitted && batch_slurm_reason(submitted, plan->tasks[k].name, slurm_job, sizeof slurm_job, reason,
                                                sizeof reason) == 2) {
                cli_note(run, "batch: %s is still in Slurm's queue (%s): not submitted again", plan->tasks[k].name,
                         reason);
                ++*skipped;
                continue;
            }
        }
        todo[count++] = k;
    }
    batch_slurm_jobs_free(submitted);
    if (*skipped)
        cli_note(run, "batch: %d of %d task(s) are done already and unchanged", *skipped, plan->task_count);
    return count;
}

static int run_batch(cli_run* run) {
    /* SIGINT and SIGTERM wait until the scheduler or the Slurm wait takes
     * them (sigtimedwait), so an interruption is never lost in between. */
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    sigprocmask(SIG_BLOCK, &stop, NULL);
    const cli_value* status = cli_get(run, "--status");
    const cli_value* report = cli_get(run, "--report");
    const int slurm = cli_get(run, "--slurm")->given;
    if (status->set) {
        if (run->positional_count > 0) return cli_usage_error(run, "--status STATE reads a state folder: give no JOB");
        batch_counts counts;
        return batch_summary(status->text, 1, report->set ? report->text : NULL, &counts);
    }
    const int usage = check_options(run);
    if (usage) return usage;
    const cli_value* jobs_value = cli_get(run, "--jobs");
    const cli_value* task_names = cli_get(run, "--task");
    const char* job = run->positional[0];
    const cli_value* inputs = cli_get(run, "--inputs");
    const cli_value* out = cli_get(run, "--out");

    batch_plan plan;
    char error[4096];
    int code = batch_plan_read(job, inputs->set ? inputs->text : NULL, out->set ? out->text : NULL, &plan, error,
                               sizeof error);
    if (code == CLI_EXIT_USAGE) return cli_usage_error(run, "%s", error);
    if (code) {
        fprintf(stderr, "fabvdb batch: %s\n", error);
        return code;
    }
    if (cli_get(run, "--dry-run")->given) {
        print_dry_run(&plan);
        cli_note(run, "batch: %d task(s) checked", plan.task_count);
        batch_plan_free(&plan);
        return CLI_EXIT_OK;
    }
    char state[8192];
    int* todo = calloc((size_t)plan.task_count, sizeof *todo);
    if (!todo || state_folder(run, job, state, sizeof state) != 0) {
        free(todo);
        batch_plan_free(&plan);
        return CLI_EXIT_BAD_INPUT;
    }
    const int cores = cli_get(run, "--threads")->number > 0 ? (int)cli_get(run, "--threads")->number
                                                             : available_cores();
    batch_local_options local = {jobs_value->number > 0 ? (int)jobs_value->number : cores, cores,
                                 (double)fabvdb_ctx_memory_budget(run->ctx), cli_get(run, "--keep-going")->given,
                                 run->quiet, state};
    int todo_count = 0, skipped = 0;
    if (task_names->set) {
        /* An array task: the plan is the one the submission wrote; the cores
         * are the ones Slurm gave it. */
        const char* given = getenv("SLURM_CPUS_PER_TASK");
        if (!given) given = getenv("SLURM_CPUS_ON_NODE");
        if (given && atoi(given) > 0 && cli_get(run, "--threads")->number == 0) local.cores = atoi(given);
        local.jobs = 1;
        todo_count = named_tasks(&plan, task_names->text, todo);
        code = todo_count < 0 ? CLI_EXIT_BAD_INPUT : batch_run_local(&plan, todo, todo_count, 0, &local);
        free(todo);
        batch_plan_free(&plan);
        return code;
    }
    char plan_path[8192 + 16];
    snprintf(plan_path, sizeof plan_path, "%s/plan.job", state);
    if (batch_plan_write(&plan, job, plan_path) != 0) {
        status_print("batch", FABVDB_ERR_IO, "%s: cannot write the plan", plan_path);
        free(todo);
        batch_plan_free(&plan);
        return CLI_EXIT_BAD_INPUT;
    }
    todo_count = tasks_to_run(run, &plan, state, slurm, todo, &skipped);
    if (slurm) {
        const cli_value* mem = cli_get(run, "--mem");
        batch_slurm_options options = {cli_get(run, "--partition")->set ? cli_get(run, "--partition")->text : NULL,
                                       (int)cli_get(run, "--max-running")->number,
                                       cli_get(run, "--time")->set ? cli_get(run, "--time")->text : NULL,
                                       mem->set ? mem->number : 0, cli_get(run, "--wait")->given, run->quiet, state};
        code = submit_to_slurm(run, &plan, todo, todo_count, &options);
    } else {
        code = batch_run_local(&plan, todo, todo_count, skipped, &local);
    }
    if (code != CLI_EXIT_CANCELLED && (!slurm || report->set)) {
        batch_counts counts;
        const int summary = batch_summary(state, 0, report->set ? report->text : NULL, &counts);
        if (summary && !code) code = summary;
        if (!summary && !slurm)
            cli_note(run, "batch: %d done, %d failed, %d pending (%s; see 'fabvdb batch --status %s')", counts.done,
                     counts.failed, counts.pending, state, state);
        if (!summary && report->set) cli_note(run, "wrote %s", report->text);
    }
    free(todo);
    batch_plan_free(&plan);
    return code;
}

const cli_command cmd_batch = {
    "batch",
    "run a job's tasks here in parallel or on Slurm, resumably (recipes over many inputs, replays --save-job)",
    "JOB.job [--inputs PATTERN --out FOLDER] [--jobs N] [--resume] [--slurm ...] | --status STATE",
    "A job file is text: the first line is 'fabvdb-job 1'; then fabvdb command lines (without the word\n"
    "fabvdb), words bare or in double quotes, '#' comments, 'directory PATH' to run the lines below in PATH,\n"
    "and 'task NAME' to start a task. Without task lines the file is one task (any command run with\n"
    "--save-job FILE writes such a file, to replay it exactly). A recipe uses placeholders and runs once per\n"
    "input of --inputs: {input} (its path), {name}, {stem}, {out} (FOLDER/STEM of --out), {prev} (the\n"
    "--output of the line above):\n"
    "    repair {input} -o {out}/repaired.stl --report {out}/repair.json\n"
    "    hollow {prev} -o {out}/hollow.stl --wall 2mm --report {out}/hollow.json\n"
    "A task's lines run in order, each as its own fabvdb process; a failing line ends its task (unless\n"
    "--keep-going) but never the other tasks. Tasks run --jobs at a time, sharing --max-memory (each line\n"
    "gets a share as its budget; one refused under its share waits for more; one that cannot fit the whole\n"
    "budget fails with exit 3) and the cores (--threads). Each task writes its record (exit code, message,\n"
    "times, peak memory, SHA-256 of inputs and outputs) into the state folder when it ends; --resume\n"
    "reruns only what is failed, missing or changed. --slurm submits the tasks as one Slurm job array.\n"
    "Exit code: the first failed task's (in job order), 130 when interrupted. More: docs/batch.md.",
    options, sizeof(options) / sizeof(options[0]), 0, 1, run_batch};
