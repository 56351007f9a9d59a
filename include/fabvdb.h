/*
 * fabvdb.h — the public C API of fabvdb, a library that prepares 3D models for
 * fabrication: repair, hollowing, drain holes, mold decomposition and molds.
 *
 * Conventions (see README "The C API"; reports: docs/reports.md):
 *   - Opaque handles, each with one create/free pair; freeing NULL does nothing.
 *   - Every fallible call takes the context first and returns fabvdb_status;
 *     results come back through out-parameters, which are left untouched on
 *     failure. The message of the last failure is fabvdb_last_error(ctx).
 *   - No call throws or aborts; a cancelled call never returns a partial result.
 *   - Option structs have an _init() that sets struct_size and the defaults.
 *     A caller built against an older header passes its older, smaller
 *     struct: the fields it does not know keep their defaults. A struct the
 *     library fills (info, part info, options out) is written only as far
 *     as the caller's struct_size.
 *   - Lengths are millimetres.
 *   - A context may be used by one thread at a time; fabvdb_ctx_cancel() is the
 *     one call that is safe from any thread. Distinct contexts are independent.
 *
 * Copyright (C) 2026 the fabvdb developers. GPL-3.0-or-later.
 */
#ifndef FABVDB_H
#define FABVDB_H

#include <stddef.h>
#include <stdint.h>

#include "fabvdb_version.h"

/* Exported when the library is built (CMake defines FABVDB_BUILDING), imported
 * by its users; a static build defines FABVDB_STATIC. */
#if defined(_WIN32) && defined(FABVDB_STATIC)
#define FABVDB_API
#elif defined(_WIN32) && defined(FABVDB_BUILDING)
#define FABVDB_API __declspec(dllexport)
#elif defined(_WIN32)
#define FABVDB_API __declspec(dllimport)
#else
#define FABVDB_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------- */
/* Status codes. Numbered explicitly; never renumbered. (since 0.1)          */
/* ------------------------------------------------------------------------- */
typedef enum fabvdb_status {
    FABVDB_OK = 0,
    /* A parameter is out of its documented range, or a handle is NULL. */
    FABVDB_ERR_INVALID_ARGUMENT = 1,
    /* A file could not be opened, read, written or renamed. */
    FABVDB_ERR_IO = 2,
    /* The input is malformed or cannot be processed (the message names the defect). */
    FABVDB_ERR_BAD_INPUT = 3,
    /* The operation would exceed the context's memory budget. */
    FABVDB_ERR_OUT_OF_BUDGET = 4,
    /* Memory allocation failed. */
    FABVDB_ERR_OUT_OF_MEMORY = 5,
    /* The progress callback or fabvdb_ctx_cancel() cancelled the call. */
    FABVDB_ERR_CANCELLED = 6,
    /* A bug or an unexpected library failure. */
    FABVDB_ERR_INTERNAL = 7,
    /* A key or item asked for does not exist (reports). */
    FABVDB_ERR_NOT_FOUND = 8
} fabvdb_status;

/* Static English text for a status code ("ok", "bad input", ...); never NULL.
 * Thread-safe. (since 0.1) */
FABVDB_API const char* fabvdb_status_string(fabvdb_status status);

/* ------------------------------------------------------------------------- */
/* Version (since 0.1)                                                        */
/* ------------------------------------------------------------------------- */
/* The library's version as MAJOR*10000 + MINOR*100 + PATCH; compare with
 * FABVDB_VERSION_NUMBER to detect a header/library mismatch. Thread-safe. */
FABVDB_API int fabvdb_version_number(void);
/* The library's version as static text "MAJOR.MINOR.PATCH". Thread-safe. */
FABVDB_API const char* fabvdb_version_string(void);

/* ------------------------------------------------------------------------- */
/* Context (since 0.1)                                                        */
/* ------------------------------------------------------------------------- */
typedef struct fabvdb_ctx fabvdb_ctx;

/* Progress callback: called from the thread that made the call, with the
 * current stage's name (static text, e.g. "winding number") and the fraction
 * of that stage done in [0, 1]. Return non-zero to cancel the call, which then
 * returns FABVDB_ERR_CANCELLED and no result. */
typedef int (*fabvdb_progress_fn)(void* user, const char* stage, double fraction);

/* Creates a context with the defaults: all hardware threads, a memory budget
 * of half the physical memory, no progress callback.
 * out: receives the context, owned by the caller (free with fabvdb_ctx_free).
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT (out is NULL) or
 * FABVDB_ERR_OUT_OF_MEMORY. */
FABVDB_API fabvdb_status fabvdb_ctx_new(fabvdb_ctx** out);
/* Frees a context. NULL does nothing. Handles made with it stay valid. */
FABVDB_API void fabvdb_ctx_free(fabvdb_ctx* ctx);

/* Sets the number of worker threads for later calls; 0 means all hardware
 * threads. Returns FABVDB_OK or FABVDB_ERR_INVALID_ARGUMENT (threads < 0). */
FABVDB_API fabvdb_status fabvdb_ctx_set_threads(fabvdb_ctx* ctx, int threads);
/* Sets the memory budget in bytes; 0 means the default (half the physical
 * memory). Operations that can estimate their memory refuse with
 * FABVDB_ERR_OUT_OF_BUDGET before allocating more than this. */
FABVDB_API fabvdb_status fabvdb_ctx_set_memory_budget(fabvdb_ctx* ctx, uint64_t bytes);
/* The memory budget in force, in bytes (the default resolved). */
FABVDB_API uint64_t fabvdb_ctx_memory_budget(const fabvdb_ctx* ctx);
/* Sets (or with fn NULL clears) the progress/cancel callback. */
FABVDB_API fabvdb_status fabvdb_ctx_set_progress(fabvdb_ctx* ctx, fabvdb_progress_fn fn, void* user);
/* Requests cancellation of the call running on ctx (or the next one started).
 * Safe from any thread and from a signal handler. The request is cleared when
 * the cancelled call returns. */
FABVDB_API void fabvdb_ctx_cancel(fabvdb_ctx* ctx);
/* The message of the last failed call on ctx ("" if none). Owned by ctx, valid
 * until the next call on it. Never NULL (also for a NULL ctx). */
FABVDB_API const char* fabvdb_last_error(const fabvdb_ctx* ctx);

/* ------------------------------------------------------------------------- */
/* Reports (since 0.1)                                                        */
/* ------------------------------------------------------------------------- */
/* A report is a JSON document holding every figure an operation computed.
 * Geometric findings (open edges, thin walls, trapped powder) are data in a
 * report, never errors. Keys are snake_case; lengths in mm, volumes in mm^3. */
typedef struct fabvdb_report fabvdb_report;

/* Frees a report. NULL does nothing. */
FABVDB_API void fabvdb_report_free(fabvdb_report* report);
/* The report as JSON text (pretty-printed). Owned by the report, valid until it
 * is freed. Never NULL for a non-NULL report. Thread-safe for distinct reports. */
FABVDB_API const char* fabvdb_report_json(const fabvdb_report* report);
/* Reads a number (or boolean as 0/1) at a JSON pointer such as "/bbox/min/0".
 * Returns FABVDB_OK, FABVDB_ERR_NOT_FOUND (no such key, or the value is null
 * or not a number/boolean) or FABVDB_ERR_INVALID_ARGUMENT. */
FABVDB_API fabvdb_status fabvdb_report_number(fabvdb_ctx* ctx, const fabvdb_report* report,
                                              const char* pointer, double* out);
