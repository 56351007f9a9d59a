/* status_text.h — the error text of the programs in tools/: a failure is
 * told as "<status>: <message>", <status> being fabvdb_status_string's words
 * for the status ("input/output error", "bad input", "internal error"...), so
 * a message from a program reads like one from the library and every program
 * spells a status the same way; printed, it is prefixed "fabvdb PROGRAM: ". */
#ifndef FABVDB_STATUS_TEXT_H
#define FABVDB_STATUS_TEXT_H

#include <stdarg.h>
#include <stddef.h>

#include "fabvdb.h"

/* Writes "<status>: <message>" into out (truncated to size, always ended). */
void status_text(char* out, size_t size, fabvdb_status status, const char* format, ...)
    __attribute__((format(printf, 4, 5)));
/* The same with the message's arguments as a va_list. */
void status_vtext(char* out, size_t size, fabvdb_status status, const char* format, va_list args);
/* Prints "fabvdb <program>: <status>: <message>" and a newline on stderr. */
void status_print(const char* program, fabvdb_status status, const char* format, ...)
    __attribute__((format(printf, 3, 4)));

#endif
