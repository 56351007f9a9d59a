/* decomposition_api_test.c — decomposition sessions from C, through fabvdb.h
 * only: a session on the bundled sphere (40 mm), every edit type with its
 * effect measured on the session's own arrays (a no-cut stroke ends inside
 * one part, a closed cut around a vertex splits off its fan, a merge joins
 * two touching parts (given as JSON text), a smoothing stroke moves boundary
 * vertices only near it), undo and redo restoring the labels exactly, bad edits refused with the
 * session unchanged, the draft map, cancellation of a new session and of a
 * re-run (session unchanged), the decomposition written and molded by
 * fabvdb_mesh_mold, read back into a session with the same labels, and the
 * edit list replayed by fabvdb_mesh_decompose giving the same labels. */
#define _DEFAULT_SOURCE /* POSIX: mkdtemp */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "fabvdb.h"

static int exists(const char* path) {
    struct stat info;
    return stat(path, &info) == 0;
}

static int cancel_at(void* user, const char* stage, double fraction) {
    (void)fraction;
    const char* wanted = (const char*)user;
    return strcmp(stage, wanted) == 0;
}

/* A copy of the session's labels (caller frees). */
static int32_t* labels_copy(const fabvdb_decomposition* d) {
    const size_t n = fabvdb_decomposition_triangle_count(d);
    int32_t* copy = malloc(n * sizeof *copy);
    memcpy(copy, fabvdb_decomposition_labels(d), n * sizeof *copy);
    return copy;
}

static int same_labels(const fabvdb_decomposition* d, const int32_t* labels) {
    return memcmp(fabvdb_decomposition_labels(d), labels, fabvdb_decomposition_triangle_count(d) * sizeof *labels) ==
           0;
}

static void centroid(const fabvdb_decomposition* d, size_t t, double out[3]) {
    const double* v = fabvdb_decomposition_vertices(d);
    const uint32_t* f = fabvdb_decomposition_triangles(d) + 3 * t;
    for (int k = 0; k < 3; ++k) out[k] = (v[3 * f[0] + k] + v[3 * f[1] + k] + v[3 * f[2] + k]) / 3.0;
}

static double distance(const double* a, const double* b) {
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Whether triangles s and t share an edge. */
static int adjacent(const uint32_t* f, size_t s, size_t t) {
    int shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) shared += f[3 * s + i] == f[3 * t + j];
    return shared == 2;
}

