/* json_test.c — tools/common/json.c: the reader on every kind of value,
 * escapes (\uXXXX and surrogate pairs to UTF-8), each defect with its byte
 * offset, the nesting bound; the writers' strings and numbers read back by
 * the reader; json_read_file. */
#define _GNU_SOURCE /* open_memstream, mkdtemp, nftw */
#include <math.h>

#include "capi/check.h"
#include "common/json.h"
#include "tools/temp_folder.h"

/* The defect and its offset of text that must not parse. */
static void check_defect(const char* text, const char* wanted, size_t wanted_offset) {
    const char* error = NULL;
    size_t offset = 0;
    json_value* value = json_parse(text, &error, &offset);
    CHECK(value == NULL);
    CHECK(error && strcmp(error, wanted) == 0);
    CHECK(offset == wanted_offset);
    if (!error || strcmp(error, wanted) != 0 || offset != wanted_offset)
        fprintf(stderr, "  %s: got '%s' at %zu\n", text, error ? error : "(none)", offset);
    json_free(value);
}

/* What json_write_string writes for text, parsed back. */
static void check_round_trip(const char* text) {
    char* written = NULL;
    size_t size = 0;
    FILE* out = open_memstream(&written, &size);
    json_write_string(out, text);
    fclose(out);
    json_value* value = json_parse(written, NULL, NULL);
    CHECK(value && value->type == JSON_STRING && strcmp(value->string, text) == 0);
    json_free(value);
    free(written);
}

static void check_number_text(double number, const char* wanted) {
    char* written = NULL;
    size_t size = 0;
    FILE* out = open_memstream(&written, &size);
    json_write_number(out, number);
    fclose(out);
    CHECK(strcmp(written, wanted) == 0);
    free(written);
}

int main(void) {
    const char* error = NULL;
    json_value* v = json_parse(" {\"a\": [1, -2.5e3, true, false, null], \"b\": {\"c\": \"d\"}, \"e\": \"\"} ", &error,
                               NULL);
    CHECK(v && v->type == JSON_OBJECT && v->count == 3);
    const json_value* a = json_get(v, "a");
    CHECK(a && a->type == JSON_ARRAY && a->count == 5);
    CHECK(a->child->type == JSON_NUMBER && a->child->number == 1);
    CHECK(a->child->next->number == -2500);
    CHECK(a->child->next->next->type == JSON_BOOL && a->child->next->next->number == 1);
    CHECK(a->child->next->next->next->type == JSON_BOOL && a->child->next->next->next->number == 0);
    CHECK(a->child->next->next->next->next->type == JSON_NULL);
    CHECK(strcmp(json_get_string(json_get(v, "b"), "c", "?"), "d") == 0);
    CHECK(strcmp(json_get_string(v, "e", "?"), "") == 0);
    CHECK(strcmp(json_get_string(v, "a", "fallback"), "fallback") == 0); /* not a string */
    CHECK(json_get_number(v, "missing", 7) == 7);
    CHECK(json_get(a, "x") == NULL); /* not an object */
    CHECK(json_get(NULL, "x") == NULL);
    json_free(v);

    /* Escapes: the short ones, \u to UTF-8 (1 to 3 bytes), a surrogate pair to 4. */
    v = json_parse("\"q\\\" b\\\\ s\\/ \\b\\f\\n\\r\\t \\u0041\\u00e9\\u20ac\\ud83d\\ude00\"", &error, NULL);
    CHECK(v && v->type == JSON_STRING);
    CHECK(v && strcmp(v->string, "q\" b\\ s/ \b\f\n\r\t A\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80") == 0);
    json_free(v);

    /* Defects and where they are. */
    check_defect("", "unexpected end of the text", 0);
    check_defect("[1, 2", "expected ',' or ']'", 5);
    check_defect("{\"a\" 1}", "expected ':' after a member name", 5);
    check_defect("{1: 2}", "expected a member name in quotes", 1);
    check_defect("\"open", "a string is not closed", 1);
    check_defect("\"tab\there\"", "a control character inside a string", 5);
    check_defect("\"\\x\"", "a bad escape in a string", 3);
    check_defect("\"\\u12g4\"", "a bad \\u escape", 3);
    check_defect("\"\\ud83d\\u0041\"", "a bad surrogate pair", 13);
    check_defect("[1] 2", "text after the end of the value", 4);
    check_defect("-", "a bad number", 0);
    check_defect("tru", "unexpected character", 0);

    /* Nesting: 64 levels are taken, 65 are not. */
    char deep[200];
    memset(deep, '[', 64);
    memset(deep + 64, ']', 64);
    deep[128] = 0;
    v = json_parse(deep, &error, NULL);
    CHECK(v != NULL);
    json_free(v);
    memset(deep, '[', 65);
    memset(deep + 65, ']', 65);
    deep[130] = 0;
    check_defect(deep, "nested too deep", 64);

    /* The writers, read back. */
    check_round_trip("plain");
    check_round_trip("quote \" backslash \\ newline \n tab \t bell \a nul-free \x1f end");
    check_round_trip("UTF-8 stays as it is: \xc3\xa9\xe2\x82\xac");
    check_number_text(3, "3");
    check_number_text(-12345678901234.0, "-12345678901234");
    check_number_text(0.1, "0.10000000000000001");
    check_number_text(NAN, "null");
    check_number_text(INFINITY, "null");
    char* written = NULL;
    size_t size = 0;
    FILE* out = open_memstream(&written, &size);
    json_write_string(out, NULL);
    fclose(out);
    CHECK(strcmp(written, "null") == 0);
    free(written);

    char folder[4096], path[4096];
    CHECK(temp_folder_make(folder) == 0);
    CHECK(temp_write(temp_path(path, folder, "r.json"), "{\"status\": \"done\", \"exit_code\": 0}\n") == 0);
    v = json_read_file(path, &error);
    CHECK(v && strcmp(json_get_string(v, "status", ""), "done") == 0 && json_get_number(v, "exit_code", -1) == 0);
    json_free(v);
    error = NULL;
    CHECK(json_read_file(temp_path(path, folder, "missing.json"), &error) == NULL && error != NULL);
    CHECK(temp_write(temp_path(path, folder, "bad.json"), "{\"status\": ") == 0);
    error = NULL;
    CHECK(json_read_file(path, &error) == NULL && error && strcmp(error, "unexpected end of the text") == 0);
    temp_folder_remove(folder);
    return check_summary();
}
