/* cmd_info.c — `fabvdb info FILE`: what a person checking a print file wants to
 * know (size, topology, defects, volume), printed readably and, with --report,
 * written as JSON. Finds, never fixes: defects are data, the exit code is 0. */
#include <stdio.h>

#include "commands.h"

static const cli_option options[] = {
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/info.md)"},
};

static int number(const cli_run* run, const fabvdb_report* report, const char* pointer, double* out) {
    return fabvdb_report_number(run->ctx, report, pointer, out) == FABVDB_OK;
}

static void print_count(const cli_run* run, const fabvdb_report* report, const char* label, const char* pointer) {
    double value;
    if (number(run, report, pointer, &value)) printf("  %-26s %.0f\n", label, value);
}

static void print_yes_no(const cli_run* run, const fabvdb_report* report, const char* label, const char* pointer) {
    double value;
    if (number(run, report, pointer, &value)) printf("  %-26s %s\n", label, value != 0 ? "yes" : "no");
}

static int run_info(cli_run* run) {
    const char* path = run->positional[0];
    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, path, &mesh);
    if (code != CLI_EXIT_OK) return code;
    fabvdb_report* report = NULL;
    fabvdb_status status = fabvdb_mesh_inspect(run->ctx, mesh, &report);
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) return cli_fail(run, status);

    double a[3], b[3], value;
    printf("%s\n", path);
    print_count(run, report, "vertices", "/vertices");
    print_count(run, report, "triangles", "/triangles");
    print_count(run, report, "components", "/components");
    if (number(run, report, "/bbox/min/0", &a[0]) && number(run, report, "/bbox/min/1", &a[1]) &&
        number(run, report, "/bbox/min/2", &a[2]) && number(run, report, "/bbox/max/0", &b[0]) &&
        number(run, report, "/bbox/max/1", &b[1]) && number(run, report, "/bbox/max/2", &b[2]))
        printf("  %-26s %.3f x %.3f x %.3f mm  (from %.3f %.3f %.3f)\n", "size", b[0] - a[0], b[1] - a[1],
               b[2] - a[2], a[0], a[1], a[2]);
    print_yes_no(run, report, "closed (watertight)", "/closed");
    print_yes_no(run, report, "consistently oriented", "/consistently_oriented");
    if (number(run, report, "/volume", &value)) printf("  %-26s %.3f mm^3\n", "volume", value);
    if (number(run, report, "/genus", &value)) printf("  %-26s %.0f\n", "genus", value);
    printf("Defects:\n");
    print_count(run, report, "boundary edges", "/boundary_edges");
    print_count(run, report, "boundary loops (holes)", "/boundary_loops");
    print_count(run, report, "non-manifold edges", "/non_manifold_edges");
    print_count(run, report, "non-manifold vertices", "/non_manifold_vertices");
    print_count(run, report, "degenerate triangles", "/degenerate_triangles");
    print_count(run, report, "duplicate triangles", "/duplicate_triangles");
    print_count(run, report, "self-intersecting pairs", "/self_intersecting_pairs");
    print_count(run, report, "unreferenced vertices", "/unreferenced_vertices");
    cli_print_warnings(run, report);

    code = cli_write_report(run, report);
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_info = {
    "info",
    "describe a mesh file: size, topology, defects, volume",
    "FILE [--report R.json]",
    "Reads FILE (STL, OBJ, PLY, OFF or 3MF) and prints what matters before printing it: whether it is\n"
    "closed and consistently oriented, its holes, non-manifold edges and vertices, degenerate and\n"
    "duplicate triangles, self-intersecting triangle pairs (exact predicates), volume and genus.\n"
    "Topology is counted on the vertices as stored; 'welded' in the report repeats it after merging\n"
    "exactly coincident vertices.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_info};
