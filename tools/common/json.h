/* json.h — the JSON the programs in tools/ read and write themselves: a small
 * reader into a tree (batch: task records, the commands' --report files) and
 * writers for strings and numbers (batch records and summaries, the studio's
 * messages). The reader takes RFC 8259 text (\uXXXX escapes become UTF-8) up
 * to a nesting of 64, and reports the first defect with its byte offset; it
 * allocates one node per value and never reads past the text's final NUL
 * (fuzz/fuzz_json.c). Reports of the library are read through the C API
 * instead (fabvdb_report_*). */
#ifndef FABVDB_JSON_H
#define FABVDB_JSON_H

#include <stddef.h>
#include <stdio.h>

typedef enum json_type { JSON_NULL, JSON_BOOL, JSON_NUMBER, JSON_STRING, JSON_ARRAY, JSON_OBJECT } json_type;

typedef struct json_value {
    json_type type;
    double number;            /* JSON_NUMBER, and JSON_BOOL as 0 or 1 */
    char* string;             /* JSON_STRING */
    char* key;                /* the member's name inside an object, else NULL */
    struct json_value* child; /* first element or member */
    struct json_value* next;  /* next sibling */
    size_t count;             /* elements or members */
} json_value;

/* Parses `text`. Returns the tree (free with json_free), or NULL with a static
 * description of the defect in *error and its byte offset in *offset. */
json_value* json_parse(const char* text, const char** error, size_t* offset);
/* Reads and parses a whole file (file_text.h); NULL on a read or parse error
 * (*error says which, static text). */
json_value* json_read_file(const char* path, const char** error);
void json_free(json_value* value);

/* The member `key` of an object, or NULL (also for a non-object). */
const json_value* json_get(const json_value* object, const char* key);
/* The member's string, or `fallback` when it is missing or not a string. */
const char* json_get_string(const json_value* object, const char* key, const char* fallback);
/* The member's number, or `fallback` when it is missing or not a number. */
double json_get_number(const json_value* object, const char* key, double fallback);

/* Writes `text` as a JSON string (quoted; ", \\ and control characters
 * escaped); NULL writes null. The one escaper of tools/: a message built in
 * memory uses it through open_memstream. */
void json_write_string(FILE* out, const char* text);
/* Writes a number with 17 significant digits, or null when not finite. */
void json_write_number(FILE* out, double number);

#endif