/* Reads a string at a JSON pointer such as "/outer_surface". *out points into
 * the report (valid until it is freed; do not free it). Returns FABVDB_OK,
 * FABVDB_ERR_NOT_FOUND (no such key, or the value is not a string) or
 * FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_report_string(fabvdb_ctx* ctx, const fabvdb_report* report,
                                              const char* pointer, const char** out);
/* The element count of the array (or the key count of the object) at a JSON
 * pointer such as "/holes" ("" is the whole report). Returns FABVDB_OK,
 * FABVDB_ERR_NOT_FOUND (no such key, or the value is neither an array nor an
 * object) or FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_report_count(fabvdb_ctx* ctx, const fabvdb_report* report,
                                             const char* pointer, size_t* out);
/* Writes the report's JSON to path, atomically (temporary file, then rename).
 * Returns FABVDB_OK, FABVDB_ERR_IO or FABVDB_ERR_INVALID_ARGUMENT. */
FABVDB_API fabvdb_status fabvdb_report_write(fabvdb_ctx* ctx, const fabvdb_report* report,
                                             const char* path);

/* ------------------------------------------------------------------------- */
/* Meshes (since 0.1)                                                         */
/* ------------------------------------------------------------------------- */
/* A triangle mesh: vertex positions (x, y, z doubles, millimetres) and
 * triangles (three 0-based vertex indices). Vertices no triangle uses are kept
 * as read. Immutable once made. */
typedef struct fabvdb_mesh fabvdb_mesh;

/* Makes a mesh from caller arrays, which are copied.
 * vertices: 3*vertex_count doubles; triangles: 3*triangle_count indices.
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT (NULL arrays with non-zero
 * counts) or FABVDB_ERR_BAD_INPUT (an index out of range, a non-finite
 * coordinate). */
FABVDB_API fabvdb_status fabvdb_mesh_new(fabvdb_ctx* ctx, const double* vertices, size_t vertex_count,
                                         const uint32_t* triangles, size_t triangle_count,
                                         fabvdb_mesh** out);
/* Frees a mesh. NULL does nothing. */
FABVDB_API void fabvdb_mesh_free(fabvdb_mesh* mesh);

/* Reads a mesh file. The format comes from the extension (.stl .obj .ply .off
 * .3mf, any case); STL content is sniffed (ASCII or binary). Polygons are
 * fan-triangulated, PLY triangle strips decoded, exactly coincident STL corners
 * welded. Returns FABVDB_OK, FABVDB_ERR_IO (missing, unreadable, a directory),
 * FABVDB_ERR_BAD_INPUT (unknown extension, malformed content: the message names
 * the file and the defect) or FABVDB_ERR_CANCELLED. Reports progress. */
FABVDB_API fabvdb_status fabvdb_mesh_read(fabvdb_ctx* ctx, const char* path, fabvdb_mesh** out);
/* Writes a mesh (format from the extension: .stl binary, .ply binary little-endian, .obj, .off, .3mf) to a
 * temporary file renamed when complete. A mesh fabvdb made as a solid (repair, hollow, drain, extraction) is
 * first checked as stored (STL/3MF: floats): closed, 2-manifold, no degenerate or crossing triangle; else nothing
 * is written. Returns FABVDB_OK, FABVDB_ERR_IO, FABVDB_ERR_BAD_INPUT (extension), FABVDB_ERR_INTERNAL (check). */
FABVDB_API fabvdb_status fabvdb_mesh_write(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const char* path);

/* Makes a copy of mesh scaled uniformly by factor about the origin (files
 * without units: a model drawn in metres is scaled by 1000).
 * Returns FABVDB_OK or FABVDB_ERR_INVALID_ARGUMENT (factor not finite and > 0). */
FABVDB_API fabvdb_status fabvdb_mesh_scale(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, double factor,
                                           fabvdb_mesh** out);

/* Accessors. Pointers are owned by the mesh and valid until it is freed.
 * A NULL mesh gives 0 / NULL. Thread-safe. */
FABVDB_API size_t fabvdb_mesh_vertex_count(const fabvdb_mesh* mesh);
FABVDB_API size_t fabvdb_mesh_triangle_count(const fabvdb_mesh* mesh);
/* 3*vertex_count doubles: x0 y0 z0 x1 y1 z1 ... */
FABVDB_API const double* fabvdb_mesh_vertices(const fabvdb_mesh* mesh);
/* 3*triangle_count indices: a0 b0 c0 a1 b1 c1 ... */
FABVDB_API const uint32_t* fabvdb_mesh_triangles(const fabvdb_mesh* mesh);

/* Inspects a mesh as a print-file checker would: counts, topology, defects.
 * The report has (at least) vertices, triangles, components, closed,
 * boundary_edges, boundary_loops, non_manifold_edges, non_manifold_vertices,
 * degenerate_triangles, duplicate_triangles, self_intersecting_pairs,
 * consistently_oriented, volume (null unless closed), genus (null unless
 * closed and manifold), bbox {min, max}; see docs/info.md.
 * out: receives the report, owned by the caller.
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_CANCELLED,
 * FABVDB_ERR_OUT_OF_MEMORY. Reports progress. */
FABVDB_API fabvdb_status fabvdb_mesh_inspect(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, fabvdb_report** out);

/* ------------------------------------------------------------------------- */
/* Volumes (since 0.1)                                                        */
/* ------------------------------------------------------------------------- */
/* A solid as a sparse narrow-band signed distance field (negative inside). */
typedef struct fabvdb_volume fabvdb_volume;

/* Frees a volume. NULL does nothing. */
FABVDB_API void fabvdb_volume_free(fabvdb_volume* volume);

/* ------------------------------------------------------------------------- */
/* Repair: robust level sets from dirty meshes (issue: fabvdb repair)         */
/* ------------------------------------------------------------------------- */

/* A mesh becomes a volume (a narrow-band signed distance field) whatever its
 * defects: holes, self-intersections, flipped or inconsistent normals,
 * duplicated triangles, unwelded soups, overlapping or nested shells. Inside is
 * where the generalized winding number of the consistently oriented input is
 * at least 1/2: holes close along that surface, inverted shells count as
 * solids, overlapping shells unite. Extracting the volume again gives a
 * closed, 2-manifold, outward-oriented mesh free of self-intersections. */

/* fabvdb_volume_options.flags */
#define FABVDB_REPAIR_NO_SNAP 0x1u /* keep extracted vertices where the voxels put them */
#define FABVDB_REPAIR_VOLUMETRIC 0x2u /* fabvdb_mesh_repair: through the level set, never at mesh level */
typedef struct fabvdb_volume_options {
    size_t struct_size;      /* sizeof(fabvdb_volume_options), set by _init() */
    double voxel_size;       /* voxel edge in mm; 0 (default): from resolution */
    int resolution;          /* voxels along the longest bounding-box side when
                                voxel_size is 0; default 400 (0.25 mm on a
                                100 mm part) */
    int half_band_voxels;    /* narrow band on each side, in voxels; default 3 (>= 2) */
    double adaptivity;       /* extraction adaptivity in [0, 1]; default 0 (uniform) */
    double min_shell_volume; /* shells under this volume (mm^3) are dropped; default 0
                                (keep all but specks under a voxel's volume,
                                which the extraction always drops) */
    double thicken;          /* > 0: an input enclosing no volume (an open sheet)
                                becomes a solid sheet this thick (mm); default 0 */
    uint32_t flags;          /* FABVDB_REPAIR_* bits; default 0 */
} fabvdb_volume_options;

/* Fills *options with the defaults above. NULL does nothing. (since 0.1) */
FABVDB_API void fabvdb_volume_options_init(fabvdb_volume_options* options);

