/* batch_task.c — one task's lines as child processes, and its record
 * (batch_task.h). */
#define _GNU_SOURCE /* strsignal, dprintf */
#include "batch_task.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "batch_files.h"
#include "cli/cli.h"
#include "common/spawn.h"
#include "common/status_text.h"

/* Removes the temporary files (NAME.partial-*) a killed command left in `folder`. */
static void remove_partials(const char* folder) {
    DIR* listing = opendir(folder);
    if (!listing) return;
    struct dirent* entry;
    while ((entry = readdir(listing))) {
        if (!strstr(entry->d_name, ".partial-")) continue;
        char path[8192];
        snprintf(path, sizeof path, "%s/%s", folder, entry->d_name);
        unlink(path);
    }
    closedir(listing);
}

int batch_task_begin(batch_task_run* run, const batch_task* task, const char* state, int keep_going) {
    memset(run, 0, sizeof *run);
    run->task = task;
    run->state = state;
    run->keep_going = keep_going;
    run->log_fd = -1;
    batch_record* record = &run->record;
    record->task = task;
    record->failed_line = -1;
    record->started = batch_now();
    record->lines = calloc((size_t)task->line_count, sizeof *record->lines);
    gethostname(record->host, sizeof record->host - 1);
    const char* array_job = getenv("SLURM_ARRAY_JOB_ID");
    const char* array_task = getenv("SLURM_ARRAY_TASK_ID");
    if (array_job && array_task) snprintf(record->slurm_job, sizeof record->slurm_job, "%s_%s", array_job, array_task);
    char path[8192];
    batch_record_path(state, task->name, path, sizeof path);
    unlink(path);
    snprintf(record->log, sizeof record->log, "%s/logs/%s.log", state, task->name);
    run->log_fd = open(record->log, O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
    if (!record->lines || run->log_fd < 0) {
        status_text(record->message, sizeof record->message, FABVDB_ERR_IO, "%.1900s: cannot write the task's log",
                    record->log);
        record->exit_code = cli_exit_code(FABVDB_ERR_IO);
        return -1;
    }
    if (task->out) {
        if (mkdir(task->out, 0777) != 0 && errno != EEXIST) {
            status_text(record->message, sizeof record->message, FABVDB_ERR_IO,
                        "%.1900s: cannot create the task's folder", task->out);
            record->exit_code = cli_exit_code(FABVDB_ERR_IO);
            return -1;
        }
        remove_partials(task->out);
    }
    /* The task's inputs: what its lines read that no line before them writes. */
    batch_file_list written = {0};
    for (int i = 0; i < task->line_count; ++i) {
        const batch_plan_line* line = &task->lines[i];
        batch_line_files files;
        const char* problem;
        if (batch_line_files_of(&line->line, 1, &files, &problem) != 0) continue;
        for (int k = 0; k < files.input_count; ++k) {
            char* path_k = batch_files_absolute(line->directory, files.inputs[k]);
            int produced = 0;
            for (int w = 0; path_k && w < written.count; ++w)
                produced |= strcmp(written.files[w].path, path_k) == 0 ||
                            (strncmp(path_k, written.files[w].path, strlen(written.files[w].path)) == 0 &&
                             path_k[strlen(written.files[w].path)] == '/');
            if (path_k && !produced) batch_file_list_add(&record->inputs, path_k);
            free(path_k);
        }
        for (int k = 0; k < files.output_count; ++k) {
            batch_file_hash* grown = realloc(written.files, (size_t)(written.count + 1) * sizeof *grown);
            if (!grown) break;
            written.files = grown;
            written.files[written.count].path = batch_files_absolute(line->directory, files.outputs[k]);
            if (written.files[written.count].path) ++written.count;
        }
    }
    batch_file_list_free(&written);
    return 0;
}

double batch_task_own_budget(const batch_task_run* run) {
    batch_line_files files;
    const char* problem;
    if (batch_line_files_of(&run->task->lines[run->next_line].line, 0, &files, &problem) != 0 || !files.max_memory)
        return 0;
    double bytes = 0;
    int relative = 0;
    return cli_parse_value(CLI_SIZE, files.max_memory, &bytes, &relative) == 0 ? bytes : 0;
}

pid_t batch_task_spawn(batch_task_run* run, int threads, double max_memory) {
    const batch_plan_line* line = &run->task->lines[run->next_line];
    batch_line_result* result = &run->record.lines[run->next_line];
    batch_line_files files;
    const char* problem;
    if (batch_line_files_of(&line->line, 0, &files, &problem) != 0) memset(&files, 0, sizeof files);
    if (files.threads) threads = 0;
    if (files.max_memory) max_memory = 0;
    char threads_text[32], memory_text[32];
    snprintf(threads_text, sizeof threads_text, "%d", threads);
    snprintf(memory_text, sizeof memory_text, "%.0f", max_memory);
    char* argv[JOB_MAX_TOKENS + 8];
    int argc = 0;
    argv[argc++] = "fabvdb";
    argv[argc++] = line->line.tokens[0];
    if (threads > 0) {
        argv[argc++] = "--threads";
        argv[argc++] = threads_text;
    }
    if (max_memory > 0) {
        argv[argc++] = "--max-memory";
        argv[argc++] = memory_text;
    }
    for (int t = 1; t < line->line.count; ++t) argv[argc++] = line->line.tokens[t];
    argv[argc] = NULL;

    dprintf(run->log_fd, "== job line %d:", line->source_line);
    for (int a = 0; a < argc; ++a) dprintf(run->log_fd, " %s", argv[a]);
    dprintf(run->log_fd, "\n");
    run->log_offset = (long)lseek(run->log_fd, 0, SEEK_END);
    result->ran = 1;
    result->started = batch_now();
    result->threads = threads;
    result->max_memory = max_memory;
    /* The child dies with the batch (SIGTERM cancels the command, which then
     * removes its temporary files). */
    const spawn_options spawn = {line->directory, run->log_fd, 1};
    spawn_failure failure;
    const pid_t pid = spawn_start("/proc/self/exe", argv, &spawn, &failure);
    if (pid < 0) {
        const fabvdb_status status = failure == SPAWN_NO_DIRECTORY ? FABVDB_ERR_IO : FABVDB_ERR_INTERNAL;
        status_text(run->record.message, sizeof run->record.message, status, "%s %.1900s: %s",
                    failure == SPAWN_NO_DIRECTORY ? "cannot enter the directory"
                    : failure == SPAWN_NO_PROGRAM ? "cannot run"
                                                  : "cannot start a process for",
                    failure == SPAWN_NO_DIRECTORY ? line->directory : "/proc/self/exe", strerror(errno));
        run->record.exit_code = cli_exit_code(status);
        run->record.failed_line = run->next_line;
        result->ran = 0;
        return -1;
    }
    run->pid = pid;
    return pid;
}

/* The message of the line that just failed: the last line of its output that
 * starts with "fabvdb " (the error every command prints), else its last line. */
static void read_message(batch_task_run* run, char* message, size_t size) {
    message[0] = 0;
    const int fd = open(run->record.log, O_RDONLY);
    if (fd < 0) return;
    const off_t end = lseek(fd, 0, SEEK_END);
    off_t start = run->log_offset;
    if (end - start > 65536) start = end - 65536;
    char* text = malloc((size_t)(end - start) + 1);
    ssize_t got = text ? pread(fd, text, (size_t)(end - start), start) : -1;
    close(fd);
    if (got < 0) {
        free(text);
        return;
    }
    text[got] = 0;
    const char* best = NULL, *last = NULL;
    for (char* line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        char* r = strchr(line, '\r');
        if (r) line = r + 1; /* what a progress bar's carriage return left */
        if (!*line) continue;
        last = line;
        if (strncmp(line, "fabvdb ", 7) == 0) best = line;
    }
    snprintf(message, size, "%s", best ? best : last ? last : "");
    free(text);
}

batch_line_outcome batch_task_reaped(batch_task_run* run, int status, const struct rusage* usage, double whole_budget) {
    batch_record* record = &run->record;
    batch_line_result* result = &record->lines[run->next_line];
    run->pid = 0;
    result->ended = batch_now();
    result->peak_kib = usage->ru_maxrss;
    result->signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    result->exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + result->signal;
    const int last = run->next_line + 1 == run->task->line_count;
    if (result->exit_code == CLI_EXIT_OK) {
        ++run->next_line;
        if (!last) return BATCH_LINE_NEXT;
        record->done = !run->failed;
        return BATCH_TASK_ENDED;
    }
    if (result->exit_code == CLI_EXIT_BUDGET && result->max_memory > 0 && result->max_memory < whole_budget) {
        ++result->budget_retries;
        return BATCH_LINE_OVER_BUDGET;
    }
    if (!run->failed) {
        char message[sizeof record->message - 64];
        read_message(run, message, sizeof message);
        if (result->signal)
            snprintf(record->message, sizeof record->message, "killed by signal %d (%s)%s%s", result->signal,
                     strsignal(result->signal), message[0] ? "; its last words: " : "", message);
        else
            snprintf(record->message, sizeof record->message, "%s", message[0] ? message : "failed without a message");
        record->exit_code = result->signal ? CLI_EXIT_INTERNAL : result->exit_code;
        record->failed_line = run->next_line;
        run->failed = 1;
    }
    ++run->next_line;
    if (run->keep_going && !last && result->exit_code != CLI_EXIT_CANCELLED) return BATCH_LINE_NEXT;
    record->done = 0;
    return BATCH_TASK_ENDED;
}

int batch_task_end(batch_task_run* run) {
    batch_record* record = &run->record;
    record->ended = batch_now();
    for (int i = 0; i < run->task->line_count; ++i) {
        if (!record->lines[i].ran) continue;
        const batch_plan_line* line = &run->task->lines[i];
        batch_line_files files;
        const char* problem;
        if (batch_line_files_of(&line->line, 0, &files, &problem) != 0) continue;
        for (int k = 0; k < files.output_count; ++k) {
            char* path = batch_files_absolute(line->directory, files.outputs[k]);
            if (path) batch_file_list_add(&record->outputs, path);
            free(path);
        }
        char* report = files.report ? batch_files_absolute(line->directory, files.report) : NULL;
        struct stat info;
        if (report && stat(report, &info) == 0) {
            char** grown = realloc(record->reports, (size_t)(record->report_count + 1) * sizeof *grown);
            if (grown) record->reports = grown;
            const char** commands =
                realloc(record->report_commands, (size_t)(record->report_count + 1) * sizeof *commands);
            if (commands) record->report_commands = commands;
            if (grown && commands) {
                record->report_commands[record->report_count] = line->line.tokens[0];
                record->reports[record->report_count++] = report;
                report = NULL;
            }
        }
        free(report);
    }
    char path[8192];
    batch_record_path(run->state, run->task->name, path, sizeof path);
    return batch_record_write(record, path);
}

void batch_task_free(batch_task_run* run) {
    if (run->log_fd >= 0) close(run->log_fd);
    run->log_fd = -1;
    free(run->record.lines);
    batch_file_list_free(&run->record.inputs);
    batch_file_list_free(&run->record.outputs);
    for (int i = 0; i < run->record.report_count; ++i) free(run->record.reports[i]);
    free(run->record.reports);
    free(run->record.report_commands);
    memset(&run->record, 0, sizeof run->record);
}
