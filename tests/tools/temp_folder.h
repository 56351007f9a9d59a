/* temp_folder.h — a fresh folder for one test program of tests/tools
 * (mkdtemp under $TMPDIR or /tmp), its files written and read back as text,
 * stderr caught in a file, and the folder removed with everything in it at
 * the end. A test that
 * includes it defines _GNU_SOURCE (mkdtemp, nftw) before any include. */
#ifndef FABVDB_TESTS_TEMP_FOLDER_H
#define FABVDB_TESTS_TEMP_FOLDER_H

#include <dirent.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Creates the folder into `folder` (at least 4096 bytes); 0, or -1. */
static inline int temp_folder_make(char* folder) {
    const char* root = getenv("TMPDIR");
    snprintf(folder, 4096, "%s/fabvdb-tools-XXXXXX", root && *root ? root : "/tmp");
    return mkdtemp(folder) ? 0 : -1;
}

/* `folder`/`name` into path (4096 bytes). */
static inline const char* temp_path(char* path, const char* folder, const char* name) {
    const size_t a = strlen(folder), b = strlen(name);
    if (a + b + 2 > 4096) abort(); /* a test's own paths are short */
    memcpy(path, folder, a);
    path[a] = '/';
    memcpy(path + a + 1, name, b + 1);
    return path;
}

/* Writes text to the file at path; 0, or -1. */
static inline int temp_write(const char* path, const char* text) {
    FILE* out = fopen(path, "wb");
    if (!out) return -1;
    const int failed = fputs(text, out) < 0;
    return fclose(out) != 0 || failed ? -1 : 0;
}

/* The file's text (up to size - 1 bytes) into text; 0, or -1 when unreadable. */
static inline int temp_read(const char* path, char* text, size_t size) {
    FILE* in = fopen(path, "rb");
    if (!in) return -1;
    const size_t got = fread(text, 1, size - 1, in);
    text[got] = 0;
    fclose(in);
    return 0;
}

static inline int remove_entry(const char* path, const struct stat* info, int type, struct FTW* where) {
    (void)info, (void)type, (void)where;
    return remove(path);
}

static inline void temp_folder_remove(const char* folder) { nftw(folder, remove_entry, 16, FTW_DEPTH | FTW_PHYS); }

/* Sends stderr into the file at path until temp_stderr_end(the returned
 * descriptor); -1 when it cannot. */
static inline int temp_stderr_begin(const char* path) {
    fflush(stderr);
    const int saved = dup(STDERR_FILENO);
    if (saved < 0 || !freopen(path, "w", stderr)) return -1;
    return saved;
}

static inline void temp_stderr_end(int saved) {
    fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
}

/* The number of entries in folder whose name holds `part`, or -1. */
static inline int temp_count(const char* folder, const char* part) {
    DIR* listing = opendir(folder);
    if (!listing) return -1;
    int count = 0;
    struct dirent* entry;
    while ((entry = readdir(listing)))
        if (strstr(entry->d_name, part)) ++count;
    closedir(listing);
    return count;
}

#endif