/* Makes the robust signed distance field of a mesh (voxel_size or resolution,
 * half_band_voxels, min_shell_volume, thicken are used).
 * options: NULL for the defaults. out: receives the volume, owned by the caller
 * (fabvdb_volume_free). report: NULL, or receives a report owned by the caller
 * with voxel_size, active_voxels, estimated_bytes, rebuilt (the band was
 * rebuilt from the winding-number surface), thickened, enclosed_share, volume
 * (mm^3), shells_kept, shells_dropped, timings {stage: seconds}.
 * Before allocating, the memory is estimated; over the context's budget the
 * call fails with FABVDB_ERR_OUT_OF_BUDGET and a message proposing a voxel size
 * that fits. Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT,
 * FABVDB_ERR_BAD_INPUT (no triangle with area, encloses no volume and no
 * thickness given, every shell dropped), FABVDB_ERR_OUT_OF_BUDGET,
 * FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED. Reports progress.
 * One thread per context at a time; uses the context's worker threads. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_volume_from_mesh(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                                 const fabvdb_volume_options* options, fabvdb_volume** out,
                                                 fabvdb_report** report);

/* Extracts the zero surface of a volume as a triangle mesh (options: NULL or
 * its adaptivity is used): closed, 2-manifold, outward-oriented, vertices
 * shared. out: receives the mesh, owned by the caller. Returns FABVDB_OK,
 * FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED.
 * Reports progress. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_volume_to_mesh(fabvdb_ctx* ctx, const fabvdb_volume* volume,
                                               const fabvdb_volume_options* options, fabvdb_mesh** out);

/* Repairs a mesh, changing no more than it must: a clean solid comes back as it is; exactly fixable defects
 * (unwelded points, degenerate/duplicate triangles, flipped shells, small holes: faired, crossing shells: union)
 * are fixed at mesh level, keeping the input's triangles. Else (or FABVDB_REPAIR_VOLUMETRIC, thicken, a minimum
 * shell volume): fabvdb_volume_from_mesh, the extraction, then (unless FABVDB_REPAIR_NO_SNAP) vertices within a
 * voxel of a clean part of the input moved onto it, never flipping or crossing a triangle. out: the repaired mesh,
 * owned by the caller; shells that fail alone go volumetric and are united. report: NULL, or receives (owned by
 * the caller) path (input/mesh/mixed/volumetric), mesh_level, input (fabvdb_mesh_inspect of it), output_triangles,
 * volume, shells_kept/dropped, fidelity, timings; fixes, shell_paths at mesh level; else fabvdb_volume_from_mesh's
 * keys, and mesh_level_rejected with a warning when the mesh level's result was not the input's model.
 * The fidelity gate (docs/reports.md#fidelity): the result must still be the input's model — its surface near
 * the input's (a near-zero tolerance at mesh level, two voxels through the level set) and the same enclosed
 * volume. A mesh-level result that fails is replaced by the volumetric repair; a volumetric one that fails
 * (unless min_shell_volume dropped shells on purpose) returns FABVDB_ERR_INTERNAL, the message naming the mesh
 * and the figures, and no mesh. */
FABVDB_API fabvdb_status fabvdb_mesh_repair(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                            const fabvdb_volume_options* options, fabvdb_mesh** out,
                                            fabvdb_report** report);

/* Reads the first float level set of an OpenVDB file (.vdb). out: receives the
 * volume, owned by the caller. Returns FABVDB_OK, FABVDB_ERR_IO (missing,
 * unreadable), FABVDB_ERR_BAD_INPUT (not a VDB file, or no float level set in
 * it), FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_volume_read(fabvdb_ctx* ctx, const char* path, fabvdb_volume** out);

/* Writes a volume as an OpenVDB file (.vdb), to a temporary file renamed into
 * place, so a failure leaves no partial file. Returns FABVDB_OK, FABVDB_ERR_IO,
 * FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_volume_write(fabvdb_ctx* ctx, const fabvdb_volume* volume, const char* path);

/* The voxel edge length of a volume in mm; 0 for NULL. Thread-safe. (since 0.1) */
FABVDB_API double fabvdb_volume_voxel_size(const fabvdb_volume* volume);

/* ------------------------------------------------------------------------- */
/* Hollowing (fabvdb hollow)                                                  */
/* ------------------------------------------------------------------------- */
/* Parameters of hollowing. Fill with fabvdb_hollow_options_init(). (since 0.1) */
typedef struct fabvdb_hollow_options {
    size_t struct_size;       /* sizeof(fabvdb_hollow_options), set by _init */
    double wall;              /* wall thickness, mm, > 0. Default 3 (PrusaSlicer's minimum thickness). */
    double closing;           /* closing distance, mm, >= 0: the cavity is offset by -(wall + closing)
                                 then by +closing, which rounds it and drops passages narrower than
                                 2*closing (PrusaSlicer's meaning). Default 0: the exact offset. */
    double voxel_size;        /* mm; 0 (default): automatic, wall / 4 (or from resolution) */
    int resolution;           /* > 0 and voxel_size 0: voxel = longest bounding-box side / resolution.
                                 Default 0. */
    double adaptivity;        /* [0, 1] simplification of the cavity surface; default 0 */
    double min_cavity_volume; /* mm^3: voids smaller than this are filled; default 0 */
    double infill_cell;       /* mm; > 0 adds a gyroid strut lattice in the cavity: struts along the
                                 skeleton of one gyroid labyrinth (the srs net: 8 nodes, 12 struts per
                                 cubic cell of this side), unioned with the shell, joined to the wall,
                                 the void around them one open-cell region. Default 0: no infill. */
    double infill_strut;      /* mm, strut diameter, in (0, infill_cell/4] when infill_cell > 0;
                                 default 1.2. The automatic voxel is then at most strut / 4. */
} fabvdb_hollow_options;

