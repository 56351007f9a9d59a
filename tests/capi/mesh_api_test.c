/* mesh_api_test.c — mesh handles through fabvdb.h only, against figures
 * worked out by hand: empty arrays are a valid empty mesh; an index out of
 * range or an infinite coordinate is bad input naming the defect; scaling by
 * 2 doubles every coordinate and multiplies the volume (divergence theorem,
 * computed here) by 8, and refuses a factor that is not a positive number;
 * an ASCII STL written here has its 36 corners welded to the box's 8, in any
 * case of extension; an OBJ quad is fanned into two triangles of the quad's
 * area; an unknown extension and a folder are refused naming the file; a
 * mesh the caller made is written as it is, even open; the inspection counts
 * two disjoint boxes as two closed components of the summed volume. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "box_mesh.h"
#include "check.h"
#include "fabvdb.h"

static const double lo[3] = {0, 0, 0}, hi[3] = {10, 20, 30};

static char folder[] = "/tmp/fabvdb_mesh_api_XXXXXX";

static const char* in_folder(const char* name) {
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    return path;
}

static void test_new(fabvdb_ctx* ctx) {
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_new(ctx, NULL, 0, NULL, 0, &mesh) == FABVDB_OK);
    CHECK(fabvdb_mesh_vertex_count(mesh) == 0 && fabvdb_mesh_triangle_count(mesh) == 0);
    fabvdb_mesh_free(mesh);

    double corners[24];
    box_corners(lo, hi, corners);
    const uint32_t past_the_end[] = {0, 1, 8};
    mesh = NULL;
    CHECK(fabvdb_mesh_new(ctx, corners, 8, past_the_end, 1, &mesh) == FABVDB_ERR_BAD_INPUT && mesh == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), "index") != NULL);
    corners[7] = INFINITY;
    CHECK(fabvdb_mesh_new(ctx, corners, 8, box_triangles, 12, &mesh) == FABVDB_ERR_BAD_INPUT && mesh == NULL);
    CHECK(strlen(fabvdb_last_error(ctx)) > 0);
    CHECK(fabvdb_mesh_new(ctx, corners, 8, NULL, 12, &mesh) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "triangles is NULL") != NULL);
    /* Accessors of no mesh. */
    CHECK(fabvdb_mesh_vertex_count(NULL) == 0 && fabvdb_mesh_triangle_count(NULL) == 0);
    CHECK(fabvdb_mesh_vertices(NULL) == NULL && fabvdb_mesh_triangles(NULL) == NULL);
}

static void test_scale(fabvdb_ctx* ctx) {
    fabvdb_mesh* box = new_box(ctx, lo, hi, 0);
    CHECK(fabs(mesh_signed_volume(box) - 6000.0) < 1e-9);
    fabvdb_mesh* doubled = NULL;
    CHECK(fabvdb_mesh_scale(ctx, box, 2.0, &doubled) == FABVDB_OK);
    CHECK(fabvdb_mesh_vertex_count(doubled) == 8 && fabvdb_mesh_triangle_count(doubled) == 12);
    for (size_t i = 0; i < 24; ++i) CHECK(fabvdb_mesh_vertices(doubled)[i] == 2.0 * fabvdb_mesh_vertices(box)[i]);
    CHECK(memcmp(fabvdb_mesh_triangles(doubled), box_triangles, sizeof box_triangles) == 0);
    CHECK(fabs(mesh_signed_volume(doubled) - 8 * 6000.0) < 1e-9);
    CHECK(fabvdb_mesh_vertices(box)[3 * 7 + 2] == 30.0); /* the original is untouched */
    fabvdb_mesh_free(doubled);

    const double bad_factors[] = {0.0, -1.0, NAN, INFINITY};
    for (size_t i = 0; i < sizeof bad_factors / sizeof bad_factors[0]; ++i) {
        fabvdb_mesh* none = NULL;
        CHECK(fabvdb_mesh_scale(ctx, box, bad_factors[i], &none) == FABVDB_ERR_INVALID_ARGUMENT && none == NULL);
        CHECK(strstr(fabvdb_last_error(ctx), "scale factor") != NULL);
    }
    fabvdb_mesh_free(box);
}

