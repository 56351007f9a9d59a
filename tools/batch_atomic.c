/* batch_atomic.c — whole-or-nothing files (batch_atomic.h). */
#define _DEFAULT_SOURCE /* mkstemp, fsync, fchmod */
#include "batch_atomic.h"

#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int batch_atomic_open(batch_atomic* file, const char* path) {
    snprintf(file->path, sizeof file->path, "%s", path);
    snprintf(file->temp, sizeof file->temp, "%.8000s.partial-XXXXXX", path);
    const int fd = mkstemp(file->temp);
    if (fd < 0) return -1;
    fchmod(fd, 0644);
    file->out = fdopen(fd, "w");
    if (!file->out) {
        close(fd);
        unlink(file->temp);
        return -1;
    }
    return 0;
}

int batch_atomic_commit(batch_atomic* file) {
    int failed = ferror(file->out) != 0 || fflush(file->out) != 0 || fsync(fileno(file->out)) != 0;
    failed |= fclose(file->out) != 0;
    file->out = NULL;
    if (!failed) failed = rename(file->temp, file->path) != 0;
    if (failed) {
        unlink(file->temp);
        return -1;
    }
    char folder[8192];
    snprintf(folder, sizeof folder, "%s", file->path);
    char* slash = strrchr(folder, '/');
    if (slash) *slash = 0;
    const int folder_fd = open(slash ? (slash == folder ? "/" : folder) : ".", O_RDONLY | O_DIRECTORY);
    if (folder_fd >= 0) {
        fsync(folder_fd);
        close(folder_fd);
    }
    return 0;
}
