/* studio_molded_test.c — tools/studio/studio_molded.c: the pieces the studio
 * asks for after "mold" are the files the mold report names, by part id.
 * Its report here is a fake: this program defines the three report
 * functions studio_molded.c calls (an executable's own definitions come
 * before libfabvdb's), over a JSON text read by tools/common/json.h, so any
 * report can be written down, among them one where a part vanished in the
 * sweep (ids 0 and 2, no 1) as the library writes it (src/api/mold_api.cpp:
 * parts/part_ID.stl, molds/part_ID_top.stl, molds/part_ID_bottom.stl). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi/check.h"
#include "common/json.h"
#include "studio/studio_molded.h"

struct fabvdb_report {
    json_value* root;
};

/* The value at a JSON pointer ("/parts/1/file"), or NULL. */
static const json_value* at(const fabvdb_report* report, const char* pointer) {
    const json_value* value = report->root;
    while (value && *pointer == '/') {
        ++pointer;
        const size_t length = strcspn(pointer, "/");
        char key[256];
        snprintf(key, sizeof key, "%.*s", (int)length, pointer);
        pointer += length;
        if (value->type == JSON_OBJECT) {
            value = json_get(value, key);
        } else if (value->type == JSON_ARRAY) {
            const json_value* element = value->child;
            for (long index = strtol(key, NULL, 10); element && index > 0; --index) element = element->next;
            value = element;
        } else {
            value = NULL;
        }
    }
    return value;
}

fabvdb_status fabvdb_report_count(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer, size_t* out) {
    (void)ctx;
    const json_value* value = at(report, pointer);
    if (!value || (value->type != JSON_ARRAY && value->type != JSON_OBJECT)) return FABVDB_ERR_NOT_FOUND;
    *out = value->count;
    return FABVDB_OK;
}

fabvdb_status fabvdb_report_number(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer, double* out) {
    (void)ctx;
    const json_value* value = at(report, pointer);
    if (!value || (value->type != JSON_NUMBER && value->type != JSON_BOOL)) return FABVDB_ERR_NOT_FOUND;
    *out = value->number;
    return FABVDB_OK;
}

fabvdb_status fabvdb_report_string(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer,
                                   const char** out) {
    (void)ctx;
    const json_value* value = at(report, pointer);
    if (!value || value->type != JSON_STRING) return FABVDB_ERR_NOT_FOUND;
    *out = value->string;
    return FABVDB_OK;
}

static int read_parts(const char* json, fabvdb_report* report, studio_molded_part** parts) {
    report->root = json_parse(json, NULL, NULL);
    CHECK(report->root != NULL);
    return studio_molded_parts(NULL, report, parts);
}

int main(void) {
    /* Part 1 vanished in the sweep: the report lists parts 0 and 2. */
    fabvdb_report report;
    studio_molded_part* parts = NULL;
    int count = read_parts(
        "{\"part_count\": 2, \"vanished_parts\": 1, \"parts\": ["
        "{\"id\": 0, \"file\": \"parts/part_00.stl\", \"top_file\": \"molds/part_00_top.stl\","
        " \"bottom_file\": \"molds/part_00_bottom.stl\", \"volume\": 1200.5, \"weight\": 1.32},"
        "{\"id\": 2, \"file\": \"parts/part_02.stl\", \"top_file\": \"molds/part_02_top.stl\","
        " \"bottom_file\": \"molds/part_02_bottom.stl\", \"volume\": 800, \"weight\": 0.88}]}",
        &report, &parts);
    CHECK(count == 2);
    if (count == 2) {
        CHECK(parts[0].id == 0 && parts[1].id == 2);
        CHECK(strcmp(parts[1].files[0], "parts/part_02.stl") == 0);
        CHECK(strcmp(parts[1].files[1], "molds/part_02_top.stl") == 0);
        CHECK(strcmp(parts[1].files[2], "molds/part_02_bottom.stl") == 0);
        CHECK(parts[0].volume == 1200.5 && parts[1].weight == 0.88);
    }
    free(parts);
    json_free(report.root);

    /* A common mold: each part names only its own file. */
    count = read_parts("{\"parts\": [{\"id\": 3, \"file\": \"parts/part_03.stl\", \"volume\": 5, \"weight\": 6}],"
                       " \"common_mold\": {\"top_file\": \"molds/common_top.stl\"}}",
                       &report, &parts);
    CHECK(count == 1 && parts[0].id == 3 && strcmp(parts[0].files[0], "parts/part_03.stl") == 0 &&
          parts[0].files[1] == NULL && parts[0].files[2] == NULL);
    free(parts);
    json_free(report.root);

    /* No parts, no array, and an entry without an id. */
    count = read_parts("{\"parts\": []}", &report, &parts);
    CHECK(count == 0 && parts == NULL);
    json_free(report.root);
    count = read_parts("{\"part_count\": 0}", &report, &parts);
    CHECK(count == 0 && parts == NULL);
    json_free(report.root);
    count = read_parts("{\"parts\": [{\"file\": \"parts/part_00.stl\"}, {\"id\": 1}]}", &report, &parts);
    CHECK(count == 1 && parts[0].id == 1 && parts[0].files[0] == NULL);
    free(parts);
    json_free(report.root);
    return check_summary();
}
