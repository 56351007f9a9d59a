/* studio_server.h — the local server behind `fabvdb studio`: serves the page
 * (files embedded at build time, tools/studio_assets.h) and one WebSocket
 * over which the page steers a decomposition session (fabvdb.h). Binds
 * 127.0.0.1 only; every request must carry the per-run token as the first
 * path segment (http://127.0.0.1:PORT/TOKEN/), name this origin in Host (and
 * in Origin when it has one, always for the WebSocket); messages are bounded
 * (STUDIO_MAX_MESSAGE bytes) and one at a time. Long work (the initial
 * decomposition, re-runs, molds) runs on a worker thread that streams its
 * progress and can be cancelled from the page; a refused edit is an error
 * message and leaves the session as it was.
 *
 * Messages from the page are text: "SEQ OP ARGS", OP one of
 *   edit JSON        one edit object of the edits file (fabvdb decompose --edits)
 *   undo | redo
 *   rerun GAMMA PARTS DRAFT_DEGREES   (PARTS 0: automatic)
 *   draft X Y Z DRAFT_DEGREES         the draft/undercut map for that direction
 *   save             OUTPUT/decomposition/ and OUTPUT/edits.json
 *   mold             save, then molds into OUTPUT/molds/, sent back as meshes
 *   cancel           cancels the running long work
 * Replies: text JSON {"type": "state" | "progress" | "error" | "saved" |
 * "molded" | "busy", "seq": SEQ, ...}; binary frames start with a
 * little-endian uint32 kind: 1 S_low mesh, 2 labels/sides/deformation,
 * 3 draft map, 4 a mold piece (README "fabvdb studio" gives the layouts). */
#ifndef FABVDB_STUDIO_SERVER_H
#define FABVDB_STUDIO_SERVER_H

#include "fabvdb.h"

/* Largest message the page may send, in bytes: a stroke of the page's 1000
 * points at most fits; anything larger closes the connection (civetweb also
 * hands frames over about 128 KiB in pieces, which are refused as not whole). */
#define STUDIO_MAX_MESSAGE 262144

typedef struct studio_config {
    fabvdb_ctx* ctx;                   /* borrowed; used by one thread at a time */
    const fabvdb_mesh* mesh;           /* borrowed; the model */
    const fabvdb_decompose_options* options; /* the session's options */
    const char* decomposition_path;    /* NULL, or a decomposition.json to start from */
    const char* output_dir;            /* where save and mold write */
    int port;                          /* 0: a free one */
    int quiet;
} studio_config;

typedef struct studio_server studio_server;

/* Starts the server and the initial decomposition in the background.
 * Returns NULL after printing why on stderr. */
studio_server* studio_start(const studio_config* config);
/* The page's URL (with the token); owned by the server. */
const char* studio_url(const studio_server* server);
/* 1 once the initial decomposition failed (the server keeps serving the
 * error to the page); its status in *status. */
int studio_failed(const studio_server* server, fabvdb_status* status);
/* Stops the server, waits for the worker, frees everything. NULL does nothing. */
void studio_stop(studio_server* server);

#endif
