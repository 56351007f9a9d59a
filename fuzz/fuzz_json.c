/* libFuzzer target: the JSON reader of tools/ (tools/common/json.c) on
 * arbitrary bytes, cut at the first NUL as every caller's text is; every
 * string and key it returns is walked, and the tree freed. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/json.h"

/* Touches every node, as the callers do (json_get, json_get_string). */
static size_t walk(const json_value* value) {
    size_t bytes = 0;
    for (; value; value = value->next) {
        if (value->string) bytes += strlen(value->string);
        if (value->key) bytes += strlen(value->key) + (json_get(value, value->key) != NULL);
        bytes += walk(value->child);
    }
    return bytes;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    char* text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = 0;
    const char* error = NULL;
    size_t offset = 0;
    json_value* value = json_parse(text, &error, &offset);
    if (value) walk(value);
    else if (!error || offset > strlen(text)) abort(); /* a defect is always told, inside the text */
    json_free(value);
    free(text);
    return 0;
}
