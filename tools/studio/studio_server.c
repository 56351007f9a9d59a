/* studio_server.c — civetweb handlers of `fabvdb studio`: the checks every
 * request passes (token, Host, Origin, size), the embedded files, the
 * WebSocket protocol of studio_server.h (each operation a function, found in
 * one table), and the worker thread for long work (after molds, the pieces
 * the mold report names: studio_molded.h). Replies are JSON written with
 * tools/common/json.h into memory.
 * One mutex guards the session; `busy` marks long work, during which only
 * "cancel" is taken. Costs: an edit answers with one labels frame (9 bytes a
 * triangle) and a state message; the mesh is sent again only when S_low moved. */
#define _DEFAULT_SOURCE /* POSIX: clock_gettime, strdup */
#include "studio_server.h"

#include <civetweb.h>
#include <errno.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "common/json.h"
#include "common/status_text.h"
#include "studio_assets.h"
#include "studio_molded.h"

#define MAX_CLIENTS 8

enum { FRAME_MESH = 1, FRAME_LABELS = 2, FRAME_DRAFT = 3, FRAME_PIECE = 4 };
enum { JOB_NONE, JOB_CREATE, JOB_RERUN, JOB_MOLD };

struct studio_server {
    studio_config config;
    struct mg_context* web;
    char token[33];
    int port;
    char url[128];
    char host_ip[32], host_name[32];     /* "127.0.0.1:PORT", "localhost:PORT" */
    char origin_ip[48], origin_name[48]; /* "http://" + the above */

    pthread_mutex_t lock; /* the session, busy, job, failure, sent_vertices */
    fabvdb_decomposition* session;
    int busy;
    int job;
    long job_seq;
    fabvdb_decompose_options rerun_options;
    pthread_t worker;
    int worker_started;
    int failed;
    int stopping; /* studio_stop has begun: a cancelled decomposition is not reported */
    fabvdb_status failure;
    char failure_message[1024];
    double* sent_vertices; /* S_low as last sent, to send it again only when it moved */
    size_t sent_vertex_count;

    pthread_mutex_t clients_lock;
    struct mg_connection* clients[MAX_CLIENTS];

    /* progress throttling (worker thread only) */
    const char* last_stage;
    double last_fraction;
    double last_progress_time;
};

/* --- small helpers -------------------------------------------------------- */

