/* atomic_file.c — whole-or-nothing files (atomic_file.h). */
#define _DEFAULT_SOURCE /* mkstemp, fsync, fchmod */
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int atomic_file_open(atomic_file* file, const char* path) {
    file->out = NULL;
    if (strlen(path) + sizeof ".partial-XXXXXX" > sizeof file->temp) {
        errno = ENAMETOOLONG;
        return -1;
    }
    snprintf(file->path, sizeof file->path, "%s", path);
    snprintf(file->temp, sizeof file->temp, "%s.partial-XXXXXX", path);
    const int fd = mkstemp(file->temp);
    if (fd < 0) return -1;
    fchmod(fd, 0644);
    file->out = fdopen(fd, "w");
    if (!file->out) {
        const int error = errno;
        close(fd);
        unlink(file->temp);
        errno = error;
        return -1;
    }
    return 0;
}

void atomic_file_abandon(atomic_file* file) {
    if (!file->out) return;
    fclose(file->out);
    file->out = NULL;
    unlink(file->temp);
}

int atomic_file_commit(atomic_file* file) {
    if (!file->out) return -1;
    int failed = ferror(file->out) != 0 || fflush(file->out) != 0 || fsync(fileno(file->out)) != 0;
    failed |= fclose(file->out) != 0;
    file->out = NULL;
    if (!failed) failed = rename(file->temp, file->path) != 0;
    if (failed) {
        unlink(file->temp);
        return -1;
    }
    char folder[ATOMIC_FILE_MAX_PATH];
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
