/* atomic_file.h — a file that appears at its path only whole: written to a
 * new temporary file in the same folder (PATH.partial-XXXXXX, mode 0644),
 * flushed to disk, renamed over PATH, and the folder flushed, so a kill or a
 * power loss leaves the old file or the new one, never a part. What every
 * program in tools/ writes goes through it: batch records, plans and
 * summaries, Slurm's task lists, and the CLI's --save-job files. A temporary
 * file a killed writer left behind is recognisable by ".partial-" in its
 * name. Costs two fsyncs per file. */
#ifndef FABVDB_ATOMIC_FILE_H
#define FABVDB_ATOMIC_FILE_H

#include <stdio.h>

#define ATOMIC_FILE_MAX_PATH 8192

typedef struct atomic_file {
    FILE* out; /* write here */
    char temp[ATOMIC_FILE_MAX_PATH];
    char path[ATOMIC_FILE_MAX_PATH];
} atomic_file;

/* Opens the temporary file for `path`. Returns 0, or -1 (errno set; nothing
 * is left on disk). */
int atomic_file_open(atomic_file* file, const char* path);
/* Flushes, renames into place and flushes the folder; on any failure
 * (including an earlier write error on `out`) removes the temporary file and
 * leaves PATH as it was. Returns 0, or -1. */
int atomic_file_commit(atomic_file* file);
/* Closes and removes the temporary file; PATH stays as it was. */
void atomic_file_abandon(atomic_file* file);

#endif
