/* file_text_test.c — tools/common/file_text.c: whole files of any size (past
 * its first 64 KiB block), empty ones, NUL bytes counted in the size, and a
 * missing file as NULL with errno. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include <errno.h>

#include "capi/check.h"
#include "common/file_text.h"
#include "tools/temp_folder.h"

#include <errno.h>

int main(void) {
    char folder[4096], path[4096];
    CHECK(temp_folder_make(folder) == 0);

    size_t size = 1;
    CHECK(temp_write(temp_path(path, folder, "empty"), "") == 0);
    char* text = file_text_read(path, &size);
    CHECK(text && size == 0 && text[0] == 0);
    free(text);

    /* 200 000 bytes: three doublings of the buffer. */
    const size_t big = 200000;
    char* pattern = malloc(big + 1);
    for (size_t i = 0; i < big; ++i) pattern[i] = (char)('a' + i % 26);
    pattern[big] = 0;
    CHECK(temp_write(temp_path(path, folder, "big"), pattern) == 0);
    text = file_text_read(path, &size);
    CHECK(text && size == big && memcmp(text, pattern, big) == 0 && text[big] == 0);
    free(text);
    free(pattern);

    /* Exactly one block less its final NUL: the edge of the first growth. */
    const size_t edge = ((size_t)1 << 16) - 1;
    pattern = malloc(edge + 1);
    memset(pattern, 'x', edge);
    pattern[edge] = 0;
    CHECK(temp_write(temp_path(path, folder, "edge"), pattern) == 0);
    text = file_text_read(path, NULL);
    CHECK(text && strlen(text) == edge);
    free(text);
    free(pattern);

    FILE* out = fopen(temp_path(path, folder, "nul"), "wb");
    fwrite("a\0b", 1, 3, out);
    fclose(out);
    text = file_text_read(path, &size);
    CHECK(text && size == 3 && text[0] == 'a' && text[1] == 0 && text[2] == 'b');
    free(text);

    errno = 0;
    CHECK(file_text_read(temp_path(path, folder, "missing"), &size) == NULL && errno == ENOENT);

    temp_folder_remove(folder);
    return check_summary();
}
