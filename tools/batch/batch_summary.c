/* batch_summary.c — the status and the report of a state folder
 * (batch_summary.h). */
#include "batch_summary.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "batch_plan.h"
#include "batch_record.h"
#include "batch_slurm.h"
#include "cli/cli.h"
#include "common/atomic_file.h"
#include "common/json.h"
#include "common/status_text.h"

/* Writes the top-level figures of one command's report. */
static void write_figures(FILE* out, const char* path) {
    const char* error = NULL;
    json_value* report = json_read_file(path, &error);
    fputc('{', out);
    int first = 1;
    for (const json_value* member = report && report->type == JSON_OBJECT ? report->child : NULL; member;
         member = member->next) {
        if (member->type != JSON_NUMBER && member->type != JSON_BOOL && member->type != JSON_ARRAY) continue;
        fputs(first ? "" : ", ", out);
        first = 0;
        json_write_string(out, member->key);
        fputs(": ", out);
        if (member->type == JSON_BOOL) fputs(member->number ? "true" : "false", out);
        else if (member->type == JSON_ARRAY) fprintf(out, "%zu", member->count);
        else json_write_number(out, member->number);
    }
    fputc('}', out);
    json_free(report);
}

typedef struct task_state {
    const char* status; /* done, failed, pending */
    json_value* record;
    char reason[1024];  /* Slurm's, for a task without a record */
    char slurm_job[64];
} task_state;

static void write_task(FILE* out, const batch_task* task, const task_state* s, int figures) {
    fputs("    {\"task\": ", out);
    json_write_string(out, task->name);
    fputs(", \"input\": ", out);
    json_write_string(out, task->input);
    fprintf(out, ", \"status\": \"%s\"", s->status);
    const json_value* r = s->record;
    if (r) {
        fputs(", \"exit_code\": ", out);
        json_write_number(out, json_get_number(r, "exit_code", -1));
        fputs(", \"message\": ", out);
        json_write_string(out, json_get_string(r, "message", ""));
        fputs(", \"failed_line\": ", out);
        json_write_number(out, json_get_number(r, "failed_line", NAN));
        fputs(", \"timings\": {\"total\": ", out);
        json_write_number(out, json_get_number(r, "seconds", NAN));
        fputc('}', out);
        fputs(", \"peak_memory_bytes\": ", out);
        json_write_number(out, json_get_number(r, "peak_memory_bytes", NAN));
        fputs(", \"slurm_job\": ", out);
        json_write_string(out, json_get_string(r, "slurm_job", NULL));
        fputs(", \"log\": ", out);
        json_write_string(out, json_get_string(r, "log", NULL));
    } else {
        fputs(", \"exit_code\": null, \"message\": ", out);
        json_write_string(out, s->reason[0] ? s->reason : NULL);
        fputs(", \"slurm_job\": ", out);
        json_write_string(out, s->slurm_job[0] ? s->slurm_job : NULL);
    }
    if (figures) {
        fputs(", \"reports\": [", out);
        const json_value* reports = json_get(r, "reports");
        int first = 1;
        for (const json_value* report = reports ? reports->child : NULL; report; report = report->next) {
            const char* path = json_get_string(report, "path", NULL);
            if (!path) continue;
            fputs(first ? "\n      {\"command\": " : ",\n      {\"command\": ", out);
            first = 0;
            json_write_string(out, json_get_string(report, "command", NULL));
            fputs(", \"path\": ", out);
            json_write_string(out, path);
            fputs(", \"figures\": ", out);
            write_figures(out, path);
            fputc('}', out);
        }
        fputs(first ? "]" : "\n    ]", out);
    }
    fputc('}', out);
}

/* The summary's `timings`: `tasks`, the sum of the recorded tasks' wall times,
 * and `total`, from the first recorded start to the last recorded end. */
static void write_timings(FILE* out, const batch_plan* plan, const task_state* states) {
    double tasks = 0.0, first = INFINITY, last = -INFINITY;
    for (int k = 0; k < plan->task_count; ++k) {
        const json_value* r = states[k].record;
        if (!r) continue;
        tasks += json_get_number(r, "seconds", 0.0);
        first = fmin(first, json_get_number(r, "started_epoch", INFINITY));
        last = fmax(last, json_get_number(r, "ended_epoch", -INFINITY));
    }
    fputs("  \"timings\": {\"tasks\": ", out);
    json_write_number(out, tasks);
    fputs(", \"total\": ", out);
    json_write_number(out, last >= first ? last - first : 0.0);
    fputs("},\n", out);
}