static void test_read(fabvdb_ctx* ctx) {
    /* An ASCII STL of the box: every facet with its own three corners. */
    double corners[24];
    box_corners(lo, hi, corners);
    FILE* stl = fopen(in_folder("box.STL"), "w");
    CHECK(stl != NULL);
    if (!stl) return;
    fprintf(stl, "solid box\n");
    for (int t = 0; t < 12; ++t) {
        fprintf(stl, " facet normal 0 0 0\n  outer loop\n");
        for (int k = 0; k < 3; ++k) {
            const double* p = corners + 3 * box_triangles[3 * t + k];
            fprintf(stl, "   vertex %g %g %g\n", p[0], p[1], p[2]);
        }
        fprintf(stl, "  endloop\n endfacet\n");
    }
    fprintf(stl, "endsolid box\n");
    fclose(stl);
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_read(ctx, in_folder("box.STL"), &mesh) == FABVDB_OK);
    CHECK(fabvdb_mesh_vertex_count(mesh) == 8 && fabvdb_mesh_triangle_count(mesh) == 12);
    CHECK(fabs(mesh_signed_volume(mesh) - 6000.0) < 1e-9);
    fabvdb_mesh_free(mesh);

    /* An OBJ square 4 × 3 in z = 1, as one quad. */
    FILE* obj = fopen(in_folder("quad.obj"), "w");
    CHECK(obj != NULL);
    if (!obj) return;
    fprintf(obj, "v 0 0 1\nv 4 0 1\nv 4 3 1\nv 0 3 1\nf 1 2 3 4\n");
    fclose(obj);
    mesh = NULL;
    CHECK(fabvdb_mesh_read(ctx, in_folder("quad.obj"), &mesh) == FABVDB_OK);
    CHECK(fabvdb_mesh_triangle_count(mesh) == 2);
    if (fabvdb_mesh_triangle_count(mesh) == 2) {
        const double* v = fabvdb_mesh_vertices(mesh);
        const uint32_t* t = fabvdb_mesh_triangles(mesh);
        double area = 0;
        for (int i = 0; i < 2; ++i) {
            const double* a = v + 3 * t[3 * i];
            const double* b = v + 3 * t[3 * i + 1];
            const double* c = v + 3 * t[3 * i + 2];
            area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        }
        CHECK(fabs(area - 12.0) < 1e-12); /* both counter-clockwise seen from +z, as the quad */
    }
    fabvdb_mesh_free(mesh);

    mesh = NULL;
    FILE* unknown = fopen(in_folder("box.xyz"), "w");
    if (unknown) fclose(unknown);
    CHECK(fabvdb_mesh_read(ctx, in_folder("box.xyz"), &mesh) == FABVDB_ERR_BAD_INPUT && mesh == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), "box.xyz") != NULL);
    CHECK(mkdir(in_folder("folder.stl"), 0755) == 0);
    CHECK(fabvdb_mesh_read(ctx, in_folder("folder.stl"), &mesh) == FABVDB_ERR_IO && mesh == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), "folder.stl") != NULL);
    CHECK(fabvdb_mesh_read(ctx, NULL, &mesh) == FABVDB_ERR_INVALID_ARGUMENT);
    remove(in_folder("box.STL"));
    remove(in_folder("quad.obj"));
    remove(in_folder("box.xyz"));
    rmdir(in_folder("folder.stl"));
}

static void test_write(fabvdb_ctx* ctx) {
    /* A mesh the caller made is written unchecked: an open box is fine. */
    fabvdb_mesh* open_box = new_box(ctx, lo, hi, 1);
    CHECK(fabvdb_mesh_write(ctx, open_box, in_folder("open.off")) == FABVDB_OK);
    fabvdb_mesh* back = NULL;
    CHECK(fabvdb_mesh_read(ctx, in_folder("open.off"), &back) == FABVDB_OK);
    CHECK(fabvdb_mesh_triangle_count(back) == 10);
    fabvdb_mesh_free(back);
    CHECK(fabvdb_mesh_write(ctx, open_box, in_folder("open.xyz")) == FABVDB_ERR_BAD_INPUT);
    CHECK(fabvdb_mesh_write(ctx, open_box, in_folder("missing/open.stl")) == FABVDB_ERR_IO);
    CHECK(strstr(fabvdb_last_error(ctx), "missing/open.stl") != NULL);
    CHECK(fabvdb_mesh_write(ctx, NULL, in_folder("none.stl")) == FABVDB_ERR_INVALID_ARGUMENT);
    remove(in_folder("open.off"));
    fabvdb_mesh_free(open_box);
}

static void test_inspect(fabvdb_ctx* ctx) {
    /* Two disjoint boxes, 6000 and 8 mm³. */
    const double small_lo[3] = {20, 0, 0}, small_hi[3] = {22, 2, 2};
    fabvdb_mesh* two = new_two_boxes(ctx, lo, hi, small_lo, small_hi);
    CHECK(two != NULL);
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_inspect(ctx, two, &report) == FABVDB_OK);
    CHECK(report_value(ctx, report, "/vertices") == 16 && report_value(ctx, report, "/triangles") == 24);
    CHECK(report_value(ctx, report, "/components") == 2 && report_value(ctx, report, "/closed") == 1);
    CHECK(fabs(report_value(ctx, report, "/volume") - 6008.0) < 1e-9);
    CHECK(report_value(ctx, report, "/bbox/max/0") == 22 && report_value(ctx, report, "/bbox/max/2") == 30);
    CHECK(report_value(ctx, report, "/duplicate_triangles") == 0);
    fabvdb_report_free(report);
    CHECK(fabvdb_mesh_inspect(ctx, NULL, &report) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(strstr(fabvdb_last_error(ctx), "mesh is NULL") != NULL);
    CHECK(fabvdb_mesh_inspect(ctx, two, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_mesh_free(two);
}

int main(void) {
    if (!mkdtemp(folder)) return 1;
    fabvdb_ctx* ctx = NULL;
    if (fabvdb_ctx_new(&ctx) != FABVDB_OK) return 1;
    test_new(ctx);
    test_scale(ctx);
    test_read(ctx);
    test_write(ctx);
    test_inspect(ctx);
    fabvdb_ctx_free(ctx);
    rmdir(folder);
    return check_summary();
}
