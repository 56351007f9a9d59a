/* batch_record.c — writing task records atomically and checking them against
 * the plan and the files (batch_record.h). */
#define _DEFAULT_SOURCE /* POSIX: strdup, gettimeofday */
#include "batch_record.h"

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <time.h>
#include <unistd.h>

#include "batch_files.h"
#include "common/atomic_file.h"
#include "common/json.h"

double batch_now(void) {
    struct timeval now;
    gettimeofday(&now, NULL);
    return (double)now.tv_sec + 1e-6 * (double)now.tv_usec;
}

void batch_format_time(double seconds, char* text, size_t size) {
    const time_t whole = (time_t)seconds;
    struct tm utc;
    gmtime_r(&whole, &utc);
    char base[32];
    strftime(base, sizeof base, "%Y-%m-%dT%H:%M:%S", &utc);
    snprintf(text, size, "%s.%03dZ", base, (int)((seconds - (double)whole) * 1000.0));
}

int batch_file_list_add(batch_file_list* list, const char* path) {
    struct stat info;
    if (stat(path, &info) != 0) return 0;
    if (S_ISDIR(info.st_mode)) {
        DIR* folder = opendir(path);
        if (!folder) return 0;
        char** names = NULL;
        size_t n = 0;
        struct dirent* entry;
        while ((entry = readdir(folder))) {
            if (strcmp(entry->d_name, ".") == 0 || strcmp(entry->d_name, "..") == 0) continue;
            char** grown = realloc(names, (n + 1) * sizeof *names);
            if (!grown) break;
            names = grown;
            names[n++] = strdup(entry->d_name);
        }
        closedir(folder);
        batch_files_sort(names, n);
        int code = 0;
        for (size_t i = 0; i < n; ++i) {
            char child[8192];
            snprintf(child, sizeof child, "%s/%s", path, names[i]);
            if (!code && strstr(names[i], ".partial-") == NULL) code = batch_file_list_add(list, child);
            free(names[i]);
        }
        free(names);
        return code;
    }
    if (!S_ISREG(info.st_mode) || batch_file_list_has(list, path)) return 0;
    batch_file_hash* grown = realloc(list->files, (size_t)(list->count + 1) * sizeof *grown);
    if (!grown) return -1;
    list->files = grown;
    batch_file_hash* entry = &list->files[list->count];
    entry->path = strdup(path);
    if (!entry->path) return -1;
    if (batch_sha256_file(path, entry->sha256) != 0) entry->sha256[0] = 0;
    ++list->count;
    return 0;
}

int batch_file_list_has(const batch_file_list* list, const char* path) {
    for (int i = 0; i < list->count; ++i)
        if (strcmp(list->files[i].path, path) == 0) return 1;
    return 0;
}

void batch_file_list_free(batch_file_list* list) {
    for (int i = 0; i < list->count; ++i) free(list->files[i].path);
    free(list->files);
    list->files = NULL;
    list->count = 0;
}

void batch_record_path(const char* state, const char* name, char* path, size_t size) {
    snprintf(path, size, "%s/tasks/%s.json", state, name);
}

static void write_files(FILE* out, const char* key, const batch_file_list* list) {
    fprintf(out, "  \"%s\": [", key);
    for (int i = 0; i < list->count; ++i) {
        fputs(i ? ",\n    {\"path\": " : "\n    {\"path\": ", out);
        json_write_string(out, list->files[i].path);
        fputs(", \"sha256\": ", out);
        json_write_string(out, list->files[i].sha256[0] ? list->files[i].sha256 : NULL);
        fputc('}', out);
    }
    fputs(list->count ? "\n  ],\n" : "],\n", out);
}

static void write_time(FILE* out, const char* key, double seconds) {
    char text[64];
    batch_format_time(seconds, text, sizeof text);
    fprintf(out, "\"%s\": \"%s\", \"%s_epoch\": ", key, text, key);
    json_write_number(out, seconds);
}

