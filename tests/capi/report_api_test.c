/* report_api_test.c — reports through fabvdb.h only, on the inspection of
 * boxes whose figures are known (a closed 10 × 20 × 30 box, the same box
 * open at the bottom) and the repair report of a clean box: numbers at JSON
 * pointers (booleans as 0/1, array elements), null and non-numbers not found,
 * strings that point into the report, element counts (the whole report's
 * keys counted here in its text), malformed pointers and NULL arguments as
 * invalid arguments with a message, and the atomic write: the file holds the
 * report's text, replaces an older file, leaves nothing else behind, and a
 * missing folder is an I/O error naming the path. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "box_mesh.h"
#include "check.h"
#include "fabvdb.h"

static const double lo[3] = {0, 0, 0}, hi[3] = {10, 20, 30};

static fabvdb_report* inspection_of(fabvdb_ctx* ctx, int open) {
    fabvdb_mesh* mesh = new_box(ctx, lo, hi, open);
    fabvdb_report* report = NULL;
    CHECK(mesh != NULL && fabvdb_mesh_inspect(ctx, mesh, &report) == FABVDB_OK);
    fabvdb_mesh_free(mesh);
    return report;
}

/* Top-level keys of pretty-printed JSON text: lines indented by exactly two spaces and a quote. */
static size_t top_level_keys(const char* text) {
    size_t count = 0;
    for (const char* line = text; line; line = strchr(line, '\n')) {
        if (*line == '\n') ++line;
        if (strncmp(line, "  \"", 3) == 0) ++count;
    }
    return count;
}

static char* read_file(const char* path) {
    FILE* file = fopen(path, "rb");
    if (!file) return NULL;
    fseek(file, 0, SEEK_END);
    const long size = ftell(file);
    fseek(file, 0, SEEK_SET);
    char* text = calloc((size_t)size + 1, 1);
    if (fread(text, 1, (size_t)size, file) != (size_t)size) text[0] = '\0';
    fclose(file);
    return text;
}

static int entries_in(const char* folder) {
    DIR* dir = opendir(folder);
    int count = 0;
    for (struct dirent* entry; dir && (entry = readdir(dir));)
        if (strcmp(entry->d_name, ".") != 0 && strcmp(entry->d_name, "..") != 0) ++count;
    if (dir) closedir(dir);
    return count;
}

static void test_numbers(fabvdb_ctx* ctx) {
    fabvdb_report* closed = inspection_of(ctx, 0);
    fabvdb_report* open = inspection_of(ctx, 1);
    CHECK(report_value(ctx, closed, "/closed") == 1.0); /* a boolean */
    CHECK(report_value(ctx, open, "/closed") == 0.0);
    CHECK(report_value(ctx, closed, "/triangles") == 12 && report_value(ctx, open, "/triangles") == 10);
    CHECK(fabs(report_value(ctx, closed, "/volume") - 6000.0) < 1e-9);
    CHECK(report_value(ctx, open, "/boundary_edges") == 4 && report_value(ctx, open, "/boundary_loops") == 1);
    CHECK(report_value(ctx, closed, "/bbox/max/1") == 20 && report_value(ctx, closed, "/bbox/max/2") == 30);

    double value = -7;
    /* The open box's volume is null: not found, and *out untouched. */
    CHECK(fabvdb_report_number(ctx, open, "/volume", &value) == FABVDB_ERR_NOT_FOUND && value == -7);
    CHECK(strstr(fabvdb_last_error(ctx), "/volume") != NULL);
    CHECK(fabvdb_report_number(ctx, closed, "/bbox", &value) == FABVDB_ERR_NOT_FOUND);
    CHECK(strstr(fabvdb_last_error(ctx), "not a number") != NULL);
    CHECK(fabvdb_report_number(ctx, closed, "/bbox/max/3", &value) == FABVDB_ERR_NOT_FOUND);
    CHECK(fabvdb_report_number(ctx, closed, "volume", &value) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "not a JSON pointer: volume") != NULL);
    CHECK(fabvdb_report_number(ctx, closed, "/volume", NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "out is NULL") != NULL);
    CHECK(fabvdb_report_number(ctx, NULL, "/volume", &value) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "report is NULL") != NULL);
    CHECK(fabvdb_report_number(ctx, closed, NULL, &value) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_report_number(NULL, closed, "/volume", &value) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(value == -7);
    CHECK(fabvdb_report_number(ctx, closed, "/volume", &value) == FABVDB_OK);
    CHECK(strcmp(fabvdb_last_error(ctx), "") == 0); /* a success clears the message */
    fabvdb_report_free(closed);
    fabvdb_report_free(open);
}