static double now_ms(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* A message being built: text printed into memory (open_memstream). */
typedef struct text {
    FILE* out; /* opened at the first text_add */
    char* data;
    size_t size;
} text;

static FILE* text_out(text* t) {
    if (!t->out) t->out = open_memstream(&t->data, &t->size);
    return t->out;
}

static void text_add(text* t, const char* format, ...) {
    FILE* out = text_out(t);
    if (!out) return;
    va_list args;
    va_start(args, format);
    vfprintf(out, format, args);
    va_end(args);
}

/* Appends s as a JSON string literal (tools/common/json.h). */
static void text_add_string(text* t, const char* s) {
    FILE* out = text_out(t);
    if (out) json_write_string(out, s);
}

static void text_free(text* t) {
    if (t->out) fclose(t->out);
    free(t->data);
    memset(t, 0, sizeof *t);
}

/* Constant-time comparison of n bytes. */
static int same_bytes(const char* a, const char* b, size_t n) {
    unsigned char differ = 0;
    for (size_t i = 0; i < n; ++i) differ |= (unsigned char)(a[i] ^ b[i]);
    return differ == 0;
}

static void put_u32(unsigned char* at, uint32_t v) { memcpy(at, &v, 4); }

/* --- sending -------------------------------------------------------------- */

static void send_to(struct mg_connection* conn, int opcode, const void* data, size_t size) {
    mg_websocket_write(conn, opcode, (const char*)data, size);
}

/* To one connection, or to every client when conn is NULL. */
static void deliver(studio_server* s, struct mg_connection* conn, int opcode, const void* data, size_t size) {
    if (conn) {
        send_to(conn, opcode, data, size);
        return;
    }
    pthread_mutex_lock(&s->clients_lock);
    for (int i = 0; i < MAX_CLIENTS; ++i)
        if (s->clients[i]) send_to(s->clients[i], opcode, data, size);
    pthread_mutex_unlock(&s->clients_lock);
}

static void deliver_text(studio_server* s, struct mg_connection* conn, text* t) {
    if (!t->out || fflush(t->out) != 0) return;
    deliver(s, conn, MG_WEBSOCKET_OPCODE_TEXT, t->data, t->size);
}

static void send_error(studio_server* s, struct mg_connection* conn, long seq, const char* op, const char* message) {
    text t = {0};
    text_add(&t, "{\"type\":\"error\",\"seq\":%ld,\"op\":", seq);
    text_add_string(&t, op);
    text_add(&t, ",\"message\":");
    text_add_string(&t, message);
    text_add(&t, "}");
    deliver_text(s, conn, &t);
    text_free(&t);
}

/* The S_low mesh (kind 1); remembers what was sent. Lock held. */
static void send_mesh(studio_server* s, struct mg_connection* conn) {
    const size_t nv = fabvdb_decomposition_vertex_count(s->session);
    const size_t nt = fabvdb_decomposition_triangle_count(s->session);
    const double* v = fabvdb_decomposition_vertices(s->session);
    const uint32_t* f = fabvdb_decomposition_triangles(s->session);
    if (!v || !f) return;
    const size_t size = 12 + nv * 12 + nt * 12;
    unsigned char* frame = malloc(size);
    if (!frame) return;
    put_u32(frame, FRAME_MESH);
    put_u32(frame + 4, (uint32_t)nv);
    put_u32(frame + 8, (uint32_t)nt);
    float* xyz = (float*)(frame + 12);
    for (size_t i = 0; i < 3 * nv; ++i) xyz[i] = (float)v[i];
    memcpy(frame + 12 + nv * 12, f, nt * 12);
    deliver(s, conn, MG_WEBSOCKET_OPCODE_BINARY, frame, size);
    free(frame);
    double* copy = realloc(s->sent_vertices, 3 * nv * sizeof(double));
    if (copy) {
        memcpy(copy, v, 3 * nv * sizeof(double));
        s->sent_vertices = copy;
        s->sent_vertex_count = nv;
    }
}

static int mesh_moved(const studio_server* s) {
    const size_t nv = fabvdb_decomposition_vertex_count(s->session);
    const double* v = fabvdb_decomposition_vertices(s->session);
    return nv != s->sent_vertex_count || !v || memcmp(v, s->sent_vertices, 3 * nv * sizeof(double)) != 0;
}

/* Labels, sides and deformation (kind 2). Lock held. */
static void send_labels(studio_server* s, struct mg_connection* conn) {
    const size_t nt = fabvdb_decomposition_triangle_count(s->session);
    const int32_t* labels = fabvdb_decomposition_labels(s->session);
    const uint8_t* sides = fabvdb_decomposition_sides(s->session);
    const float* heat = fabvdb_decomposition_deformation(s->session);
    if (!labels || !sides || !heat) return;
    fabvdb_decomposition_info info;
    fabvdb_decomposition_info_init(&info);
    fabvdb_decomposition_get_info(s->config.ctx, s->session, &info);
    const size_t size = 12 + nt * 9;
    unsigned char* frame = malloc(size);
    if (!frame) return;
    put_u32(frame, FRAME_LABELS);
    put_u32(frame + 4, (uint32_t)nt);
    put_u32(frame + 8, (uint32_t)info.part_count);
    memcpy(frame + 12, labels, nt * 4);
    memcpy(frame + 12 + nt * 4, heat, nt * 4);
    memcpy(frame + 12 + nt * 8, sides, nt);
    deliver(s, conn, MG_WEBSOCKET_OPCODE_BINARY, frame, size);
    free(frame);
}

static void add_lines(studio_server* s, text* t, int kind, const char* name) {
    const double* points = NULL;
    const size_t* starts = NULL;
    const int32_t* parts = NULL;
    size_t point_count = 0, line_count = 0;
    text_add(t, ",\"%s\":[", name);
    if (fabvdb_decomposition_lines(s->config.ctx, s->session, kind, &points, &point_count, &starts, &parts,
                                   &line_count) == FABVDB_OK)
        for (size_t l = 0; l < line_count; ++l) {
            text_add(t, "%s{\"part\":%d,\"points\":[", l ? "," : "", (int)parts[l]);
            for (size_t i = starts[l]; i < starts[l + 1]; ++i)
                text_add(t, "%s%.6g,%.6g,%.6g", i > starts[l] ? "," : "", points[3 * i], points[3 * i + 1],
                         points[3 * i + 2]);
            text_add(t, "]}");
        }
    text_add(t, "]");
}

/* The state message. Lock held. */
static void send_state(studio_server* s, struct mg_connection* conn, long seq, double started_ms) {
    fabvdb_decomposition_info info;
    fabvdb_decomposition_info_init(&info);
    fabvdb_decomposition_get_info(s->config.ctx, s->session, &info);
    fabvdb_decompose_options options;
    fabvdb_decompose_options_init(&options);
    fabvdb_decomposition_get_options(s->config.ctx, s->session, &options);
    text t = {0};
    text_add(&t, "{\"type\":\"state\",\"seq\":%ld,\"total_energy\":%.9g,\"gamma\":%.9g,\"over_gamma\":%s,", seq,
             info.total_energy, info.gamma, info.over_gamma ? "true" : "false");
    text_add(&t, "\"draft_degrees\":%.9g,\"parts_setting\":%d,\"undo\":%zu,\"redo\":%zu,\"edits\":%zu,", info.draft_degrees,
             options.parts, info.undo_steps, info.redo_steps, info.edit_count);
    text_add(&t, "\"library_ms\":%.3f,\"triangles\":%zu,\"parts\":[", info.last_step_seconds * 1e3,
             fabvdb_decomposition_triangle_count(s->session));
    for (size_t p = 0; p < info.part_count; ++p) {
        fabvdb_part_info part;
        fabvdb_part_info_init(&part);
        if (fabvdb_decomposition_get_part(s->config.ctx, s->session, p, &part) != FABVDB_OK) continue;
        text_add(&t,
                 "%s{\"id\":%zu,\"direction\":[%.6g,%.6g,%.6g],\"energy\":%.9g,\"overhang\":%.9g,\"overlap\":%.9g,"
                 "\"area\":%.6g,\"triangles\":%zu}",
                 p ? "," : "", p, part.direction[0], part.direction[1], part.direction[2], part.energy,
                 part.overhang_energy, part.overlap_energy, part.area, part.triangle_count);
    }
    text_add(&t, "]");
    add_lines(s, &t, FABVDB_LINES_PARTING, "parting_lines");
    add_lines(s, &t, FABVDB_LINES_BOUNDARY, "boundaries");
    text_add(&t, ",\"server_ms\":%.3f}", now_ms() - started_ms);
    deliver_text(s, conn, &t);
    text_free(&t);
}

/* Everything a page needs after a change. Lock held. */
static void send_update(studio_server* s, struct mg_connection* conn, long seq, double started_ms, int whole) {
    if (whole || mesh_moved(s)) send_mesh(s, conn);
    send_labels(s, conn);
    send_state(s, conn, seq, started_ms);
}

/* --- long work ------------------------------------------------------------ */

static int report_progress(void* user, const char* stage, double fraction) {
    studio_server* s = (studio_server*)user;
    const double t = now_ms();
    if (stage != s->last_stage || fraction - s->last_fraction >= 0.01 || t - s->last_progress_time > 250 ||
        fraction >= 1.0) {
        s->last_stage = stage;
        s->last_fraction = fraction;
        s->last_progress_time = t;
        text m = {0};
        text_add(&m, "{\"type\":\"progress\",\"seq\":%ld,\"stage\":", s->job_seq);
        text_add_string(&m, stage);
        text_add(&m, ",\"fraction\":%.4f}", fraction);
        deliver_text(s, NULL, &m);
        text_free(&m);
    }
    return 0;
}

static int ensure_folder(const char* path) { return mkdir(path, 0755) == 0 || errno == EEXIST ? 0 : -1; }

/* Writes OUTPUT/decomposition/ and OUTPUT/edits.json. Lock held or busy. */
static fabvdb_status save(studio_server* s, char* decomposition_json, size_t size) {
    char folder[4096], edits[4096];
    if (ensure_folder(s->config.output_dir) != 0) return FABVDB_ERR_IO;
    snprintf(folder, sizeof folder, "%s/decomposition", s->config.output_dir);
    snprintf(edits, sizeof edits, "%s/edits.json", s->config.output_dir);
    fabvdb_status status = fabvdb_decomposition_write(s->config.ctx, s->session, folder);
    if (status == FABVDB_OK) status = fabvdb_decomposition_write_edits(s->config.ctx, s->session, edits);
    snprintf(decomposition_json, size, "%s/decomposition.json", folder);
    return status;
}

static void send_saved(studio_server* s, struct mg_connection* conn, long seq) {
    char decomposition[4200], edits[4200];
    snprintf(decomposition, sizeof decomposition, "%s/decomposition/decomposition.json", s->config.output_dir);
    snprintf(edits, sizeof edits, "%s/edits.json", s->config.output_dir);
    text t = {0};
    text_add(&t, "{\"type\":\"saved\",\"seq\":%ld,\"decomposition\":", seq);
    text_add_string(&t, decomposition);
    text_add(&t, ",\"edits\":");
    text_add_string(&t, edits);
    text_add(&t, "}");
    deliver_text(s, conn, &t);
    text_free(&t);
}

/* Sends one mold piece file (kind 4); 0 when it was there. */
static int send_piece(studio_server* s, const char* path, uint32_t role, uint32_t part) {
    fabvdb_mesh* mesh = NULL;
    if (fabvdb_mesh_read(s->config.ctx, path, &mesh) != FABVDB_OK) return -1;
    const size_t nv = fabvdb_mesh_vertex_count(mesh), nt = fabvdb_mesh_triangle_count(mesh);
    const size_t size = 20 + nv * 12 + nt * 12;
    unsigned char* frame = malloc(size);
    if (frame) {
        put_u32(frame, FRAME_PIECE);
        put_u32(frame + 4, role);
        put_u32(frame + 8, part);
        put_u32(frame + 12, (uint32_t)nv);
        put_u32(frame + 16, (uint32_t)nt);
        const double* v = fabvdb_mesh_vertices(mesh);
        float* xyz = (float*)(frame + 20);
        for (size_t i = 0; i < 3 * nv; ++i) xyz[i] = (float)v[i];
        memcpy(frame + 20 + nv * 12, fabvdb_mesh_triangles(mesh), nt * 12);
        deliver(s, NULL, MG_WEBSOCKET_OPCODE_BINARY, frame, size);
        free(frame);
    }
    fabvdb_mesh_free(mesh);
    return 0;
}

/* Saves, makes the molds into OUTPUT/molds, and sends each piece the mold
 * report names (studio_molded.h: by part id, so a part that vanished in the
 * sweep is left out, not asked for), then the "molded" message. */
static void run_mold(studio_server* s, long seq) {
    char decomposition[4200], molds[4200], path[8400], message[1200];
    fabvdb_status status = save(s, decomposition, sizeof decomposition);
    if (status != FABVDB_OK) {
        send_error(s, NULL, seq, "mold", fabvdb_last_error(s->config.ctx));
        return;
    }
    send_saved(s, NULL, seq);
    snprintf(molds, sizeof molds, "%s/molds", s->config.output_dir);
    fabvdb_report* report = NULL;
    status = fabvdb_mesh_mold(s->config.ctx, s->config.mesh, decomposition, NULL, NULL, molds, &report);
    if (status != FABVDB_OK) {
        status_text(message, sizeof message, status, "%s", fabvdb_last_error(s->config.ctx));
        send_error(s, NULL, seq, "mold", message);
        return;
    }
    studio_molded_part* parts = NULL;
    const int count = studio_molded_parts(s->config.ctx, report, &parts);
    if (count < 0) {
        status_text(message, sizeof message, FABVDB_ERR_OUT_OF_MEMORY, "cannot list the molded parts");
        send_error(s, NULL, seq, "mold", message);
        fabvdb_report_free(report);
        return;
    }
    text t = {0};
    text_add(&t, "{\"type\":\"molded\",\"seq\":%ld,\"folder\":", seq);
    text_add_string(&t, molds);
    text_add(&t, ",\"parts\":[");
    for (int p = 0; p < count; ++p) {
        for (uint32_t role = 0; role < 3; ++role) {
            if (!parts[p].files[role]) continue;
            snprintf(path, sizeof path, "%s/%s", molds, parts[p].files[role]);
            send_piece(s, path, role, (uint32_t)parts[p].id);
        }
        text_add(&t, "%s{\"id\":%d,\"volume\":%.6g,\"weight\":%.6g}", p ? "," : "", parts[p].id, parts[p].volume,
                 parts[p].weight);
    }
    text_add(&t, "]}");
    deliver_text(s, NULL, &t);
    text_free(&t);
    free(parts);
    fabvdb_report_free(report);
}

static void* work(void* argument) {
    studio_server* s = (studio_server*)argument;
    const int job = s->job;
    const long seq = s->job_seq;
    s->last_stage = NULL;
    s->last_fraction = -1;
    s->last_progress_time = 0;
    fabvdb_ctx_set_progress(s->config.ctx, report_progress, s);
    const double started = now_ms();
    fabvdb_status status = FABVDB_OK;
    if (job == JOB_CREATE) {
        fabvdb_decomposition* session = NULL;
        status = s->config.decomposition_path
                     ? fabvdb_decomposition_read(s->config.ctx, s->config.mesh, s->config.decomposition_path, &session)
                     : fabvdb_decomposition_new(s->config.ctx, s->config.mesh, s->config.options, &session);
        pthread_mutex_lock(&s->lock);
        if (status == FABVDB_OK) {
            s->session = session;
        } else {
            s->failed = 1;
            s->failure = status;
            status_text(s->failure_message, sizeof s->failure_message, status, "%s",
                        fabvdb_last_error(s->config.ctx));
            if (!s->config.quiet && !s->stopping) fprintf(stderr, "fabvdb studio: %s\n", s->failure_message);
        }
        pthread_mutex_unlock(&s->lock);
    } else if (job == JOB_RERUN) {
        status = fabvdb_decomposition_rerun(s->config.ctx, s->session, &s->rerun_options);
    } else if (job == JOB_MOLD) {
        run_mold(s, seq);
    }
    char message[1200];
    status_text(message, sizeof message, status, "%s", fabvdb_last_error(s->config.ctx));
    fabvdb_ctx_set_progress(s->config.ctx, NULL, NULL);
    pthread_mutex_lock(&s->lock);
    s->busy = 0;
    if (job != JOB_MOLD) {
        if (status == FABVDB_OK)
            send_update(s, NULL, seq, started, 1);
        else
            send_error(s, NULL, seq, job == JOB_CREATE ? "decompose" : "rerun", message);
    }
    pthread_mutex_unlock(&s->lock);
    return NULL;
}

/* Starts long work; lock held, not busy. 0 on success. */
static int start_job(studio_server* s, int job, long seq) {
    if (s->worker_started) pthread_join(s->worker, NULL);
    s->worker_started = 0;
    s->busy = 1;
    s->job = job;
    s->job_seq = seq;
    if (pthread_create(&s->worker, NULL, work, s) != 0) {
        s->busy = 0;
        return -1;
    }
    s->worker_started = 1;
    return 0;
}

/* --- the WebSocket ------------------------------------------------------- */

/* One message from the page, parsed: "SEQ OP ARGS". */
typedef struct request {
    studio_server* s;
    struct mg_connection* conn; /* who sent it */
    long seq;
    const char* op;
    const char* args; /* the rest of the message */
    double started;   /* ms, when it arrived */
} request;

/* An operation on the session. Runs with the lock held, not busy, a session
 * present. Returns FABVDB_OK, or a failed call's status (its error goes back
 * as "<status>: <last error>"); a request it refuses (bad arguments, no
 * thread) it answers itself with an error message and returns FABVDB_OK. */
typedef fabvdb_status (*operation)(const request* r);

static fabvdb_status op_edit(const request* r) {
    const fabvdb_status status = fabvdb_decomposition_apply_json(r->s->config.ctx, r->s->session, r->args);
    if (status == FABVDB_OK) send_update(r->s, NULL, r->seq, r->started, 0);
    return status;
}

static fabvdb_status op_undo(const request* r) {
    const fabvdb_status status = fabvdb_decomposition_undo(r->s->config.ctx, r->s->session);
    if (status == FABVDB_OK) send_update(r->s, NULL, r->seq, r->started, 0);
    return status;
}

static fabvdb_status op_redo(const request* r) {
    const fabvdb_status status = fabvdb_decomposition_redo(r->s->config.ctx, r->s->session);
    if (status == FABVDB_OK) send_update(r->s, NULL, r->seq, r->started, 0);
    return status;
}

/* The draft map of one direction, to the page that asked (kind 3). */
static fabvdb_status op_draft(const request* r) {
    double d[3], degrees;
    char extra;
    if (sscanf(r->args, "%lf %lf %lf %lf %c", &d[0], &d[1], &d[2], &degrees, &extra) != 4) {
        send_error(r->s, r->conn, r->seq, r->op, "draft takes X Y Z DRAFT_DEGREES");
        return FABVDB_OK;
    }
    const size_t nt = fabvdb_decomposition_triangle_count(r->s->session);
    unsigned char* frame = malloc(8 + nt);
    if (!frame) return FABVDB_ERR_OUT_OF_MEMORY;
    const fabvdb_status status = fabvdb_decomposition_draft_map(r->s->config.ctx, r->s->session, d, degrees, frame + 8);
    if (status == FABVDB_OK) {
        put_u32(frame, FRAME_DRAFT);
        put_u32(frame + 4, (uint32_t)nt);
        send_to(r->conn, MG_WEBSOCKET_OPCODE_BINARY, frame, 8 + nt);
    }
    free(frame);
    return status;
}

static fabvdb_status op_save(const request* r) {
    char path[4200];
    const fabvdb_status status = save(r->s, path, sizeof path);
    if (status == FABVDB_OK) send_saved(r->s, NULL, r->seq);
    return status;
}

/* Starts long work, or answers that no thread could start it. */
static fabvdb_status start_or_refuse(const request* r, int job) {
    if (start_job(r->s, job, r->seq) != 0) send_error(r->s, r->conn, r->seq, r->op, "cannot start a thread");
    return FABVDB_OK;
}

static fabvdb_status op_rerun(const request* r) {
    studio_server* s = r->s;
    double gamma, draft;
    int parts;
    char extra;
    if (sscanf(r->args, "%lf %d %lf %c", &gamma, &parts, &draft, &extra) != 3 || !(gamma > 0) || parts < 0 ||
        parts > 1000 || !(draft >= 0 && draft <= 30)) {
        send_error(s, r->conn, r->seq, r->op,
                   "rerun takes GAMMA > 0, PARTS in 0..1000 (0: automatic), DRAFT in [0, 30]");
        return FABVDB_OK;
    }
    fabvdb_decompose_options_init(&s->rerun_options);
    fabvdb_decomposition_get_options(s->config.ctx, s->session, &s->rerun_options);
    s->rerun_options.gamma = gamma;
    s->rerun_options.parts = parts;
    if (parts > s->rerun_options.max_parts) s->rerun_options.max_parts = parts;
    s->rerun_options.draft_degrees = draft;
    return start_or_refuse(r, JOB_RERUN);
}

static fabvdb_status op_mold(const request* r) { return start_or_refuse(r, JOB_MOLD); }

/* The operations of the protocol (studio_server.h), "cancel" aside: it is
 * the one taken while long work runs. */
static const struct {
    const char* name;
    operation run;
} operations[] = {
    {"edit", op_edit}, {"undo", op_undo}, {"redo", op_redo}, {"draft", op_draft},
    {"save", op_save}, {"rerun", op_rerun}, {"mold", op_mold},
};

static void handle_message(studio_server* s, struct mg_connection* conn, char* message) {
    request r = {s, conn, 0, NULL, NULL, now_ms()};
    char* rest = NULL;
    r.seq = strtol(message, &rest, 10);
    if (rest == message || *rest != ' ') {
        send_error(s, conn, 0, "?", "a message is 'SEQ OP ARGS'");
        return;
    }
    ++rest;
    char op[16] = {0};
    size_t n = 0;
    while (rest[n] && rest[n] != ' ' && n < sizeof op - 1) op[n] = rest[n], ++n;
    r.op = op;
    r.args = rest[n] == ' ' ? rest + n + 1 : rest + n;

    operation run = NULL;
    for (size_t i = 0; i < sizeof operations / sizeof operations[0]; ++i)
        if (strcmp(op, operations[i].name) == 0) run = operations[i].run;
    pthread_mutex_lock(&s->lock);
    if (strcmp(op, "cancel") == 0) {
        /* Only long work is cancelled: a request left pending would cancel the next edit. */
        if (s->busy) fabvdb_ctx_cancel(s->config.ctx);
        pthread_mutex_unlock(&s->lock);
        return;
    }
    const char* refusal = s->busy     ? "busy: long work is running (cancel it or wait)"
                          : !s->session ? (s->failed ? s->failure_message : "no decomposition yet")
                          : !run        ? "unknown operation (edit, undo, redo, rerun, draft, save, mold, cancel)"
                                        : NULL;
    if (refusal) {
        char why[sizeof s->failure_message];
        snprintf(why, sizeof why, "%s", refusal);
        pthread_mutex_unlock(&s->lock);
        send_error(s, conn, r.seq, op, why);
        return;
    }
    const fabvdb_status status = run(&r);
    if (status != FABVDB_OK) {
        char why[1200];
        status_text(why, sizeof why, status, "%s", fabvdb_last_error(s->config.ctx));
        send_error(s, conn, r.seq, op, why);
    }
    pthread_mutex_unlock(&s->lock);
}

/* Whether the request names this server (Host) and comes from its own page
 * (Origin, when given or `origin_required`). */
static int trusted(const studio_server* s, const struct mg_connection* conn, int origin_required) {
    const char* host = mg_get_header(conn, "Host");
    if (!host || (strcmp(host, s->host_ip) != 0 && strcmp(host, s->host_name) != 0)) return 0;
    const char* origin = mg_get_header(conn, "Origin");
    if (!origin) return !origin_required;
    return strcmp(origin, s->origin_ip) == 0 || strcmp(origin, s->origin_name) == 0;
}

/* The path after "/TOKEN", or NULL without the token. */
static const char* after_token(const studio_server* s, const char* uri) {
    if (!uri || uri[0] != '/' || strlen(uri) < 33) return NULL;
    if (!same_bytes(uri + 1, s->token, 32)) return NULL;
    return uri + 33;
}

static int ws_connect(const struct mg_connection* conn, void* data) {
    studio_server* s = (studio_server*)data;
    const struct mg_request_info* request = mg_get_request_info(conn);
    const char* rest = after_token(s, request->local_uri);
    if (!rest || strcmp(rest, "/ws") != 0 || !trusted(s, conn, 1)) return 1;
    pthread_mutex_lock(&s->clients_lock);
    int free_slot = 0;
    for (int i = 0; i < MAX_CLIENTS; ++i) free_slot |= s->clients[i] == NULL;
    pthread_mutex_unlock(&s->clients_lock);
    return free_slot ? 0 : 1;
}

static void ws_ready(struct mg_connection* conn, void* data) {
    studio_server* s = (studio_server*)data;
    pthread_mutex_lock(&s->clients_lock);
    for (int i = 0; i < MAX_CLIENTS; ++i)
        if (!s->clients[i]) {
            s->clients[i] = conn;
            break;
        }
    pthread_mutex_unlock(&s->clients_lock);
    pthread_mutex_lock(&s->lock);
    if (s->failed)
        send_error(s, conn, 0, "decompose", s->failure_message);
    else if (s->busy || !s->session) {
        text t = {0};
        text_add(&t, "{\"type\":\"busy\",\"seq\":%ld}", s->job_seq);
        deliver_text(s, conn, &t);
        text_free(&t);
    } else
        send_update(s, conn, 0, now_ms(), 1);
    pthread_mutex_unlock(&s->lock);
}

static int ws_data(struct mg_connection* conn, int bits, char* data, size_t size, void* user) {
    studio_server* s = (studio_server*)user;
    const int opcode = bits & 0x0f;
    if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
    if (opcode == MG_WEBSOCKET_OPCODE_PING || opcode == MG_WEBSOCKET_OPCODE_PONG) return 1;
    if (size > STUDIO_MAX_MESSAGE) {
        char message[128];
        snprintf(message, sizeof message, "message too large: %zu bytes (at most %d); connection closed", size,
                 STUDIO_MAX_MESSAGE);
        send_error(s, conn, 0, "?", message);
        return 0;
    }
    if (opcode != MG_WEBSOCKET_OPCODE_TEXT || !(bits & 0x80)) {
        send_error(s, conn, 0, "?", "only whole text messages are taken; connection closed");
        return 0;
    }
    char* message = malloc(size + 1);
    if (!message) return 0;
    memcpy(message, data, size);
    message[size] = 0;
    if (strlen(message) != size) {
        send_error(s, conn, 0, "?", "a message holds a NUL byte");
    } else {
        handle_message(s, conn, message);
    }
    free(message);
    return 1;
}

static void ws_close(const struct mg_connection* conn, void* data) {
    studio_server* s = (studio_server*)data;
    pthread_mutex_lock(&s->clients_lock);
    for (int i = 0; i < MAX_CLIENTS; ++i)
        if (s->clients[i] == conn) s->clients[i] = NULL;
    pthread_mutex_unlock(&s->clients_lock);
}

/* --- HTTP ---------------------------------------------------------------- */

static int refuse(struct mg_connection* conn, int code, const char* why) {
    mg_printf(conn,
              "HTTP/1.1 %d %s\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: %zu\r\n"
              "Cache-Control: no-store\r\nConnection: close\r\n\r\n%s",
              code, code == 403 ? "Forbidden" : code == 404 ? "Not Found" : "Method Not Allowed", strlen(why), why);
    return code;
}

static int serve(struct mg_connection* conn, void* data) {
    studio_server* s = (studio_server*)data;
    const struct mg_request_info* request = mg_get_request_info(conn);
    if (!trusted(s, conn, 0)) return refuse(conn, 403, "forbidden: foreign Host or Origin\n");
    const char* rest = after_token(s, request->local_uri);
    if (!rest) return refuse(conn, 403, "forbidden: the URL lacks this run's token\n");
    if (strcmp(request->request_method, "GET") != 0 && strcmp(request->request_method, "HEAD") != 0)
        return refuse(conn, 405, "only GET\n");
    if (*rest == 0) {
        mg_printf(conn, "HTTP/1.1 302 Found\r\nLocation: /%s/\r\nContent-Length: 0\r\n\r\n", s->token);
        return 302;
    }
    const char* name = rest + 1; /* after '/' */
    if (*name == 0) name = "index.html";
    const studio_asset* asset = NULL;
    for (size_t i = 0; i < studio_asset_count; ++i)
        if (strcmp(studio_assets[i].path, name) == 0) asset = &studio_assets[i];
    if (!asset) return refuse(conn, 404, "not found\n");
    mg_printf(conn,
              "HTTP/1.1 200 OK\r\nContent-Type: %s\r\nContent-Length: %zu\r\nCache-Control: no-store\r\n"
              "X-Content-Type-Options: nosniff\r\nReferrer-Policy: no-referrer\r\nX-Frame-Options: DENY\r\n"
              "Content-Security-Policy: default-src 'self'; script-src 'self' 'unsafe-inline'; "
              "style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; connect-src 'self' ws://%s ws://%s; "
              "frame-ancestors 'none'\r\n\r\n",
              asset->mime, (size_t)(asset->end - asset->data), s->host_ip, s->host_name);
    if (strcmp(request->request_method, "GET") == 0) mg_write(conn, asset->data, (size_t)(asset->end - asset->data));
    return 200;
}

/* --- lifetime ------------------------------------------------------------ */

static int random_token(char out[33]) {
    unsigned char bytes[16];
    FILE* random = fopen("/dev/urandom", "rb");
    if (!random) return -1;
    const size_t got = fread(bytes, 1, sizeof bytes, random);
    fclose(random);
    if (got != sizeof bytes) return -1;
    for (int i = 0; i < 16; ++i) snprintf(out + 2 * i, 3, "%02x", bytes[i]);
    return 0;
}

studio_server* studio_start(const studio_config* config) {
    if (!studio_assets_complete) {
        fprintf(stderr, "fabvdb studio: this fabvdb was built without the page's three.js files "
                        "(run 'npm ci' in studio/ or scripts/setup.sh, then build again)\n");
        return NULL;
    }
    studio_server* s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->config = *config;
    pthread_mutex_init(&s->lock, NULL);
    pthread_mutex_init(&s->clients_lock, NULL);
    if (random_token(s->token) != 0) {
        fprintf(stderr, "fabvdb studio: cannot read /dev/urandom for the token\n");
        free(s);
        return NULL;
    }
    char listening[32], timeout[16];
    snprintf(listening, sizeof listening, "127.0.0.1:%d", config->port);
    snprintf(timeout, sizeof timeout, "%d", 3600 * 1000);
    const char* options[] = {"listening_ports", listening, "num_threads", "6", "tcp_nodelay", "1",
                             "max_request_size", "16384", "request_timeout_ms", "30000",
                             "websocket_timeout_ms", timeout, "enable_keep_alive", "yes", NULL};
    mg_init_library(0);
    struct mg_callbacks callbacks;
    memset(&callbacks, 0, sizeof callbacks);
    char why[256] = "";
    struct mg_init_data init = {&callbacks, s, options};
    struct mg_error_data error = {0, why, sizeof why};
    s->web = mg_start2(&init, &error);
    if (!s->web) {
        fprintf(stderr, "fabvdb studio: cannot serve on %s: %s\n", listening, why);
        free(s);
        return NULL;
    }
    struct mg_server_port ports[4];
    memset(ports, 0, sizeof ports);
    if (mg_get_server_ports(s->web, 4, ports) < 1) {
        fprintf(stderr, "fabvdb studio: cannot tell the port it listens on\n");
        mg_stop(s->web);
        free(s);
        return NULL;
    }
    s->port = ports[0].port;
    snprintf(s->host_ip, sizeof s->host_ip, "127.0.0.1:%d", s->port);
    snprintf(s->host_name, sizeof s->host_name, "localhost:%d", s->port);
    snprintf(s->origin_ip, sizeof s->origin_ip, "http://%s", s->host_ip);
    snprintf(s->origin_name, sizeof s->origin_name, "http://%s", s->host_name);
    snprintf(s->url, sizeof s->url, "http://127.0.0.1:%d/%s/", s->port, s->token);
    mg_set_websocket_handler(s->web, "/", ws_connect, ws_ready, ws_data, ws_close, s);
    mg_set_request_handler(s->web, "/", serve, s);
    pthread_mutex_lock(&s->lock);
    const int started = start_job(s, JOB_CREATE, 0);
    pthread_mutex_unlock(&s->lock);
    if (started != 0) {
        fprintf(stderr, "fabvdb studio: cannot start a thread\n");
        mg_stop(s->web);
        free(s);
        return NULL;
    }
    return s;
}

const char* studio_url(const studio_server* server) { return server->url; }

int studio_failed(const studio_server* server, fabvdb_status* status) {
    studio_server* s = (studio_server*)server;
    pthread_mutex_lock(&s->lock);
    const int failed = s->failed;
    if (failed && status) *status = s->failure;
    pthread_mutex_unlock(&s->lock);
    return failed;
}

void studio_stop(studio_server* s) {
    if (!s) return;
    pthread_mutex_lock(&s->lock);
    s->stopping = 1;
    pthread_mutex_unlock(&s->lock);
    fabvdb_ctx_cancel(s->config.ctx);
    pthread_mutex_lock(&s->lock);
    const int joined = s->worker_started;
    s->worker_started = 0;
    pthread_mutex_unlock(&s->lock);
    if (joined) pthread_join(s->worker, NULL);
    mg_stop(s->web);
    fabvdb_decomposition_free(s->session);
    free(s->sent_vertices);
    pthread_mutex_destroy(&s->lock);
    pthread_mutex_destroy(&s->clients_lock);
    free(s);
}
