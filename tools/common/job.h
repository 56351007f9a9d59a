/* job.h — job files: versioned text files holding fabvdb command lines, so a
 * run can be written out (the CLI's --save-job, tools/cli/cli.c) and replayed
 * exactly (fabvdb batch, tools/batch/batch_plan.c), split into tokens here.
 *
 *   fabvdb-job 1                 first line: the format and its version
 *   # a comment
 *   directory "/where/it/ran"    relative paths below resolve from here
 *   hollow "in.stl" "-o" "out.stl" "--wall" "3mm"
 *
 * Tokens are bare words or double-quoted strings with \" and \\ escapes.
 * `fabvdb batch` also reads 'task NAME' lines, 'line N' lines (in the plans it
 * writes) and placeholders such as {input} (tools/batch/batch_plan.h). */
#ifndef FABVDB_JOB_H
#define FABVDB_JOB_H

#include <stdio.h>

#define JOB_FORMAT_VERSION 1
#define JOB_MAX_TOKENS 256

/* One line split into tokens (owned by the line; free with job_line_free). */
typedef struct job_line {
    char* tokens[JOB_MAX_TOKENS];
    int count;
} job_line;

/* Splits `text` (one line; a # where a word would start ends it) into tokens.
 * Returns 0, or -1 with *error set to a static description of the defect (an
 * unterminated quote, too many tokens) and nothing allocated. Reads no
 * further than the text's final NUL (fuzz/fuzz_job.c). */
int job_tokenize(const char* text, job_line* line, const char** error);
void job_line_free(job_line* line);
/* Writes `token` quoted, for job_tokenize to read back. */
void job_write_token(FILE* out, const char* token);

#endif
