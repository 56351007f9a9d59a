/* box_mesh.h — shapes and measures shared by the C API tests (fabvdb.h
 * only): an axis-aligned box as a fabvdb_mesh (8 vertices, 12 outward
 * triangles, or without its bottom face: 10), two boxes as one mesh (16
 * vertices, 24 triangles, the first box's first), the signed volume of a mesh by
 * the divergence theorem, and a report's number at a JSON pointer (NAN when
 * the look-up fails). */
#ifndef FABVDB_TEST_BOX_MESH_H
#define FABVDB_TEST_BOX_MESH_H

#include <math.h>

#include "fabvdb.h"

/* Corner i of the box is (i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo);
 * the bottom face (z = lo) comes first. */
static const uint32_t box_triangles[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                         2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};

static inline void box_corners(const double lo[3], const double hi[3], double corners[24]) {
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) corners[3 * i + k] = (i >> k) & 1 ? hi[k] : lo[k];
}

/* The box from lo to hi; with `open`, without its two bottom triangles. NULL on failure. */
static inline fabvdb_mesh* new_box(fabvdb_ctx* ctx, const double lo[3], const double hi[3], int open) {
    double corners[24];
    box_corners(lo, hi, corners);
    fabvdb_mesh* mesh = NULL;
    if (fabvdb_mesh_new(ctx, corners, 8, open ? box_triangles + 6 : box_triangles, open ? 10 : 12, &mesh) != FABVDB_OK)
        return NULL;
    return mesh;
}

/* Boxes a (lo_a to hi_a) and b as one mesh. NULL on failure. */
static inline fabvdb_mesh* new_two_boxes(fabvdb_ctx* ctx, const double lo_a[3], const double hi_a[3],
                                         const double lo_b[3], const double hi_b[3]) {
    double corners[48];
    box_corners(lo_a, hi_a, corners);
    box_corners(lo_b, hi_b, corners + 24);
    uint32_t triangles[72];
    for (int i = 0; i < 36; ++i) {
        triangles[i] = box_triangles[i];
        triangles[36 + i] = box_triangles[i] + 8;
    }
    fabvdb_mesh* mesh = NULL;
    if (fabvdb_mesh_new(ctx, corners, 16, triangles, 24, &mesh) != FABVDB_OK) return NULL;
    return mesh;
}

static inline double mesh_signed_volume(const fabvdb_mesh* mesh) {
    const double* v = fabvdb_mesh_vertices(mesh);
    const uint32_t* t = fabvdb_mesh_triangles(mesh);
    double six_volume = 0;
    for (size_t i = 0; i < fabvdb_mesh_triangle_count(mesh); ++i) {
        const double* a = v + 3 * t[3 * i];
        const double* b = v + 3 * t[3 * i + 1];
        const double* c = v + 3 * t[3 * i + 2];
        six_volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return six_volume / 6.0;
}

static inline double report_value(fabvdb_ctx* ctx, const fabvdb_report* report, const char* pointer) {
    double value = NAN;
    if (fabvdb_report_number(ctx, report, pointer, &value) != FABVDB_OK) return NAN;
    return value;
}

#endif
