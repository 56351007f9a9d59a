/* batch_atomic.h — a file written by batch (a record, the plan, the status)
 * that appears at its path only whole: written to a new temporary file in the
 * same folder (PATH.partial-XXXXXX), flushed to disk, renamed over PATH, and
 * the folder flushed, so a kill or a power loss leaves the old file or the
 * new one, never a part. Costs two fsyncs. */
#ifndef FABVDB_BATCH_ATOMIC_H
#define FABVDB_BATCH_ATOMIC_H

#include <stdio.h>

typedef struct batch_atomic {
    FILE* out; /* write here */
    char temp[8192];
    char path[8192];
} batch_atomic;

/* Opens the temporary file for `path`. Returns 0, or -1 (errno set). */
int batch_atomic_open(batch_atomic* file, const char* path);
/* Flushes, renames into place and flushes the folder; on any failure
 * removes the temporary file. Returns 0, or -1. */
int batch_atomic_commit(batch_atomic* file);

#endif
