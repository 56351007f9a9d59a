/* batch_files.h — what one job line reads and writes, read from its command's
 * option table (tools/cli/cli.h): the outputs are the values of --output (-o),
 * --report, --heatmap and --save-job; the inputs are the positional arguments
 * and every other text option whose value names an existing file when asked
 * (--decomposition, --keep-out, --holes, an --orientations file...). Also
 * tells whether the line sets --threads or --max-memory itself. Pointers
 * point into the line's tokens. */
#ifndef FABVDB_BATCH_FILES_H
#define FABVDB_BATCH_FILES_H

#include <stddef.h>

#include "common/job.h"

#define BATCH_MAX_LINE_FILES 32

typedef struct batch_line_files {
    const char* outputs[BATCH_MAX_LINE_FILES];
    int output_count;
    const char* inputs[BATCH_MAX_LINE_FILES];
    int input_count;
    const char* output;     /* the value of --output, or NULL */
    const char* report;     /* the value of --report, or NULL */
    const char* threads;    /* the value of --threads, or NULL */
    const char* max_memory; /* the value of --max-memory, or NULL */
} batch_line_files;

/* Classifies the tokens of `line` (tokens[0] a command name). With
 * check_inputs, text options count as inputs only where they name an existing
 * regular file; positional arguments always do. Returns 0, or -1 with *error
 * set to a static description (an unknown command or option, a missing value). */
int batch_line_files_of(const job_line* line, int check_inputs, batch_line_files* files, const char** error);

/* `path` resolved against `directory` (a path that starts with / as it is),
 * newly allocated; NULL when out of memory. */
char* batch_files_absolute(const char* directory, const char* path);
/* Sorts file names bytewise, so listings come out the same on every machine. */
void batch_files_sort(char** names, size_t count);

#endif