/* Fills *options with the defaults above and sets struct_size. NULL does
 * nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_hollow_options_init(fabvdb_hollow_options* options);

/* Hollows a solid for printing: keeps a wall of options->wall under the outer
 * surface and empties the rest. The mesh may be dirty (holes, self-
 * intersections, flipped or duplicated triangles, several shells): it then
 * goes through the robust signed distance first. A clean closed mesh keeps its
 * own outer triangles exactly; so does a closed mesh whose only defect is a
 * few crossing triangles (overlapping shells, a fold), cut down to the exact
 * boundary of its shells' union. The cavity vertices lie at exactly the wall
 * distance from the outer surface (closing 0) or at least at it (closing > 0).
 * Regions thinner than 2*wall stay solid; a part that thin everywhere comes back
 * solid, cavity_count 0, with a warning. mesh: borrowed. opts: NULL: defaults.
 * out_mesh: receives the hollowed mesh (owned by the caller): outer shells
 *   facing out, cavity shells facing in, every shell closed, no cavity
 *   triangle touching the outer surface (checked exactly).
 * out_report: NULL, or receives a report (owned by the caller) with
 *   voxel_size, wall, closing, outer_surface ("input", "resolved" or
 *   "repaired"),
 *   volume_solid, volume_shell, material_saved_fraction, cavity_count,
 *   cavities [{volume}], filled_cavities [{volume}], min_wall_at_vertices,
 *   output_vertices, output_triangles, fidelity (the outer surface against
 *   the input: docs/reports.md#fidelity), timings {stage: seconds, total}, warnings.
 *   With infill: infill {pattern, cell, strut}; the cavity vertices are then
 *   at least (not exactly) the wall from the outer surface.
 * Returns FABVDB_OK; FABVDB_ERR_INVALID_ARGUMENT (NULL handle, wall <= 0,
 * closing < 0, voxel larger than the wall, adaptivity outside [0, 1],
 * a negative min_cavity_volume,
 * infill_cell < 0, an infill strut <= 0 or over infill_cell / 4);
 * FABVDB_ERR_BAD_INPUT (a mesh that encloses no volume); FABVDB_ERR_OUT_OF_BUDGET
 * (the voxel size needs more memory than the context's budget; the message
 * names a voxel size that fits); FABVDB_ERR_CANCELLED; FABVDB_ERR_OUT_OF_MEMORY;
 * FABVDB_ERR_INTERNAL (the outer surface is not the input's model: the
 * fidelity gate; a union of crossing shells that fails it is replaced by the
 * repaired surface first).
 * Out-parameters are untouched on failure. Reports progress. A context is
 * used by one thread at a time. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_mesh_hollow(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                            const fabvdb_hollow_options* opts, fabvdb_mesh** out_mesh,
                                            fabvdb_report** out_report);

/* As fabvdb_mesh_hollow, but returns the shell as a level set (signed
 * distance at the voxel size used, negative in the material) in *out_shell
 * (owned by the caller). Same statuses, progress and thread safety. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_mesh_hollow_volume(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                                   const fabvdb_hollow_options* opts, fabvdb_volume** out_shell,
                                                   fabvdb_report** out_report);

/* Hollows a solid given as a level set: its zero iso-surface is the outer
 * surface; the shell comes back as a level set at the solid's voxel size
 * (options->voxel_size and resolution are ignored). Same report, statuses,
 * progress and thread safety as fabvdb_mesh_hollow. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_volume_hollow(fabvdb_ctx* ctx, const fabvdb_volume* solid,
                                              const fabvdb_hollow_options* opts, fabvdb_volume** out_shell,
                                              fabvdb_report** out_report);

/* ------------------------------------------------------------------------- */
/* Drainability and drain holes (fabvdb drain, fabvdb powder-sim)             */
/* ------------------------------------------------------------------------- */
/* Options of fabvdb_mesh_drain. Orientations are gravity directions (x, y, z;
 * need not be unit) in the part's frame. (since 0.1) */
typedef struct fabvdb_drain_options {
    size_t struct_size;          /* set by fabvdb_drain_options_init */
    double wall;                 /* mm, wall left when a solid input is hollowed; default 3 */
    double voxel_size;           /* mm of the level sets; 0 (default): wall / 4 */
    int hole_count;              /* holes to place; 0 (default): automatic — at least 2 per
                                    cavity, more until the predicted residual is under
                                    target_residual */
    double hole_diameter;        /* mm; default 4 */
    double repose_degrees;       /* angle of repose of the powder; default 35 */
    double effort;               /* rho: chance the operator turns the part once more; default 0.9 */
    double target_residual;      /* fraction of the cavity volume, automatic mode; default 0.01 */
    const double* orientations;  /* 3*orientation_count doubles: the operator's turns; NULL
                                    (default): the 162 icosphere directions. Borrowed. */
    size_t orientation_count;
    double first_gravity[3];     /* gravity as printed, the first orientation; default 0 0 -1 */
    int patch_count;             /* cavity surface patches of the model, at least 10; default 2000 */
    const char* keep_out_path;   /* NULL (default), or a JSON file of spheres
                                    ({"spheres": [{"center": [x,y,z], "radius": r}]}) or a closed
                                    mesh file: no hole opens in it. Borrowed. */
    const char* heatmap_path;    /* NULL (default), or a .ply file that receives the cavity
                                    surface coloured by the share of the powder resting there at
                                    the start that drains (a `quality` property, viridis colours
                                    over 0..1); beside it STEM_left.ply (the powder left at the end,
                                    mm³ per mm² of surface) and a PNG colour bar for each
                                    (STEM.png, STEM_left.png). Same model as the prediction. */
} fabvdb_drain_options;

/* Fills *options with the defaults above and sets struct_size. NULL does
 * nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_drain_options_init(fabvdb_drain_options* options);

/* Places drain holes in a part for powder printing and drills them. A solid
 * mesh is hollowed first (options->wall); a mesh that already is a hollow
 * shell (it has inward-facing shells around a void) is used as is. The holes
 * maximise the powder the drainability model drains (docs/drain.md);
 * each cavity gets its own. The report has holes[] ({center, axis, diameter,
 * cavity, depth}); predicted_residual_fraction and predicted_residual_volume
 * (the model's mean over random operator routines) and random_routines
 * {routines, mean_fraction, std_fraction, min_fraction, max_fraction};
 * routine[] (the recommended cleaning routine, first turn as printed: each
 * {gravity, hole_down (index into holes[] or null), lowest_hole, tilt_degrees,
 * tilt_axis, instruction}), routine_residual_fraction and routine_residual_volume
 * (the prediction under it); the lowest-point baseline with as many holes
 * (baseline_holes[], baseline_residual_fraction, baseline_residual_volume,
 * baseline_routine_residual_fraction under its own routine); heatmap (with a
 * heat-map path: the files, their ranges and the share that drains averaged
 * by powder); cavity_volume, residual_volume_per_cavity, cavities (=
 * cavity_count), patches, candidates, input_was_hollow, voxel_size, fidelity
 * (the drilled part against the input, what the drills took and the
 * cavities filled left out; filled_cavities [{center, radius}] lists those:
 * docs/reports.md#fidelity; a part that fails is FABVDB_ERR_INTERNAL),
 * repose_degrees, effort, orientations, timings (seconds per stage, and
 * total) and warnings (docs/drain.md). No cavity: no holes, solid out.
 * mesh: borrowed. options: borrowed; NULL means the defaults.
 * out_mesh: receives the drilled part (owned by the caller). out_report:
 * receives the report (owned by the caller); may be NULL if not wanted.
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT (NULL ctx/mesh/out_mesh, an
 * option out of range, struct_size not set or from a newer header), FABVDB_ERR_BAD_INPUT (no
 * site where a hole passes cleanly through the wall; a malformed
 * keep-out file), FABVDB_ERR_IO (keep-out or heat-map file), FABVDB_ERR_OUT_OF_BUDGET,
 * FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED or FABVDB_ERR_INTERNAL; on
 * failure no output is made and no heat-map file is left. Reports progress.
 * One thread per context at a time. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_mesh_drain(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                           const fabvdb_drain_options* options, fabvdb_mesh** out_mesh,
                                           fabvdb_report** out_report);

/* A drain's heat maps as data: the cavity surface, its triangles facing the
 * powder, and per vertex of it the values and viridis colours the files of
 * heatmap_path hold (the positions there are floats, here the doubles they
 * were written from). Made by fabvdb_mesh_drain_heatmap. (since 0.2) */
typedef struct fabvdb_heatmap fabvdb_heatmap;

/* The values of a heat map. (since 0.2) */
/* The share of the powder resting at the vertex at the start that drains
 * under the recommended routine, in [0, 1]; colours over [0, 1]. */
#define FABVDB_HEATMAP_DRAINED 0
/* The powder left there at the end, mm^3 per mm^2 of surface, >= 0; colours
 * over [0, the largest value] (over [0, 1] when nothing is left). */
#define FABVDB_HEATMAP_LEFT 1

/* As fabvdb_mesh_drain, and also returns the heat maps (the model of the
 * prediction under the recommended routine) as data, with no file written
 * unless options->heatmap_path is set (then the files too, as
 * fabvdb_mesh_drain writes them). out_heatmap: receives the heat maps, owned
 * by the caller (fabvdb_heatmap_free), or NULL when the part has no cavity.
 * The report's heatmap entry has drained_share {min, max, mean_by_powder} and
 * powder_left {min, max, unit}, and with a heat-map path each also path and
 * legend. Same parameters, statuses, progress and thread safety as
 * fabvdb_mesh_drain; out_heatmap NULL is FABVDB_ERR_INVALID_ARGUMENT; on
 * failure no output is made. (since 0.2) */