static int write_json(const char* path, const char* state, const batch_plan* plan, const task_state* states,
                      const batch_counts* counts, int figures) {
    atomic_file file;
    if (atomic_file_open(&file, path) != 0) return -1;
    FILE* out = file.out;
    char now[64];
    batch_format_time(batch_now(), now, sizeof now);
    fprintf(out, "{\n  \"format\": \"%s\",\n  \"state\": ", figures ? "fabvdb-batch-report 2" : "fabvdb-batch-status 2");
    json_write_string(out, state);
    fprintf(out, ",\n  \"written\": \"%s\",\n  \"tasks\": %d, \"done\": %d, \"failed\": %d, \"pending\": %d,\n", now,
            counts->tasks, counts->done, counts->failed, counts->pending);
    write_timings(out, plan, states);
    fputs("  \"task_list\": [\n", out);
    for (int k = 0; k < plan->task_count; ++k) {
        write_task(out, &plan->tasks[k], &states[k], figures);
        fputs(k + 1 < plan->task_count ? ",\n" : "\n", out);
    }
    fputs("  ]\n}\n", out);
    return atomic_file_commit(&file);
}

int batch_summary(const char* state, int print, const char* report_path, batch_counts* counts) {
    char plan_path[8192];
    snprintf(plan_path, sizeof plan_path, "%s/plan.job", state);
    batch_plan plan;
    char error[4096];
    if (access(plan_path, R_OK) != 0) {
        status_print("batch", FABVDB_ERR_BAD_INPUT, "%s: not a batch state folder (no plan.job)", state);
        return cli_exit_code(FABVDB_ERR_BAD_INPUT);
    }
    int code = batch_plan_read(plan_path, NULL, NULL, &plan, error, sizeof error);
    if (code) {
        fprintf(stderr, "fabvdb batch: %s\n", error);
        return code;
    }
    task_state* states = calloc((size_t)plan.task_count, sizeof *states);
    memset(counts, 0, sizeof *counts);
    counts->tasks = plan.task_count;
    batch_slurm_jobs* slurm = batch_slurm_jobs_read(state);
    for (int k = 0; k < plan.task_count; ++k) {
        char path[8192];
        batch_record_path(state, plan.tasks[k].name, path, sizeof path);
        const char* problem = NULL;
        states[k].record = json_read_file(path, &problem);
        const char* status = json_get_string(states[k].record, "status", NULL);
        if (status && strcmp(status, "done") == 0) {
            states[k].status = "done";
            ++counts->done;
        } else if (status) {
            states[k].status = "failed";
            ++counts->failed;
            if (!counts->first_failure)
                counts->first_failure = (int)json_get_number(states[k].record, "exit_code", CLI_EXIT_INTERNAL);
        } else if (slurm && batch_slurm_reason(slurm, plan.tasks[k].name, states[k].slurm_job,
                                               sizeof states[k].slurm_job, states[k].reason,
                                               sizeof states[k].reason) == 1) {
            states[k].status = "failed";
            ++counts->failed;
            if (!counts->first_failure) counts->first_failure = batch_slurm_exit_code(states[k].reason);
        } else {
            states[k].status = "pending";
            ++counts->pending;
        }
    }
    batch_slurm_jobs_free(slurm);
    char status_path[8192];
    snprintf(status_path, sizeof status_path, "%s/status.json", state);
    if (write_json(status_path, state, &plan, states, counts, 0) != 0) {
        status_print("batch", FABVDB_ERR_IO, "%s: cannot write the status", status_path);
        code = cli_exit_code(FABVDB_ERR_IO);
    }
    if (!code && report_path && write_json(report_path, state, &plan, states, counts, 1) != 0) {
        status_print("batch", FABVDB_ERR_IO, "%s: cannot write the report", report_path);
        code = cli_exit_code(FABVDB_ERR_IO);
    }
    if (print) {
        printf("batch %s: %d task(s): %d done, %d failed, %d pending\n", state, counts->tasks, counts->done,
               counts->failed, counts->pending);
        for (int k = 0; k < plan.task_count; ++k) {
            if (strcmp(states[k].status, "failed") != 0) continue;
            const json_value* r = states[k].record;
            if (r)
                printf("  failed   %s (exit %.0f, job line %.0f): %s\n", plan.tasks[k].name,
                       json_get_number(r, "exit_code", -1), json_get_number(r, "failed_line", 0),
                       json_get_string(r, "message", ""));
            else
                printf("  failed   %s: %s\n", plan.tasks[k].name, states[k].reason);
        }
        int shown = 0;
        for (int k = 0; k < plan.task_count; ++k) {
            if (strcmp(states[k].status, "pending") != 0) continue;
            if (shown++ < 20)
                printf("  pending  %s%s%s\n", plan.tasks[k].name, states[k].reason[0] ? ": " : "", states[k].reason);
        }
        if (shown > 20) printf("  ... and %d more pending\n", shown - 20);
        if (!code) printf("wrote %s\n", status_path);
    }
    for (int k = 0; k < plan.task_count; ++k) json_free(states[k].record);
    free(states);
    batch_plan_free(&plan);
    return code;
}
