/* file_text.c — reading a whole file (file_text.h). */
#include "file_text.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

char* file_text_read(const char* path, size_t* size) {
    FILE* in = fopen(path, "rb");
    if (!in) return NULL;
    size_t capacity = (size_t)1 << 16, length = 0, got;
    char* text = malloc(capacity);
    while (text && (got = fread(text + length, 1, capacity - length - 1, in)) > 0) {
        length += got;
        if (length + 1 < capacity) continue;
        char* bigger = realloc(text, capacity * 2);
        if (!bigger) {
            free(text);
            text = NULL;
            break;
        }
        text = bigger;
        capacity *= 2;
    }
    const int failed = ferror(in);
    fclose(in);
    if (!text || failed) {
        const int error = text ? EIO : ENOMEM;
        free(text);
        errno = error;
        return NULL;
    }
    text[length] = 0;
    if (size) *size = length;
    return text;
}