FABVDB_API fabvdb_status fabvdb_mesh_drain_heatmap(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                                   const fabvdb_drain_options* options, fabvdb_mesh** out_mesh,
                                                   fabvdb_report** out_report, fabvdb_heatmap** out_heatmap);

/* Frees a heat map and what its accessors returned. NULL does nothing.
 * (since 0.2) */
FABVDB_API void fabvdb_heatmap_free(fabvdb_heatmap* heatmap);

/* Accessors. What they return is owned by the heat map and valid until it is
 * freed. A NULL heat map or an unknown kind gives NULL. Thread-safe.
 * (since 0.2) */
/* The cavity surface (use it as any mesh, but do not free it). */
FABVDB_API const fabvdb_mesh* fabvdb_heatmap_surface(const fabvdb_heatmap* heatmap);
/* One double per surface vertex: the values of `kind` (FABVDB_HEATMAP_*). */
FABVDB_API const double* fabvdb_heatmap_values(const fabvdb_heatmap* heatmap, int kind);
/* Three bytes per surface vertex, r g b: the viridis colours of `kind` over
 * its range (see FABVDB_HEATMAP_*), the colours of its file. */
FABVDB_API const uint8_t* fabvdb_heatmap_colours(const fabvdb_heatmap* heatmap, int kind);

/* Options of fabvdb_powder_simulate. (since 0.1) */
typedef struct fabvdb_powder_options {
    size_t struct_size;          /* set by fabvdb_powder_options_init */
    double voxel_size;           /* mm of the sand-pile cells; 0 (default): the bounding-box
                                    diagonal / 150, at most a quarter of the smallest hole */
    double repose_degrees;       /* default 35 */
    const double* orientations;  /* as in fabvdb_drain_options; NULL: the 162 directions */
    size_t orientation_count;
    double first_gravity[3];     /* the routine's first turn; default 0 0 -1 */
    int turns;                   /* turns of the routine, the first included; default 10 */
    uint64_t seed;               /* draws the later turns from the orientations; default 1 */
    int slope_window;            /* cells over which a pile's slope is measured, 1 to 16; default 4 */
    const char* routine_json;    /* NULL (default), or JSON text: a drain report (its routine[]
                                    array of {gravity}) or an array of [x, y, z] gravities; the
                                    routine replayed exactly, its first turn included, instead of
                                    first_gravity and turns drawn with the seed. Borrowed. (since 0.2) */
} fabvdb_powder_options;

/* Fills *options with the defaults above. NULL does nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_powder_options_init(fabvdb_powder_options* options);

/* The reference powder simulation, independent of the drainability model:
 * fills the cavity of `part` (a hollow shell, drilled or not) with powder,
 * drills the holes, and runs voxel sand-pile rules through the operator's
 * routine: the first orientation, then turns-1 orientations drawn with the
 * seed (or the routine of options->routine_json). The report has
 * initial_volume, residual_volume, residual_fraction,
 * residual_volume_after_turn[], routine[] (the gravity of each turn),
 * voxel_size and timings (docs/powder-sim.md).
 * part: borrowed. holes_json: JSON text, a drain report or any object with a
 * holes[] array of {center, axis, diameter, depth} (depth: drilled length from
 * the center outward; default 4 diameters).
 * options: borrowed; NULL means the defaults. out: receives the report.
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_BAD_INPUT (bad
 * holes JSON: the message names the defect; no enclosed void),
 * FABVDB_ERR_OUT_OF_BUDGET, FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED or
 * FABVDB_ERR_INTERNAL. Reports progress. One thread per context. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_powder_simulate(fabvdb_ctx* ctx, const fabvdb_mesh* part, const char* holes_json,
                                                const fabvdb_powder_options* options, fabvdb_report** out);

/* ------------------------------------------------------------------------- */
/* Mold decomposition (fabvdb decompose)                                      */
/* ------------------------------------------------------------------------- */
/* Bits of fabvdb_decompose_options.flags. (since 0.1) */
/* Cast solid parts: every prism reaches the medial axis instead of a shell of
 * thickness shell_thickness (thin-feature detection is then moot). */
#define FABVDB_DECOMPOSE_SOLID 1u

/* Parameters of the mold decomposition (thesis chapter 3). Energies and gamma
 * are measured on the model scaled so that its longest bounding-box side is 1
 * (the thesis' unit cube), so the defaults suit any size. Fill with
 * fabvdb_decompose_options_init(). (since 0.1) */
typedef struct fabvdb_decompose_options {
    size_t struct_size;       /* sizeof(fabvdb_decompose_options), set by _init */
    unsigned flags;           /* FABVDB_DECOMPOSE_* bits; default 0 */
    double shell_thickness;   /* omega, mm, >= 0; 0 (default): 0.03 x the longest bounding-box side */
    double gamma;             /* threshold on the total moldability energy (unit-cube area); default 0.05 */
    int parts;                /* >= 0; 0 (default): automatic, from 2 up until the energy is under gamma */
    int max_parts;            /* cap of the automatic search, >= 2; default 16 */
    double draft_degrees;     /* draft angle phi, [0, 30]; default 1 */
    double w_overhang;        /* w_H, >= 0; default 1 */
    double w_overlap;         /* w_L, >= 0; default 1 */
    double w_coarse_overlap;  /* w_O (overlap penalty of region growing), >= 0; default 1e6 */
    int low_res_triangles;    /* N_Delta, the size of the surface the decomposition runs on, >= 100;
                                 default 10000 */
    int smoothing_iterations; /* boundary smoothing (snakes), >= 0; 0: boundaries stay on S_low edges
                                 as grown; default 10 */
    double w_smooth;          /* w_l, weight of the boundary smoothness against the moldability, >= 0;
                                 default 1 */
} fabvdb_decompose_options;

