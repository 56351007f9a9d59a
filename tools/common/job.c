/* job.c — reading and writing the tokens of job files (job.h). */
#include "job.h"

#include <stdlib.h>
#include <string.h>

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
