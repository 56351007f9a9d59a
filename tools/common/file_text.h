/* file_text.h — a whole file read into memory as one NUL-terminated text:
 * what the programs in tools/ read whole (JSON reports and records, a drain
 * report's holes). Reads in doubling blocks from 64 KiB; the text may hold
 * NUL bytes of its own, which *size counts. */
#ifndef FABVDB_FILE_TEXT_H
#define FABVDB_FILE_TEXT_H

#include <stddef.h>

/* Reads the file at `path`. Returns the text (the caller frees it) with its
 * length in *size (NULL: not wanted), or NULL with errno set (ENOMEM when out
 * of memory). */
char* file_text_read(const char* path, size_t* size);

#endif
