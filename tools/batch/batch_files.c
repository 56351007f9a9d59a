/* batch_files.c — the inputs and outputs of a job line, from its command's
 * option table (batch_files.h). */
#include "batch_files.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/commands.h"

static int is_output_option(const char* name) {
    return strcmp(name, "--output") == 0 || strcmp(name, "--report") == 0 || strcmp(name, "--heatmap") == 0 ||
           strcmp(name, "--save-job") == 0;
}

static int is_regular_file(const char* path) {
    struct stat info;
    return stat(path, &info) == 0 && S_ISREG(info.st_mode);
}

int batch_line_files_of(const job_line* line, int check_inputs, batch_line_files* files, const char** error) {
    memset(files, 0, sizeof *files);
    const cli_command* command = line->count ? command_named(line->tokens[0]) : NULL;
    if (!command) {
        *error = "no such command";
        return -1;
    }
    int only_positional = 0;
    for (int a = 1; a < line->count; ++a) {
        const char* arg = line->tokens[a];
        if (!only_positional && strcmp(arg, "--") == 0) {
            only_positional = 1;
            continue;
        }
        if (only_positional || arg[0] != '-' || arg[1] == 0 || (arg[1] >= '0' && arg[1] <= '9')) {
            if (files->input_count == BATCH_MAX_LINE_FILES) {
                *error = "too many files on one line";
                return -1;
            }
            files->inputs[files->input_count++] = arg;
            continue;
        }
        const char* value = NULL;
        const cli_option* option;
        if (arg[1] == '-') {
            const char* equals = strchr(arg, '=');
            option = cli_option_named(command, arg, equals ? (size_t)(equals - arg) : strlen(arg), 0);
            if (equals) value = equals + 1;
        } else {
            option = arg[2] == 0 ? cli_option_named(command, NULL, 0, arg[1]) : NULL;
        }
        if (!option) {
            *error = "an option the command does not have";
            return -1;
        }
        if (option->type == CLI_FLAG) continue;
        if (!value) {
            if (a + 1 >= line->count) {
                *error = "an option without its value";
                return -1;
            }
            value = line->tokens[++a];
        }
        if (strcmp(option->name, "--threads") == 0) files->threads = value;
        if (strcmp(option->name, "--max-memory") == 0) files->max_memory = value;
        if (option->type != CLI_STRING) continue;
        if (strcmp(option->name, "--output") == 0) files->output = value;
        if (strcmp(option->name, "--report") == 0) files->report = value;
        const int output = is_output_option(option->name);
        if (!output && check_inputs && !is_regular_file(value)) continue;
        if ((output ? files->output_count : files->input_count) == BATCH_MAX_LINE_FILES) {
            *error = "too many files on one line";
            return -1;
        }
        if (output) files->outputs[files->output_count++] = value;
        else files->inputs[files->input_count++] = value;
    }
    return 0;
}

char* batch_files_absolute(const char* directory, const char* path) {
    const size_t length = strlen(directory) + strlen(path) + 2;
    char* joined = malloc(length);
    if (!joined) return NULL;
    if (path[0] == '/') snprintf(joined, length, "%s", path);
    else snprintf(joined, length, "%s/%s", directory, path);
    return joined;
}

static int compare_names(const void* a, const void* b) { return strcmp(*(char* const*)a, *(char* const*)b); }

void batch_files_sort(char** names, size_t count) { qsort(names, count, sizeof *names, compare_names); }