/* Fills *options with the defaults above and sets struct_size. NULL does
 * nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_decompose_options_init(fabvdb_decompose_options* options);

/* Decomposes the thin shell of a free-form solid (or, with
 * FABVDB_DECOMPOSE_SOLID, the solid) into parts that can each be cast in a
 * two-piece rigid mold, with a parting direction and a parting line per part
 * (the method of the thesis' chapter 3: low-resolution surface and prisms
 * from the robust level set, thin features cast solid, region growing with
 * the moldability cost, graph-cut parting lines made connected, the snake
 * smoothing of part boundaries (thesis section 3.4.5: boundary vertices of
 * S_low slide along the surface), then the user's edits).
 * mesh: borrowed; may be dirty (it goes through the robust signed distance).
 * opts: NULL for the defaults.
 * edits_path: NULL, or a JSON file of edits applied in order after the
 *   automatic decomposition, in world coordinates (docs/decompose.md):
 *   {"edits": [{"type": "no_cut", "points": [[x,y,z],...], "radius": r},
 *              {"type": "cut", "points": [[x,y,z],...], "closed": false},
 *              {"type": "merge", "points": [[x,y,z],[x,y,z]]},
 *              {"type": "smooth", "points": [[x,y,z],...], "radius": r}]}.
 *   Each edit recomputes only the parts it touches.
 * out_dir: folder that receives decomposition.json, decomposition.ply and
 *   deformation.ply; written as a new folder beside it and renamed into place
 *   at the end (an existing folder of that name is replaced), so a failed or
 *   cancelled call leaves no partial folder.
 * out_report: NULL, or receives a report (owned by the caller) with gamma,
 *   shell_thickness, unit_scale, low_res {triangles, thin_segments, voxel_size,
 *   ...}, overlap_pairs, attempts [{parts, iterations,
 *   region_cost_per_iteration, moldability_energy, timings {per_iteration,
 *   parting_line}}], smoothing {iterations, smoothness [E_smooth per
 *   accepted iteration], moldability_energy [likewise], vertices_moved,
 *   parts_touched}, edits [{type, parts_touched, parts_after, timings {total},
 *   total_moldability_energy, warning}], part_count, parts [{id, parting_direction,
 *   moldability_energy, area}], total_moldability_energy, under_gamma,
 *   warnings [text], fidelity (S_low against the input: far is twice its mean
 *   edge; docs/reports.md#fidelity), timings {stage: seconds,
 *   precompute_per_direction, total} (docs/decompose.md).
 * Returns FABVDB_OK; FABVDB_ERR_INVALID_ARGUMENT (NULL handle or out_dir, an
 * option out of range, struct_size not set or from a newer header); FABVDB_ERR_BAD_INPUT (a mesh
 * that encloses no volume, a malformed edits file or an edit that does not
 * apply, e.g. a merge of two points on the same part); FABVDB_ERR_IO (the
 * edits file or out_dir's parent cannot be read or written);
 * FABVDB_ERR_OUT_OF_BUDGET; FABVDB_ERR_CANCELLED; FABVDB_ERR_OUT_OF_MEMORY;
 * FABVDB_ERR_INTERNAL (S_low is not the input's model: the fidelity gate,
 * also applied by fabvdb_decomposition_new).
 * The report is untouched on failure. Reports progress. A context is used by
 * one thread at a time. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_mesh_decompose(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                               const fabvdb_decompose_options* opts, const char* edits_path,
                                               const char* out_dir, fabvdb_report** out_report);

/* ------------------------------------------------------------------------- */
/* Decomposition sessions (fabvdb studio)                                     */
/* ------------------------------------------------------------------------- */
/* A mold decomposition being edited interactively (thesis section 3.5): made
 * once from a mesh (pre-computation, automatic decomposition, boundary
 * smoothing) or from a decomposition.json, then changed one step at a time by
 * edits (each recomputes only the parts it touches) or a re-run with another
 * gamma, part count or draft, with undo and redo over every step. Every call
 * is atomic: it succeeds whole or leaves the session as it was (a refused
 * edit, a cancel). A session is used by one thread at a time; distinct
 * sessions are independent. (since 0.1) */
typedef struct fabvdb_decomposition fabvdb_decomposition;

/* Edit types, numbered explicitly. (since 0.1) */
typedef enum fabvdb_edit_type {
    /* A brush stroke (points, radius): the S_low triangles within radius of a
     * point (their largest connected piece) end up inside one part; the parts
     * the stroke touches are regrown together. */
    FABVDB_EDIT_NO_CUT = 0,
    /* A cut through click-placed points (at least two), snapped to S_low
     * vertices and joined by shortest edge paths: splits every part it
     * separates; each piece gets its best parting direction. */
    FABVDB_EDIT_CUT = 1,
    /* Two points: the (neighbouring) parts under them become one. */
    FABVDB_EDIT_MERGE = 2,
    /* A brush stroke (points, radius): the part boundaries within radius of
     * a point are smoothed (snakes). */
    FABVDB_EDIT_SMOOTH = 3
} fabvdb_edit_type;

/* Bits of fabvdb_edit.flags. (since 0.1) */
#define FABVDB_EDIT_CLOSED 1u /* a cut's last point joins its first */

/* One edit, in world coordinates (mm), so it survives remeshing. Fill with
 * fabvdb_edit_init(). (since 0.1) */
typedef struct fabvdb_edit {
    size_t struct_size;     /* sizeof(fabvdb_edit), set by _init */
    fabvdb_edit_type type;  /* default FABVDB_EDIT_NO_CUT */
    const double* points;   /* 3*point_count doubles, borrowed for the call; default NULL */
    size_t point_count;     /* default 0 */
    double radius;          /* brush radius, mm, > 0 for NO_CUT and SMOOTH; default 0 */
    unsigned flags;         /* FABVDB_EDIT_* bits; default 0 */
} fabvdb_edit;

/* Fills *edit with the defaults above. NULL does nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_edit_init(fabvdb_edit* edit);

/* Makes a session: the robust level set, S_low and its prisms, the
 * moldability terms of the 162 directions, the automatic decomposition and
 * the boundary smoothing, as fabvdb_mesh_decompose does with the same options.
 * mesh: borrowed (copied into the session). opts: NULL for the defaults.
 * out: receives the session, owned by the caller (fabvdb_decomposition_free).
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT (NULL handle or out, an
 * option out of range), FABVDB_ERR_BAD_INPUT (a mesh enclosing no volume),
 * FABVDB_ERR_OUT_OF_BUDGET, FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED.
 * Reports progress. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_new(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                                  const fabvdb_decompose_options* opts, fabvdb_decomposition** out);
/* Makes a session from a decomposition.json (written by fabvdb_mesh_decompose
 * or fabvdb_decomposition_write) of `mesh`: its S_low, labels and parting
 * directions; the moldability terms are computed again and the parting lines
 * recomputed. The session's first step is that decomposition (no edits).
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_IO (unreadable
 * file), FABVDB_ERR_BAD_INPUT (malformed, or of another model or scale: the
 * message names the file and the defect), FABVDB_ERR_OUT_OF_MEMORY,
 * FABVDB_ERR_CANCELLED. Reports progress. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_read(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const char* path,
                                                   fabvdb_decomposition** out);
/* Frees a session. NULL does nothing. (since 0.1) */
FABVDB_API void fabvdb_decomposition_free(fabvdb_decomposition* session);

/* Applies one edit. On success it is a new undoable step and the redo steps
 * are dropped. Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT (NULL handle,
 * struct_size not set or from a newer header, an unknown type), FABVDB_ERR_BAD_INPUT (a malformed
 * edit: no points, a non-finite point, radius <= 0 for a brush, a cut of
 * fewer than two points, a merge not of two; or an edit that does not apply:
 * a cut that separates nothing, a merge of one part or of parts that do not
 * touch, a smoothing stroke that reaches no part boundary — the message says
 * which), FABVDB_ERR_CANCELLED, FABVDB_ERR_OUT_OF_MEMORY; on failure the
 * session is unchanged. Reports progress. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_apply(fabvdb_ctx* ctx, fabvdb_decomposition* session,
                                                    const fabvdb_edit* edit);
/* Applies one edit given as JSON text: one object of the edits file that
 * fabvdb_mesh_decompose reads, e.g. {"type": "cut", "points": [[x,y,z],
 * [x,y,z]], "closed": false} (for front ends that speak JSON). Returns as
 * fabvdb_decomposition_apply; malformed JSON or a malformed edit is
 * FABVDB_ERR_BAD_INPUT with the defect in the message. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_apply_json(fabvdb_ctx* ctx, fabvdb_decomposition* session,
                                                         const char* edit_json);
/* Runs the automatic decomposition again from S_low as it was before any
 * smoothing, with opts' gamma, parts, max_parts, draft_degrees, w_overhang,
 * w_overlap, w_coarse_overlap, smoothing_iterations and w_smooth (the other
 * fields are those the session was made with and are ignored). The edit list
 * starts anew; one undoable step. Returns FABVDB_OK,
 * FABVDB_ERR_INVALID_ARGUMENT (an option out of range), FABVDB_ERR_CANCELLED,
 * FABVDB_ERR_OUT_OF_MEMORY; on failure the session is unchanged. Reports
 * progress. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_rerun(fabvdb_ctx* ctx, fabvdb_decomposition* session,
                                                    const fabvdb_decompose_options* opts);
/* The options of the session's current step (the fields rerun reads; the
 * others as the session was made), into *out (its struct_size must be set).
 * Returns FABVDB_OK or FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_get_options(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                                          fabvdb_decompose_options* out);
/* Steps back to the previous step / forward to the one undone last. Returns
 * FABVDB_OK, FABVDB_ERR_NOT_FOUND (no such step; nothing changes) or
 * FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_undo(fabvdb_ctx* ctx, fabvdb_decomposition* session);
FABVDB_API fabvdb_status fabvdb_decomposition_redo(fabvdb_ctx* ctx, fabvdb_decomposition* session);

/* A summary of the current step. Fill struct_size (fabvdb_decomposition_info_init). (since 0.1) */
typedef struct fabvdb_decomposition_info {
    size_t struct_size;
    size_t part_count;
    double total_energy;  /* sum of the parts' moldability energies (unit-cube area) */
    double gamma;
    int over_gamma;       /* 1: total_energy >= gamma, the designer should be warned */
    double draft_degrees;
    size_t undo_steps;    /* steps fabvdb_decomposition_undo can take back */
    size_t redo_steps;
    size_t edit_count;    /* edits since the last automatic decomposition */
    double last_step_seconds; /* wall time of the last apply/rerun/undo/redo in the library */
} fabvdb_decomposition_info;
/* Sets struct_size and zeroes the rest. NULL does nothing. (since 0.1) */
FABVDB_API void fabvdb_decomposition_info_init(fabvdb_decomposition_info* info);
FABVDB_API fabvdb_status fabvdb_decomposition_get_info(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                                       fabvdb_decomposition_info* out);

