/* studio_molded.h — the parts a mold report lists, as the studio sends them
 * to the page after "mold": each part's id and the files of its three pieces
 * exactly as the report names them (parts[i].id, .file, .top_file,
 * .bottom_file, relative to the molds folder), with its volume and weight.
 * The ids are the decomposition's part ids: a part that vanished in the sweep
 * is absent from the report, so the ids may skip one, and the files carry
 * the part's id, never its place in the list. Read through the report API
 * (fabvdb_report_count, _number, _string) only. */
#ifndef FABVDB_STUDIO_MOLDED_H
#define FABVDB_STUDIO_MOLDED_H

#include "fabvdb.h"

typedef struct studio_molded_part {
    int id;               /* parts[i].id */
    const char* files[3]; /* by role as the page numbers them (0 the part, 1 the top mold,
                             2 the bottom mold): parts[i].file, .top_file, .bottom_file, or NULL
                             when the report names none (a common mold); point into the report */
    double volume;        /* mm^3 */
    double weight;        /* g */
} studio_molded_part;

/* Reads parts[] of a mold report (none when it has no such array). Returns
 * the part count with *parts a new array the caller frees (NULL for none),
 * or -1 when out of memory. A part without an id is left out. */
int studio_molded_parts(fabvdb_ctx* ctx, const fabvdb_report* report, studio_molded_part** parts);

#endif
