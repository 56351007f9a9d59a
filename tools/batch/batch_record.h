/* batch_record.h — a task's record: the truth about one task, written by the
 * task itself when it ends, atomically (a temporary file in the same folder,
 * flushed to disk, renamed, the folder flushed), as STATE/tasks/NAME.json:
 * its command lines, status (done or failed), exit code, message, the line
 * that failed, start and end, peak memory, each line's threads and budget,
 * the SHA-256 of every input and output file, the report paths, the log.
 * A record is current when it says done, holds the plan's lines and every
 * file still has its hash: --resume skips exactly those tasks. */
#ifndef FABVDB_BATCH_RECORD_H
#define FABVDB_BATCH_RECORD_H

#include "batch_plan.h"
#include "batch_sha256.h"

#define BATCH_RECORD_FORMAT "fabvdb-batch-record 1"

typedef struct batch_file_hash {
    char* path;                              /* absolute */
    char sha256[BATCH_SHA256_HEX_LENGTH + 1]; /* empty when the file could not be read */
} batch_file_hash;

typedef struct batch_file_list {
    batch_file_hash* files;
    int count;
} batch_file_list;

typedef struct batch_line_result {
    int ran;
    int exit_code;          /* the child's exit code, or 128 + the signal that killed it */
    int signal;             /* the signal that killed it, or 0 */
    double started, ended;  /* seconds since the epoch */
    long peak_kib;          /* ru_maxrss of the child */
    int threads;            /* --threads it ran with (0: its own) */
    double max_memory;      /* the budget it ran under, bytes (0: its own) */
    int budget_retries;     /* refusals under a smaller share before this run */
} batch_line_result;

typedef struct batch_record {
    const batch_task* task;
    int done;
    int exit_code;
    char message[2048];
    int failed_line; /* index into task->lines, or -1 */
    double started, ended;
    batch_line_result* lines; /* task->line_count */
    batch_file_list inputs, outputs;
    char** reports;               /* absolute paths of the --report files written */
    const char** report_commands; /* the command that wrote each */
    int report_count;
    char log[4096];
    char host[256];
    char slurm_job[64]; /* ARRAYJOB_INDEX when run by Slurm, else empty */
} batch_record;

/* Adds `path` with its hash; a folder adds every file below it, sorted.
 * A missing path adds nothing. Returns 0, or -1 when out of memory. */
int batch_file_list_add(batch_file_list* list, const char* path);
int batch_file_list_has(const batch_file_list* list, const char* path);
void batch_file_list_free(batch_file_list* list);

/* The record's path for task `name` in `state` (STATE/tasks/NAME.json). */
void batch_record_path(const char* state, const char* name, char* path, size_t size);
/* Writes the record atomically to `path`. Returns 0, or -1 (errno set). */
int batch_record_write(const batch_record* record, const char* path);
/* Whether the record at `path` is current for `task`; if not, *why says why
 * (static text: no record, failed, lines changed, a file changed...). */
int batch_record_current(const char* path, const batch_task* task, const char** why);

/* Seconds since the epoch, with microseconds. */
double batch_now(void);
/* Writes a time as ISO 8601 UTC with milliseconds (2026-11-27T04:00:00.000Z). */
void batch_format_time(double seconds, char* text, size_t size);

#endif
