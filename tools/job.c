/* job.c — reading and writing the tokens of job files, and --save-job. */
#define _DEFAULT_SOURCE /* POSIX: sigaction, mkdtemp, chdir, getcwd */
#include "job.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "fabvdb.h"

int job_tokenize(const char* text, job_line* line, const char** error) {
    line->count = 0;
    const char* p = text;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
        if (!*p || *p == '#') return 0;
        if (line->count == JOB_MAX_TOKENS) {
            *error = "too many words on one line";
            job_line_free(line);
            return -1;
        }
        size_t capacity = strlen(p) + 1, length = 0;
        char* token = malloc(capacity);
        if (!token) {
            *error = "out of memory";
            job_line_free(line);
            return -1;
        }
        if (*p == '"') {
            ++p;
            while (*p && *p != '"') {
                if (*p == '\\' && (p[1] == '"' || p[1] == '\\')) ++p;
                token[length++] = *p++;
            }
            if (*p != '"') {
                free(token);
                *error = "a quoted word is not closed";
                job_line_free(line);
                return -1;
            }
            ++p;
        } else {
            while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') token[length++] = *p++;
        }
        token[length] = 0;
        line->tokens[line->count++] = token;
    }
}

void job_line_free(job_line* line) {
    for (int i = 0; i < line->count; ++i) free(line->tokens[i]);
    line->count = 0;
}

void job_write_token(FILE* out, const char* token) {
    fputc('"', out);
    for (const char* p = token; *p; ++p) {
        if (*p == '"' || *p == '\\') fputc('\\', out);
        fputc(*p, out);
    }
    fputc('"', out);
}

int cli_write_job(const char* path, const char* command_name, int argc, char** argv) {
    size_t length = strlen(path);
    char* temp = malloc(length + 16);
    if (!temp) return -1;
    snprintf(temp, length + 16, "%s.partial-job", path);
    FILE* out = fopen(temp, "w");
    if (!out) {
        free(temp);
        return -1;
    }
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
    int failed = ferror(out) != 0;
    failed |= fclose(out) != 0;
    if (!failed) failed = rename(temp, path) != 0;
    if (failed) remove(temp);
    free(temp);
    return failed ? -1 : 0;
}
