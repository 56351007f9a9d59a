/* atomic_file_test.c — tools/common/atomic_file.c: a committed file is whole
 * at its path with nothing else left beside it; an abandoned one or one
 * whose commit fails leaves the old file as it was; an impossible path is
 * refused at open. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include <errno.h>

#include "capi/check.h"
#include "common/atomic_file.h"
#include "tools/temp_folder.h"

#include <sys/stat.h>

int main(void) {
    char folder[4096], path[4096], text[256];
    CHECK(temp_folder_make(folder) == 0);
    temp_path(path, folder, "record.json");

    atomic_file file;
    CHECK(atomic_file_open(&file, path) == 0);
    CHECK(strstr(file.temp, "record.json.partial-") != NULL);
    fputs("first", file.out);
    CHECK(access(path, F_OK) != 0); /* nothing at the path before the commit */
    CHECK(atomic_file_commit(&file) == 0);
    CHECK(temp_read(path, text, sizeof text) == 0 && strcmp(text, "first") == 0);
    CHECK(temp_count(folder, ".partial-") == 0);
    struct stat info;
    CHECK(stat(path, &info) == 0 && (info.st_mode & 0777) == 0644);

    /* Replacing: the old text stays until the commit. */
    CHECK(atomic_file_open(&file, path) == 0);
    fputs("second, longer", file.out);
    CHECK(temp_read(path, text, sizeof text) == 0 && strcmp(text, "first") == 0);
    CHECK(atomic_file_commit(&file) == 0);
    CHECK(temp_read(path, text, sizeof text) == 0 && strcmp(text, "second, longer") == 0);

    /* Abandoned: the path keeps its text, the temporary file is gone. */
    CHECK(atomic_file_open(&file, path) == 0);
    fputs("never", file.out);
    atomic_file_abandon(&file);
    CHECK(file.out == NULL);
    CHECK(temp_read(path, text, sizeof text) == 0 && strcmp(text, "second, longer") == 0);
    CHECK(temp_count(folder, ".partial-") == 0);

    /* A commit that cannot rename (the path is a folder) fails whole. */
    char blocked[4096];
    temp_path(blocked, folder, "a-folder");
    CHECK(mkdir(blocked, 0755) == 0);
    CHECK(atomic_file_open(&file, blocked) == 0);
    fputs("x", file.out);
    CHECK(atomic_file_commit(&file) == -1);
    CHECK(temp_count(folder, ".partial-") == 0);
    CHECK(stat(blocked, &info) == 0 && S_ISDIR(info.st_mode));

    /* A folder that does not exist is refused at open, leaving nothing. */
    temp_path(path, folder, "missing/record.json");
    CHECK(atomic_file_open(&file, path) == -1);
    CHECK(file.out == NULL);

    /* A path too long for the temporary name is refused. */
    char long_path[ATOMIC_FILE_MAX_PATH + 16];
    memset(long_path, 'a', sizeof long_path - 1);
    long_path[sizeof long_path - 1] = 0;
    CHECK(atomic_file_open(&file, long_path) == -1 && errno == ENAMETOOLONG);

    temp_folder_remove(folder);
    return check_summary();
}