static void test_counts_and_text(fabvdb_ctx* ctx) {
    fabvdb_report* report = inspection_of(ctx, 0);
    const char* text = fabvdb_report_json(report);
    CHECK(text != NULL && text[0] == '{');
    size_t count = 0;
    CHECK(fabvdb_report_count(ctx, report, "", &count) == FABVDB_OK);
    CHECK(count == top_level_keys(text) && count > 10);
    CHECK(fabvdb_report_count(ctx, report, "/bbox", &count) == FABVDB_OK && count == 2);
    CHECK(fabvdb_report_count(ctx, report, "/bbox/max", &count) == FABVDB_OK && count == 3);
    count = 99;
    CHECK(fabvdb_report_count(ctx, report, "/closed", &count) == FABVDB_ERR_NOT_FOUND && count == 99);
    CHECK(strstr(fabvdb_last_error(ctx), "neither an array nor an object") != NULL);
    CHECK(fabvdb_report_count(ctx, report, "/bbox/~2", &count) == FABVDB_ERR_INVALID_ARGUMENT); /* bad escape */
    fabvdb_report_free(report);
}

static void test_strings(fabvdb_ctx* ctx) {
    /* A clean solid is repaired as it is: path "input". */
    fabvdb_mesh* box = new_box(ctx, lo, hi, 0);
    fabvdb_mesh* repaired = NULL;
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_repair(ctx, box, NULL, &repaired, &report) == FABVDB_OK);
    const char* path = NULL;
    CHECK(fabvdb_report_string(ctx, report, "/path", &path) == FABVDB_OK && path != NULL);
    CHECK(path != NULL && strcmp(path, "input") == 0);
    /* It points into the report's own document: the same address each time. */
    const char* again = NULL;
    CHECK(fabvdb_report_string(ctx, report, "/path", &again) == FABVDB_OK && again == path);
    const char* untouched = "untouched";
    CHECK(fabvdb_report_string(ctx, report, "/mesh_level", &untouched) == FABVDB_ERR_NOT_FOUND);
    CHECK(strstr(fabvdb_last_error(ctx), "not a string") != NULL);
    CHECK(fabvdb_report_string(ctx, report, "/no_such_key", &untouched) == FABVDB_ERR_NOT_FOUND);
    CHECK(strcmp(untouched, "untouched") == 0);
    CHECK(fabvdb_report_string(ctx, report, "/path", NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_report_free(report);
    fabvdb_mesh_free(repaired);
    fabvdb_mesh_free(box);
}

static void test_write(fabvdb_ctx* ctx) {
    fabvdb_report* report = inspection_of(ctx, 1);
    char dir[] = "/tmp/fabvdb_report_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[256];
    snprintf(path, sizeof path, "%s/report.json", dir);
    FILE* old = fopen(path, "w");
    CHECK(old != NULL);
    if (old) {
        fputs("an older file, longer than nothing", old);
        fclose(old);
    }
    CHECK(fabvdb_report_write(ctx, report, path) == FABVDB_OK);
    char* written = read_file(path);
    CHECK(written != NULL && strcmp(written, fabvdb_report_json(report)) == 0);
    free(written);
    CHECK(entries_in(dir) == 1); /* no temporary file left */

    char missing[300];
    snprintf(missing, sizeof missing, "%s/no/such/folder/report.json", dir);
    CHECK(fabvdb_report_write(ctx, report, missing) == FABVDB_ERR_IO);
    CHECK(strstr(fabvdb_last_error(ctx), missing) != NULL);
    CHECK(fabvdb_report_write(ctx, report, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_report_write(ctx, NULL, path) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(entries_in(dir) == 1);
    remove(path);
    rmdir(dir);
    fabvdb_report_free(report);
}

int main(void) {
    fabvdb_ctx* ctx = NULL;
    if (fabvdb_ctx_new(&ctx) != FABVDB_OK) return 1;
    test_numbers(ctx);
    test_counts_and_text(ctx);
    test_strings(ctx);
    test_write(ctx);
    fabvdb_ctx_free(ctx);
    return check_summary();
}
