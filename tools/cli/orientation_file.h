/* orientation_file.h — the `--orientations all|FILE` value shared by `fabvdb
 * drain` and `fabvdb powder-sim`: "all" means the library's default set (the
 * 162 icosphere directions); FILE lists gravity directions, one "x y z" per
 * line ('#' starts a comment, blank lines are skipped). */
#ifndef FABVDB_ORIENTATION_FILE_H
#define FABVDB_ORIENTATION_FILE_H

#include <stddef.h>

#include "cli.h"

/* Reads the orientations named by `spec` into *values (3 doubles each,
 * malloc'ed, free() them; NULL for "all") and *count. Returns CLI_EXIT_OK, or
 * prints "fabvdb <cmd>: ..." naming the file, line and defect and returns
 * CLI_EXIT_BAD_INPUT (or CLI_EXIT_USAGE for an unreadable file name). */
int cli_read_orientations(const cli_run* run, const char* spec, double** values, size_t* count);

#endif