/* One part of the current step. Fill struct_size (fabvdb_part_info_init). (since 0.1) */
typedef struct fabvdb_part_info {
    size_t struct_size;
    double direction[3];    /* unit parting direction d (M+ is pulled along +d) */
    double energy;          /* E_P = w_H E_H + w_L E_L (unit-cube area) */
    double overhang_energy; /* E_H */
    double overlap_energy;  /* E_L */
    double area;            /* outer area, mm^2 */
    size_t triangle_count;  /* S_low triangles in the part */
} fabvdb_part_info;
/* Sets struct_size and zeroes the rest. NULL does nothing. (since 0.1) */
FABVDB_API void fabvdb_part_info_init(fabvdb_part_info* info);
/* Returns FABVDB_OK, FABVDB_ERR_NOT_FOUND (part >= part_count) or
 * FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_get_part(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                                       size_t part, fabvdb_part_info* out);

/* Arrays of the current step, owned by the session and valid until the next
 * call that changes it (apply, rerun, undo, redo) or its free. A NULL session
 * gives 0 / NULL. (since 0.1) */
/* S_low: vertex_count*3 doubles (mm) and triangle_count*3 indices. Smoothing
 * moves vertices; the triangles never change within a session. */
FABVDB_API size_t fabvdb_decomposition_vertex_count(const fabvdb_decomposition* session);
FABVDB_API const double* fabvdb_decomposition_vertices(const fabvdb_decomposition* session);
FABVDB_API size_t fabvdb_decomposition_triangle_count(const fabvdb_decomposition* session);
FABVDB_API const uint32_t* fabvdb_decomposition_triangles(const fabvdb_decomposition* session);
/* Per S_low triangle: its part (0 .. part_count-1). */
FABVDB_API const int32_t* fabvdb_decomposition_labels(const fabvdb_decomposition* session);
/* Per S_low triangle: 1 if its outer face is in M+ (the mold half pulled
 * along +d of its part), 0 if in M-. */
FABVDB_API const uint8_t* fabvdb_decomposition_sides(const fabvdb_decomposition* session);
/* Per S_low triangle: the estimated deformation (its share of the weighted
 * moldability energy per unit-cube area, >= 0), the thesis' heat map. */
FABVDB_API const float* fabvdb_decomposition_deformation(const fabvdb_decomposition* session);

/* Kinds of polylines. (since 0.1) */
#define FABVDB_LINES_PARTING 0  /* the parting lines (M+ meets M-) of every part */
#define FABVDB_LINES_BOUNDARY 1 /* the boundaries between parts (each seen from both parts) */
/* The polylines of one kind: *points receives 3*(*point_count) doubles (mm),
 * *starts line_count+1 offsets into the points (line i is points
 * starts[i] .. starts[i+1]-1; a closed loop repeats its first point),
 * *parts the part of each line. Arrays owned as above. Returns FABVDB_OK or
 * FABVDB_ERR_INVALID_ARGUMENT (NULL handle or out-parameter, unknown kind).
 * (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_lines(fabvdb_ctx* ctx, const fabvdb_decomposition* session, int kind,
                                                    const double** points, size_t* point_count,
                                                    const size_t** starts, const int32_t** parts,
                                                    size_t* line_count);

/* Classes of the draft map. (since 0.1) */
#define FABVDB_DRAFT_POSITIVE 0 /* n.d >= sin(draft): releases from the half pulled along +d */
#define FABVDB_DRAFT_NEGATIVE 1 /* n.d <= -sin(draft): releases from the half pulled along -d */
#define FABVDB_DRAFT_NEEDED 2   /* |n.d| < sin(draft): steeper than the draft angle */
#define FABVDB_DRAFT_UNDERCUT 3 /* S_low lies in front of it along the side it faces */
/* Classifies every S_low triangle of the current step for pulling direction
 * `direction` (3 doubles, any non-zero vector) and draft angle draft_degrees
 * in [0, 30]. out: triangle_count bytes, caller-owned. Returns FABVDB_OK or
 * FABVDB_ERR_INVALID_ARGUMENT. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_draft_map(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                                        const double direction[3], double draft_degrees,
                                                        uint8_t* out);

/* Writes the current step as fabvdb_mesh_decompose writes its folder
 * (decomposition.json, which fabvdb_mesh_mold and fabvdb_decomposition_read
 * take, decomposition.ply, deformation.ply), atomically into out_dir.
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_IO. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_write(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                                    const char* out_dir);
/* Writes the edits since the last automatic decomposition as the JSON file
 * fabvdb_mesh_decompose's edits_path (fabvdb decompose --edits) replays, with
 * a "settings" object holding the options to replay them with; atomically.
 * Returns FABVDB_OK, FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_IO. (since 0.1) */
FABVDB_API fabvdb_status fabvdb_decomposition_write_edits(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                                          const char* path);

/* ------------------------------------------------------------------------- */
/* Molds (fabvdb mold)                                                        */
/* ------------------------------------------------------------------------- */
/* Bits of fabvdb_mold_options.flags. (since 0.1) */
/* One mold pair for all the parts, side by side in a row (each turned so its
 * parting direction is the row's), with a gate per part on one runner and
 * sprue, instead of a mold pair per part. */
#define FABVDB_MOLD_COMMON 1u

/* Parameters of mold generation. Fill with fabvdb_mold_options_init().
 * (since 0.1) */
typedef struct fabvdb_mold_options {
    size_t struct_size;  /* sizeof(fabvdb_mold_options), set by _init */
    unsigned flags;      /* FABVDB_MOLD_* bits; default 0 */
    double margin;       /* mold block margin around each part, mm, > 0; default 10 */
    double voxel_size;   /* level-set voxel, mm, >= 0; 0 (default): the bounding-box diagonal / 250 */
    double grid_step;    /* parting-surface grid step, mm, >= 0; 0 (default): margin / 8 */
    double density;      /* casting material, g/cm^3, > 0, for the weights; default 1.1 (polyurethane resin) */
} fabvdb_mold_options;