int batch_record_write(const batch_record* record, const char* path) {
    atomic_file file;
    if (atomic_file_open(&file, path) != 0) return -1;
    FILE* out = file.out;
    const batch_task* task = record->task;
    fprintf(out, "{\n  \"format\": \"%s\",\n  \"task\": ", BATCH_RECORD_FORMAT);
    json_write_string(out, task->name);
    fputs(",\n  \"input\": ", out);
    json_write_string(out, task->input);
    fputs(",\n  \"out\": ", out);
    json_write_string(out, task->out);
    fprintf(out, ",\n  \"status\": \"%s\",\n  \"exit_code\": %d,\n  \"message\": ", record->done ? "done" : "failed",
            record->exit_code);
    json_write_string(out, record->message);
    fputs(",\n  \"failed_line\": ", out);
    if (record->failed_line >= 0) fprintf(out, "%d", task->lines[record->failed_line].source_line);
    else fputs("null", out);
    fputs(",\n  ", out);
    write_time(out, "started", record->started);
    fputs(",\n  ", out);
    write_time(out, "ended", record->ended);
    fputs(",\n  \"seconds\": ", out);
    json_write_number(out, record->ended - record->started);
    long peak = 0;
    for (int i = 0; i < task->line_count; ++i)
        if (record->lines[i].peak_kib > peak) peak = record->lines[i].peak_kib;
    fprintf(out, ",\n  \"peak_memory_bytes\": %ld,\n  \"host\": ", peak * 1024);
    json_write_string(out, record->host);
    fputs(",\n  \"slurm_job\": ", out);
    json_write_string(out, record->slurm_job[0] ? record->slurm_job : NULL);
    fputs(",\n  \"log\": ", out);
    json_write_string(out, record->log);
    fputs(",\n  \"lines\": [", out);
    for (int i = 0; i < task->line_count; ++i) {
        const batch_plan_line* line = &task->lines[i];
        const batch_line_result* result = &record->lines[i];
        fputs(i ? ",\n    {\"command\": [" : "\n    {\"command\": [", out);
        for (int t = 0; t < line->line.count; ++t) {
            if (t) fputs(", ", out);
            json_write_string(out, line->line.tokens[t]);
        }
        fputs("], \"directory\": ", out);
        json_write_string(out, line->directory);
        fprintf(out, ", \"job_line\": %d", line->source_line);
        if (result->ran) {
            fprintf(out, ", \"exit_code\": %d, \"signal\": %d, ", result->exit_code, result->signal);
            write_time(out, "started", result->started);
            fputs(", ", out);
            write_time(out, "ended", result->ended);
            fprintf(out, ", \"seconds\": ");
            json_write_number(out, result->ended - result->started);
            fprintf(out, ", \"peak_memory_bytes\": %ld, \"threads\": %d, \"max_memory\": ", result->peak_kib * 1024,
                    result->threads);
            json_write_number(out, result->max_memory);
            fprintf(out, ", \"budget_retries\": %d", result->budget_retries);
        } else {
            fputs(", \"exit_code\": null", out);
        }
        fputc('}', out);
    }
    fputs("\n  ],\n", out);
    write_files(out, "inputs", &record->inputs);
    write_files(out, "outputs", &record->outputs);
    fputs("  \"reports\": [", out);
    for (int i = 0; i < record->report_count; ++i) {
        fputs(i ? ", {\"command\": " : "{\"command\": ", out);
        json_write_string(out, record->report_commands[i]);
        fputs(", \"path\": ", out);
        json_write_string(out, record->reports[i]);
        fputc('}', out);
    }
    fputs("]\n}\n", out);
    return atomic_file_commit(&file);
}

/* Whether every file of the record's list `key` still has its hash. */
static int files_unchanged(const json_value* record, const char* key) {
    const json_value* files = json_get(record, key);
    if (!files || files->type != JSON_ARRAY) return 0;
    for (const json_value* file = files->child; file; file = file->next) {
        const char* path = json_get_string(file, "path", NULL);
        const char* hash = json_get_string(file, "sha256", NULL);
        char now[BATCH_SHA256_HEX_LENGTH + 1];
        if (!path || !hash || batch_sha256_file(path, now) != 0 || strcmp(now, hash) != 0) return 0;
    }
    return 1;
}

static int same_lines(const json_value* record, const batch_task* task) {
    const json_value* lines = json_get(record, "lines");
    if (!lines || lines->type != JSON_ARRAY || (int)lines->count != task->line_count) return 0;
    const json_value* line = lines->child;
    for (int i = 0; i < task->line_count; ++i, line = line->next) {
        const json_value* command = json_get(line, "command");
        const char* directory = json_get_string(line, "directory", "");
        if (!command || command->type != JSON_ARRAY || (int)command->count != task->lines[i].line.count ||
            strcmp(directory, task->lines[i].directory) != 0)
            return 0;
        const json_value* token = command->child;
        for (int t = 0; t < task->lines[i].line.count; ++t, token = token->next)
            if (token->type != JSON_STRING || strcmp(token->string, task->lines[i].line.tokens[t]) != 0) return 0;
    }
    return 1;
}

int batch_record_current(const char* path, const batch_task* task, const char** why) {
    const char* error = NULL;
    json_value* record = json_read_file(path, &error);
    int current = 0;
    if (!record) *why = "no record";
    else if (strcmp(json_get_string(record, "format", ""), BATCH_RECORD_FORMAT) != 0) *why = "not a record";
    else if (strcmp(json_get_string(record, "status", ""), "done") != 0) *why = "failed";
    else if (!same_lines(record, task)) *why = "its command lines changed";
    else if (!files_unchanged(record, "inputs")) *why = "an input changed";
    else if (!files_unchanged(record, "outputs")) *why = "an output changed or is gone";
    else current = 1;
    json_free(record);
    return current;
}
