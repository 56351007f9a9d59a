/* status_text.c — "<status>: <message>" (status_text.h). */
#include "status_text.h"

#include <stdarg.h>
#include <stdio.h>

void status_vtext(char* out, size_t size, fabvdb_status status, const char* format, va_list args) {
    if (size == 0) return;
    const int prefix = snprintf(out, size, "%s: ", fabvdb_status_string(status));
    if (prefix < 0 || (size_t)prefix >= size) return;
    vsnprintf(out + prefix, size - (size_t)prefix, format, args);
}

void status_text(char* out, size_t size, fabvdb_status status, const char* format, ...) {
    va_list args;
    va_start(args, format);
    status_vtext(out, size, status, format, args);
    va_end(args);
}

void status_print(const char* program, fabvdb_status status, const char* format, ...) {
    fprintf(stderr, "fabvdb %s: %s: ", program, fabvdb_status_string(status));
    va_list args;
    va_start(args, format);
    vfprintf(stderr, format, args);
    va_end(args);
    fputc('\n', stderr);
}
