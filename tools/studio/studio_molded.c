/* studio_molded.c — the parts of a mold report (studio_molded.h). */
#include "studio_molded.h"

#include <stdio.h>
#include <stdlib.h>

int studio_molded_parts(fabvdb_ctx* ctx, const fabvdb_report* report, studio_molded_part** parts) {
    *parts = NULL;
    size_t listed = 0;
    if (fabvdb_report_count(ctx, report, "/parts", &listed) != FABVDB_OK || listed == 0) return 0;
    studio_molded_part* out = calloc(listed, sizeof *out);
    if (!out) return -1;
    static const char* const file_keys[3] = {"file", "top_file", "bottom_file"};
    int count = 0;
    for (size_t i = 0; i < listed; ++i) {
        char key[96];
        double id = 0;
        snprintf(key, sizeof key, "/parts/%zu/id", i);
        if (fabvdb_report_number(ctx, report, key, &id) != FABVDB_OK) continue;
        studio_molded_part* part = &out[count++];
        part->id = (int)id;
        for (int role = 0; role < 3; ++role) {
            snprintf(key, sizeof key, "/parts/%zu/%s", i, file_keys[role]);
            if (fabvdb_report_string(ctx, report, key, &part->files[role]) != FABVDB_OK) part->files[role] = NULL;
        }
        snprintf(key, sizeof key, "/parts/%zu/volume", i);
        fabvdb_report_number(ctx, report, key, &part->volume);
        snprintf(key, sizeof key, "/parts/%zu/weight", i);
        fabvdb_report_number(ctx, report, key, &part->weight);
    }
    *parts = out;
    return count;
}