/* Fills *options with the defaults above and sets struct_size. NULL does
 * nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_mold_options_init(fabvdb_mold_options* options);

/* Turns each part of a mold decomposition of `mesh` into a cast-ready part and
 * a two-piece rigid mold (thesis section 3.6): the part's outer surface
 * restored from the full-resolution mesh, gaps along its parting direction
 * up to two voxels wide closed by an ARAP deformation (CGAL
 * Surface_mesh_deformation; the surface moves at most about a voxel), the
 * part swept into a double height field along its parting direction (the
 * added volume kept out of the other parts), then a block split by a smooth
 * RBF parting surface through the parting line, with a gate at the parting
 * line's lowest point (when the mold stands for pouring), a runner and a
 * sprue to the block's top, vents, and registration pins and holes, made by
 * exact CGAL booleans.
 * mesh: borrowed; the model the decomposition was made for.
 * decomposition_path: a decomposition.json written by fabvdb_mesh_decompose
 *   for this mesh at this scale, or NULL to run the decomposition first with
 *   decompose_opts (NULL: its defaults); its files then go to
 *   out_dir/decomposition/.
 * opts: NULL for the defaults.
 * out_dir: folder that receives parts/part_NN.stl (the cast parts) and
 *   molds/part_NN_top.stl, molds/part_NN_bottom.stl (NN = the part id, two
 *   digits or more), or with FABVDB_MOLD_COMMON molds/common_top.stl and
 *   molds/common_bottom.stl; built beside it and renamed into place at the
 *   end (an existing folder of that name is replaced), so a failed or
 *   cancelled call leaves no partial folder.
 * out_report: NULL, or receives a report (owned by the caller): voxel_size,
 *   margin, density, diagonal, part_count, parts [{id, file, top_file,
 *   bottom_file, parting_direction, volume (mm^3), weight (g),
 *   restored_volume, deformation {handles, max_displacement (mm),
 *   mean_displacement (mm), volume_change (mm^3)}, added_volume (by the
 *   sweep), added_volume_ratio, removed_by_keep_out, columns_trimmed,
 *   handed_over {given, received} (mm^3 of a part's own material handed to
 *   or from other parts where they split its columns),
 *   mean_distance_ratio, hausdorff_ratio, mold {size [e1, up, d] mm, center,
 *   up, gates, vents} or, with FABVDB_MOLD_COMMON, common_mold_offset}],
 *   common_mold {top_file, bottom_file, size, gates, vents} (row
 *   coordinates: a part's point p is at R p + common_mold_offset, R the
 *   rotation taking its parting direction to +Z), mean_distance_ratio and
 *   hausdorff_ratio (distances from the input surface, at its vertices and
 *   every voxel inside larger triangles, to the nearest part surface over the
 *   bounding-box diagonal; the mean weighted by area; input surface that
 *   the input's own solid encloses, such as the inner faces of overlapping
 *   shells, left out), fidelity (the assembled parts against the input: far
 *   is 1% of the diagonal, at most 5% of the surface; docs/reports.md#fidelity),
 *   timings {stage: seconds, total}, and decomposition (the decomposition's report, when it
 *   ran) or decomposition_file.
 * Returns FABVDB_OK; FABVDB_ERR_INVALID_ARGUMENT (NULL mesh or out_dir, an
 * option out of range, struct_size not set or from a newer header); FABVDB_ERR_BAD_INPUT (a
 * decomposition file that is malformed, misses parts or belongs to another
 * model or scale: the message names the file and the defect; a part that
 * cannot be molded); FABVDB_ERR_IO; FABVDB_ERR_OUT_OF_BUDGET;
 * FABVDB_ERR_CANCELLED; FABVDB_ERR_OUT_OF_MEMORY; FABVDB_ERR_INTERNAL (the
 * parts are not the input's model: the fidelity gate). The report is untouched on
 * failure. Reports progress. A context is used by one thread at a time.
 * (since 0.1) */
FABVDB_API fabvdb_status fabvdb_mesh_mold(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const char* decomposition_path,
                                          const fabvdb_decompose_options* decompose_opts,
                                          const fabvdb_mold_options* opts, const char* out_dir,
                                          fabvdb_report** out_report);

/* ------------------------------------------------------------------------- */
/* Printability (fabvdb check)                                                */
/* ------------------------------------------------------------------------- */
/* Options of fabvdb_mesh_check. Fill with fabvdb_check_options_init().
 * (since 0.1) */
typedef struct fabvdb_check_options {
    size_t struct_size;          /* sizeof(fabvdb_check_options), set by _init */
    const char* process;         /* "sla" (default: resin), "powder" (SLS, MJF, binder jetting),
                                    "fdm", or the path of a JSON profile (FILE.json; keys in
                                    docs/check.md). Borrowed. */
    double up[3];                /* the build direction in the part's frame, need not be
                                    unit; default 0 0 1 */
    double build_volume[3];      /* the printer's build volume, mm; default 0 0 0: not checked */
    double voxel_size;           /* mm, >= 0; 0 (default): the longest side / resolution,
                                    kept between the process' minimum wall / 4 and / 2 */
    int resolution;              /* >= 1; voxels along the longest side that set the
                                    automatic voxel size; default 400 */
    const char* thickness_map_path; /* NULL (default), or a .ply file that receives the part's
                                    surface coloured by local wall thickness (a `quality`
                                    property in mm, viridis colours from 0 to twice the largest
                                    of the minimum wall and pin), and beside it STEM.png, its
                                    legend. Borrowed. */
} fabvdb_check_options;

/* Fills *options with the defaults above and sets struct_size. NULL does
 * nothing. Thread-safe. (since 0.1) */
FABVDB_API void fabvdb_check_options_init(fabvdb_check_options* options);

/* Judges whether a part will print in a process as it is, as a farm checks an
 * order: the mesh's defects and the path repair would take, units, local wall
 * thickness (measured on the solid's signed distance, not by rays), pins
 * under the minimum diameter and pieces under the minimum feature, holes and
 * channels under the minimum width, sealed cavities, overhangs for `up`, and
 * the build volume. The report has verdict ("pass", "warn" or "fail": the
 * worst check), process (the profile's thresholds), voxel_size,
 * surface_vertices, checks {mesh, units, wall_thickness, small_features,
 * holes, trapped_volumes, overhangs, build_volume (with a build volume)},
 * each with status, message and its figures in mm with the places they
 * concern (docs/check.md), warnings and timings. A part that fails is a
 * finding in the report, not an error.
 * mesh: borrowed. options: borrowed; NULL means the defaults. out: receives
 * the report, owned by the caller.
 * Returns FABVDB_OK; FABVDB_ERR_INVALID_ARGUMENT (NULL ctx, mesh or out, an
 * unknown process, an option out of range, struct_size not set or from a
 * newer header); FABVDB_ERR_IO (the profile or the heat map cannot be read or
 * written); FABVDB_ERR_BAD_INPUT (a malformed profile, a mesh that encloses no
 * volume; the message names the file); FABVDB_ERR_OUT_OF_BUDGET;
 * FABVDB_ERR_OUT_OF_MEMORY; FABVDB_ERR_CANCELLED (no report and no heat map is
 * left). Reports progress. A context is used by one thread at a time.
 * (since 0.1) */
FABVDB_API fabvdb_status fabvdb_mesh_check(fabvdb_ctx* ctx, const fabvdb_mesh* mesh,
                                           const fabvdb_check_options* options, fabvdb_report** out);

#ifdef __cplusplus
}
#endif

#endif /* FABVDB_H */