int main(void) {
    fabvdb_edit edit;
    fabvdb_edit_init(&edit);
    CHECK(edit.struct_size == sizeof edit && edit.type == FABVDB_EDIT_NO_CUT && edit.points == NULL &&
          edit.radius == 0.0 && edit.flags == 0);
    fabvdb_edit_init(NULL);
    fabvdb_decomposition_free(NULL);
    CHECK(fabvdb_decomposition_labels(NULL) == NULL && fabvdb_decomposition_triangle_count(NULL) == 0);

    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh *unit = NULL, *mesh = NULL;
    CHECK(fabvdb_mesh_read(ctx, FABVDB_DATA_DIR "/sphere.obj", &unit) == FABVDB_OK);
    CHECK(fabvdb_mesh_scale(ctx, unit, 20.0, &mesh) == FABVDB_OK); /* 40 mm across */
    char base[] = "/tmp/fabvdb_decomposition_api_XXXXXX";
    CHECK(mkdtemp(base) != NULL);
    char path[400], path2[400];

    fabvdb_decompose_options options;
    fabvdb_decompose_options_init(&options);
    options.low_res_triangles = 1500;
    options.parts = 2;
    options.shell_thickness = 3.0;

    /* Validation and cancellation of a new session: out untouched. */
    fabvdb_decomposition* d = (fabvdb_decomposition*)&options; /* sentinel */
    options.gamma = 0;
    CHECK(fabvdb_decomposition_new(ctx, mesh, &options, &d) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(d == (fabvdb_decomposition*)&options && strstr(fabvdb_last_error(ctx), "gamma") != NULL);
    options.gamma = 0.05;
    CHECK(fabvdb_decomposition_new(ctx, NULL, &options, &d) == FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at, (void*)"coarse decomposition") == FABVDB_OK);
    CHECK(fabvdb_decomposition_new(ctx, mesh, &options, &d) == FABVDB_ERR_CANCELLED);
    CHECK(d == (fabvdb_decomposition*)&options);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);

    d = NULL;
    CHECK(fabvdb_decomposition_new(ctx, mesh, &options, &d) == FABVDB_OK && d != NULL);
    fabvdb_decomposition_info info;
    fabvdb_decomposition_info_init(&info);
    CHECK(fabvdb_decomposition_get_info(ctx, d, &info) == FABVDB_OK);
    CHECK(info.part_count == 2 && info.undo_steps == 0 && info.redo_steps == 0 && info.edit_count == 0 &&
          info.gamma == 0.05 && fabs(info.draft_degrees - 1.0) < 1e-9 && info.total_energy >= 0 &&
          info.over_gamma == !(info.total_energy < info.gamma));
    const size_t n = fabvdb_decomposition_triangle_count(d);
    const size_t vn = fabvdb_decomposition_vertex_count(d);
    CHECK(n >= 1000 && vn == n / 2 + 2); /* a closed genus-0 surface */
    const uint32_t* f = fabvdb_decomposition_triangles(d);
    const double* v = fabvdb_decomposition_vertices(d);
    CHECK(f != NULL && v != NULL);
    for (size_t i = 0; i < vn; ++i) {
        const double r = sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
        if (!(r > 19.0 && r < 21.0)) {
            CHECK(!"an S_low vertex is off the 20 mm sphere");
            break;
        }
    }
    const int32_t* labels = fabvdb_decomposition_labels(d);
    const uint8_t* sides = fabvdb_decomposition_sides(d);
    const float* heat = fabvdb_decomposition_deformation(d);
    CHECK(labels != NULL && sides != NULL && heat != NULL);
    size_t bad = 0;
    for (size_t t = 0; t < n; ++t)
        bad += labels[t] < 0 || labels[t] >= (int32_t)info.part_count || !(heat[t] >= 0) || sides[t] > 1;
    CHECK(bad == 0);
    /* Per part: direction unit, triangles adding up, energies adding up. */
    fabvdb_part_info part;
    fabvdb_part_info_init(&part);
    size_t triangles = 0;
    double energy = 0;
    double directions[8][3];
    for (size_t p = 0; p < info.part_count; ++p) {
        CHECK(fabvdb_decomposition_get_part(ctx, d, p, &part) == FABVDB_OK);
        CHECK(fabs(part.direction[0] * part.direction[0] + part.direction[1] * part.direction[1] +
                   part.direction[2] * part.direction[2] - 1.0) < 1e-9);
        CHECK(part.area > 0 && part.energy >= 0);
        memcpy(directions[p], part.direction, sizeof directions[p]);
        triangles += part.triangle_count;
        energy += part.energy;
    }
    /* Sides: a triangle facing well along +d of its part (normal from its corners,
     * n.d > 0.5) is in M+, one facing well along -d in M-; on a sphere nothing else
     * would release. */
    size_t facing = 0;
    for (size_t t = 0; t < n; ++t) {
        const double* a = v + 3 * f[3 * t];
        const double* b = v + 3 * f[3 * t + 1];
        const double* c = v + 3 * f[3 * t + 2];
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double nrm[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        const double* dir = directions[labels[t]];
        const double cosine = (nrm[0] * dir[0] + nrm[1] * dir[1] + nrm[2] * dir[2]) /
                              sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        if (fabs(cosine) < 0.5) continue;
        ++facing;
        bad += sides[t] != (cosine > 0);
    }
    CHECK(bad == 0 && facing > n / 4);
    CHECK(triangles == n && fabs(energy - info.total_energy) < 1e-9);
    CHECK(fabvdb_decomposition_get_part(ctx, d, info.part_count, &part) == FABVDB_ERR_NOT_FOUND);

    /* Lines: parting lines and boundaries exist and lie on the sphere. */
    const double* points = NULL;
    const size_t* starts = NULL;
    const int32_t* line_parts = NULL;
    size_t point_count = 0, line_count = 0;
    CHECK(fabvdb_decomposition_lines(ctx, d, FABVDB_LINES_BOUNDARY, &points, &point_count, &starts, &line_parts,
                                     &line_count) == FABVDB_OK);
    CHECK(line_count >= 2 && starts[line_count] == point_count && point_count >= 6);
    double boundary_point[3] = {points[0], points[1], points[2]};
    CHECK(fabs(sqrt(boundary_point[0] * boundary_point[0] + boundary_point[1] * boundary_point[1] +
                    boundary_point[2] * boundary_point[2]) - 20.0) < 1.0);
    CHECK(fabvdb_decomposition_lines(ctx, d, 7, &points, &point_count, &starts, &line_parts, &line_count) ==
          FABVDB_ERR_INVALID_ARGUMENT);
    CHECK(fabvdb_decomposition_lines(ctx, d, FABVDB_LINES_PARTING, &points, &point_count, &starts, &line_parts,
                                     &line_count) == FABVDB_OK);
    CHECK(line_count >= 1);

    /* Draft map along +z: the top cap faces up and nothing on a sphere is an undercut. */
    uint8_t* classes = malloc(n);
    const double up[3] = {0, 0, 2};
    CHECK(fabvdb_decomposition_draft_map(ctx, d, up, 1.0, classes) == FABVDB_OK);
    size_t count[4] = {0, 0, 0, 0};
    for (size_t t = 0; t < n; ++t) {
        double c[3];
        centroid(d, t, c);
        if (classes[t] < 4) ++count[classes[t]];
        if (c[2] > 10 && classes[t] != FABVDB_DRAFT_POSITIVE) ++bad;
        if (c[2] < -10 && classes[t] != FABVDB_DRAFT_NEGATIVE) ++bad;
    }
    CHECK(bad == 0 && count[0] > 0 && count[1] > 0 && count[3] == 0 && count[0] + count[1] + count[2] == n);
    const double zero[3] = {0, 0, 0};
    CHECK(fabvdb_decomposition_draft_map(ctx, d, zero, 1.0, classes) == FABVDB_ERR_INVALID_ARGUMENT);

    int32_t* automatic = labels_copy(d);

    /* Bad edits: refused, the session unchanged. */
    double far_points[6];
    edit.type = FABVDB_EDIT_NO_CUT;
    edit.points = boundary_point;
    edit.point_count = 1;
    edit.radius = 0;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "radius") != NULL);
    edit.type = (fabvdb_edit_type)42;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_ERR_INVALID_ARGUMENT);
    edit.type = FABVDB_EDIT_CUT;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_ERR_BAD_INPUT); /* one point */
    far_points[0] = NAN, far_points[1] = 0, far_points[2] = 0;
    far_points[3] = 1, far_points[4] = 0, far_points[5] = 0;
    edit.points = far_points;
    edit.point_count = 2;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_ERR_BAD_INPUT);
    /* A merge of two points on one part. */
    size_t t0 = 0;
    size_t t1 = 1;
    while (t1 < n && labels[t1] != labels[t0]) ++t1;
    centroid(d, t0, far_points);
    centroid(d, t1, far_points + 3);
    edit.type = FABVDB_EDIT_MERGE;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "same part") != NULL);
    /* A smoothing stroke far from every boundary: the vertex farthest from it. */
    size_t lonely = 0;
    double farthest = -1;
    for (size_t t = 0; t < n; ++t) {
        double c[3];
        centroid(d, t, c);
        if (distance(c, boundary_point) > farthest) farthest = distance(c, boundary_point), lonely = t;
    }
    centroid(d, lonely, far_points);
    edit.type = FABVDB_EDIT_SMOOTH;
    edit.point_count = 1;
    edit.radius = 0.5;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_ERR_BAD_INPUT);
    /* Edits as JSON text: malformed JSON, an unknown type. */
    CHECK(fabvdb_decomposition_apply_json(ctx, d, "{\"type\": \"merge\", \"points\": [[0, 0") == FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "not valid JSON") != NULL);
    CHECK(fabvdb_decomposition_apply_json(ctx, d, "{\"type\": \"fold\", \"points\": [[0, 0, 0]]}") ==
          FABVDB_ERR_BAD_INPUT);
    CHECK(strstr(fabvdb_last_error(ctx), "fold") != NULL);
    CHECK(fabvdb_decomposition_apply_json(ctx, d, NULL) == FABVDB_ERR_INVALID_ARGUMENT);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(info.undo_steps == 0 && info.edit_count == 0 && same_labels(d, automatic));
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_ERR_NOT_FOUND);
    CHECK(fabvdb_decomposition_redo(ctx, d) == FABVDB_ERR_NOT_FOUND);

    /* no_cut across a boundary: every triangle within the radius ends in one part. */
    const double radius = 3.0;
    edit.type = FABVDB_EDIT_NO_CUT;
    edit.points = boundary_point;
    edit.point_count = 1;
    edit.radius = radius;
    size_t before_parts[2] = {0, 0};
    labels = fabvdb_decomposition_labels(d);
    for (size_t t = 0; t < n; ++t) {
        double c[3];
        centroid(d, t, c);
        if (distance(c, boundary_point) <= radius && labels[t] < 2) ++before_parts[labels[t]];
    }
    CHECK(before_parts[0] > 0 && before_parts[1] > 0); /* the stroke does cross the boundary */
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_OK);
    labels = fabvdb_decomposition_labels(d);
    int32_t stroke_part = -1;
    bad = 0;
    for (size_t t = 0; t < n; ++t) {
        double c[3];
        centroid(d, t, c);
        if (distance(c, boundary_point) > radius) continue;
        if (stroke_part < 0) stroke_part = labels[t];
        bad += labels[t] != stroke_part;
    }
    CHECK(bad == 0);
    int32_t* after_no_cut = labels_copy(d);

    /* A closed cut around a vertex deep inside a part splits off its fan. */
    f = fabvdb_decomposition_triangles(d);
    v = fabvdb_decomposition_vertices(d);
    size_t centre = vn;
    for (size_t i = 0; i < vn && centre == vn; ++i) {
        /* every triangle within 8 mm of vertex i is in the same part */
        int32_t owner = -1;
        int uniform = 1;
        for (size_t t = 0; t < n && uniform; ++t) {
            double c[3];
            centroid(d, t, c);
            if (distance(c, v + 3 * i) > 8.0) continue;
            if (owner < 0) owner = labels[t];
            uniform = labels[t] == owner;
        }
        if (uniform) centre = i;
    }
    CHECK(centre < vn);
    /* The one-ring of `centre` in cyclic order: each triangle (centre, a, b) links a to b. */
    uint32_t ring_next[64][2];
    size_t fan = 0;
    for (size_t t = 0; t < n && fan < 64; ++t)
        for (int k = 0; k < 3; ++k)
            if (f[3 * t + k] == centre) {
                ring_next[fan][0] = f[3 * t + (k + 1) % 3];
                ring_next[fan][1] = f[3 * t + (k + 2) % 3];
                ++fan;
            }
    CHECK(fan >= 3);
    double ring[3 * 64];
    uint32_t at = ring_next[0][0];
    for (size_t i = 0; i < fan; ++i) {
        memcpy(ring + 3 * i, v + 3 * at, sizeof(double) * 3);
        for (size_t j = 0; j < fan; ++j)
            if (ring_next[j][0] == at) {
                at = ring_next[j][1];
                break;
            }
    }
    fabvdb_decomposition_get_info(ctx, d, &info);
    const size_t parts_before_cut = info.part_count;
    edit.type = FABVDB_EDIT_CUT;
    edit.points = ring;
    edit.point_count = fan;
    edit.flags = FABVDB_EDIT_CLOSED;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_OK);
    edit.flags = 0;
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(info.part_count == parts_before_cut + 1 && info.edit_count == 2 && info.undo_steps == 2);
    labels = fabvdb_decomposition_labels(d);
    int32_t fan_label = -1;
    size_t fan_triangles = 0, elsewhere = 0;
    for (size_t t = 0; t < n; ++t) {
        const int in_fan = f[3 * t] == centre || f[3 * t + 1] == centre || f[3 * t + 2] == centre;
        if (in_fan) {
            if (fan_label < 0) fan_label = labels[t];
            fan_triangles += labels[t] == fan_label;
        } else {
            elsewhere += labels[t] == fan_label;
        }
    }
    CHECK(fan_triangles == fan && elsewhere == 0);

    /* Merge the fan back into the part around it: two adjacent triangles. */
    size_t inside = n, outside = n;
    for (size_t t = 0; t < n && inside == n; ++t)
        if (labels[t] == fan_label)
            for (size_t s = 0; s < n; ++s)
                if (labels[s] != fan_label && adjacent(f, s, t)) {
                    inside = t, outside = s;
                    break;
                }
    CHECK(inside < n);
    double pair[6];
    centroid(d, inside, pair);
    centroid(d, outside, pair + 3);
    char merge_json[512];
    snprintf(merge_json, sizeof merge_json, "{\"type\": \"merge\", \"points\": [[%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g]]}",
             pair[0], pair[1], pair[2], pair[3], pair[4], pair[5]);
    CHECK(fabvdb_decomposition_apply_json(ctx, d, merge_json) == FABVDB_OK);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(info.part_count == parts_before_cut && info.edit_count == 3);
    labels = fabvdb_decomposition_labels(d);
    CHECK(labels[inside] == labels[outside]);

    /* Smooth at a boundary: only vertices within the radius may move. */
    CHECK(fabvdb_decomposition_lines(ctx, d, FABVDB_LINES_BOUNDARY, &points, &point_count, &starts, &line_parts,
                                     &line_count) == FABVDB_OK);
    double stroke[3] = {points[3 * (point_count / 2)], points[3 * (point_count / 2) + 1],
                        points[3 * (point_count / 2) + 2]};
    double* before_vertices = malloc(vn * 3 * sizeof(double));
    memcpy(before_vertices, fabvdb_decomposition_vertices(d), vn * 3 * sizeof(double));
    int32_t* before_smooth = labels_copy(d);
    edit.type = FABVDB_EDIT_SMOOTH;
    edit.points = stroke;
    edit.point_count = 1;
    edit.radius = 6.0;
    CHECK(fabvdb_decomposition_apply(ctx, d, &edit) == FABVDB_OK);
    v = fabvdb_decomposition_vertices(d);
    size_t moved = 0, moved_far = 0;
    for (size_t i = 0; i < vn; ++i)
        if (distance(v + 3 * i, before_vertices + 3 * i) > 0) {
            ++moved;
            moved_far += distance(before_vertices + 3 * i, stroke) > edit.radius;
        }
    CHECK(moved_far == 0);
    printf("smoothing moved %zu vertices\n", moved);

    /* Undo all four, redo all four, labels exactly as they were. */
    int32_t* after_all = labels_copy(d);
    double* after_vertices = malloc(vn * 3 * sizeof(double));
    memcpy(after_vertices, v, vn * 3 * sizeof(double));
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_OK);
    CHECK(same_labels(d, before_smooth));
    CHECK(memcmp(fabvdb_decomposition_vertices(d), before_vertices, vn * 3 * sizeof(double)) == 0);
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_OK);
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_OK);
    CHECK(same_labels(d, after_no_cut));
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_OK);
    CHECK(same_labels(d, automatic));
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_ERR_NOT_FOUND);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(info.undo_steps == 0 && info.redo_steps == 4 && info.edit_count == 0);
    for (int i = 0; i < 4; ++i) CHECK(fabvdb_decomposition_redo(ctx, d) == FABVDB_OK);
    CHECK(fabvdb_decomposition_redo(ctx, d) == FABVDB_ERR_NOT_FOUND);
    CHECK(same_labels(d, after_all));
    CHECK(memcmp(fabvdb_decomposition_vertices(d), after_vertices, vn * 3 * sizeof(double)) == 0);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(info.edit_count == 4 && info.undo_steps == 4 && info.redo_steps == 0);
    const double energy_after_edits = info.total_energy;

    /* A re-run cancelled: the session as it was. Then a re-run with three parts. */
    fabvdb_decompose_options rerun;
    fabvdb_decompose_options_init(&rerun);
    CHECK(fabvdb_decomposition_get_options(ctx, d, &rerun) == FABVDB_OK);
    CHECK(rerun.parts == 2 && rerun.gamma == 0.05 && rerun.low_res_triangles == 1500 && rerun.shell_thickness == 3.0);
    rerun.parts = 3;
    rerun.draft_degrees = 2.0;
    CHECK(fabvdb_ctx_set_progress(ctx, cancel_at, (void*)"boundary smoothing") == FABVDB_OK);
    CHECK(fabvdb_decomposition_rerun(ctx, d, &rerun) == FABVDB_ERR_CANCELLED);
    CHECK(fabvdb_ctx_set_progress(ctx, NULL, NULL) == FABVDB_OK);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(same_labels(d, after_all) && info.total_energy == energy_after_edits && info.edit_count == 4 &&
          fabs(info.draft_degrees - 1.0) < 1e-9);
    CHECK(memcmp(fabvdb_decomposition_vertices(d), after_vertices, vn * 3 * sizeof(double)) == 0);
    rerun.draft_degrees = 31;
    CHECK(fabvdb_decomposition_rerun(ctx, d, &rerun) == FABVDB_ERR_INVALID_ARGUMENT);
    rerun.draft_degrees = 2.0;
    CHECK(fabvdb_decomposition_rerun(ctx, d, &rerun) == FABVDB_OK);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(info.part_count == 3 && info.edit_count == 0 && info.undo_steps == 5 && fabs(info.draft_degrees - 2.0) < 1e-9);
    CHECK(fabvdb_decomposition_undo(ctx, d) == FABVDB_OK);
    fabvdb_decomposition_get_info(ctx, d, &info);
    CHECK(same_labels(d, after_all) && info.edit_count == 4 && fabs(info.total_energy - energy_after_edits) < 1e-12);

    /* Write the decomposition and the edit list. */
    char out_dir[300];
    snprintf(out_dir, sizeof out_dir, "%s/decomposition", base);
    CHECK(fabvdb_decomposition_write(ctx, d, out_dir) == FABVDB_OK);
    snprintf(path, sizeof path, "%s/decomposition.json", out_dir);
    CHECK(exists(path));
    snprintf(path2, sizeof path2, "%s/edits.json", base);
    CHECK(fabvdb_decomposition_write_edits(ctx, d, path2) == FABVDB_OK);

    /* Read back: same labels, same part count. */
    fabvdb_decomposition* again = NULL;
    CHECK(fabvdb_decomposition_read(ctx, mesh, path, &again) == FABVDB_OK);
    CHECK(fabvdb_decomposition_triangle_count(again) == n && same_labels(again, after_all));
    fabvdb_decomposition_info read_info;
    fabvdb_decomposition_info_init(&read_info);
    CHECK(fabvdb_decomposition_get_info(ctx, again, &read_info) == FABVDB_OK);
    CHECK(read_info.part_count == info.part_count && read_info.edit_count == 0);
    fabvdb_decomposition_free(again);
    /* Read back for the model at another scale: bad input naming the file. */
    again = NULL;
    CHECK(fabvdb_decomposition_read(ctx, unit, path, &again) == FABVDB_ERR_BAD_INPUT && again == NULL);
    CHECK(strstr(fabvdb_last_error(ctx), "decomposition.json") != NULL);
    snprintf(path2, sizeof path2, "%s/missing.json", base);
    CHECK(fabvdb_decomposition_read(ctx, mesh, path2, &again) == FABVDB_ERR_IO);

    /* The edit list replayed by fabvdb_mesh_decompose gives the same labels. */
    char replay_dir[300];
    snprintf(replay_dir, sizeof replay_dir, "%s/replay", base);
    snprintf(path2, sizeof path2, "%s/edits.json", base);
    CHECK(fabvdb_mesh_decompose(ctx, mesh, &options, path2, replay_dir, NULL) == FABVDB_OK);
    snprintf(path2, sizeof path2, "%s/decomposition.json", replay_dir);
    CHECK(fabvdb_decomposition_read(ctx, mesh, path2, &again) == FABVDB_OK);
    CHECK(same_labels(again, after_all));
    fabvdb_decomposition_free(again);

    /* The written decomposition makes molds. */
    fabvdb_mold_options mold;
    fabvdb_mold_options_init(&mold);
    mold.margin = 6.0;
    mold.voxel_size = 0.8;
    char mold_dir[300];
    snprintf(mold_dir, sizeof mold_dir, "%s/molds", base);
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_mold(ctx, mesh, path, NULL, &mold, mold_dir, &report) == FABVDB_OK);
    double mold_parts = 0;
    CHECK(fabvdb_report_number(ctx, report, "/part_count", &mold_parts) == FABVDB_OK &&
          mold_parts == (double)info.part_count);
    snprintf(path2, sizeof path2, "%s/molds/part_01_top.stl", mold_dir);
    CHECK(exists(path2));
    fabvdb_report_free(report);

    free(classes);
    free(automatic);
    free(after_no_cut);
    free(before_vertices);
    free(before_smooth);
    free(after_all);
    free(after_vertices);
    fabvdb_decomposition_free(d);
    fabvdb_mesh_free(mesh);
    fabvdb_mesh_free(unit);
    fabvdb_ctx_free(ctx);
    char command[400];
    snprintf(command, sizeof command, "rm -rf '%s'", base);
    CHECK(system(command) == 0);
    return check_summary();
}
