/* cmd_repair.c — `fabvdb repair IN -o OUT`: turns a dirty mesh (holes,
 * self-intersections, flipped or duplicated triangles, soups, overlapping
 * shells) into a clean watertight solid, at mesh level when that fixes it
 * exactly, else through a robust level set; or writes the level set itself
 * when OUT ends in .vdb. */
#include <stdio.h>
#include <string.h>

#include "commands.h"

static const cli_option options[] = {
    {"--output", 'o', CLI_STRING, "OUT", NULL, "the repaired mesh (.stl .obj .ply .off .3mf), or the level set (.vdb)"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL,
     "voxel size (default: the longest bounding-box side / 400, 0.25 mm on a 100 mm part); not with --resolution"},
    {"--resolution", 0, CLI_INT, "N", NULL, "voxel = longest bounding-box side / N (N >= 8); not with --voxel"},
    {"--adaptivity", 0, CLI_NUMBER, "A", "0", "extraction adaptivity 0..1: fewer triangles on flat regions"},
    {"--volumetric", 0, CLI_FLAG, NULL, NULL,
     "always re-mesh through the level set, even an input that is clean or fixable at mesh level"},
    {"--no-snap", 0, CLI_FLAG, NULL, NULL, "keep output vertices where the voxels put them (no snapping onto the input)"},
    {"--min-shell-volume", 0, CLI_NUMBER, "MM3", "0", "drop solid shells under this volume in mm^3 (0 keeps all)"},
    {"--thicken", 0, CLI_LENGTH, "LEN", NULL, "turn an input that encloses no volume (an open sheet) into a sheet this thick"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/repair.md)"},
};

static int run_repair(cli_run* run) {
    const char* output = cli_get(run, "--output")->text;
    if (!cli_get(run, "--output")->set) return cli_usage_error(run, "-o OUT is required");
    fabvdb_volume_options options;
    fabvdb_volume_options_init(&options);
    options.adaptivity = cli_get(run, "--adaptivity")->number;
    options.min_shell_volume = cli_get(run, "--min-shell-volume")->number;
    if (cli_get(run, "--no-snap")->given) options.flags |= FABVDB_REPAIR_NO_SNAP;
    if (cli_get(run, "--volumetric")->given) options.flags |= FABVDB_REPAIR_VOLUMETRIC;

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    const double diagonal = cli_mesh_diagonal(mesh);
    code = cli_voxel_size(run, mesh, &options.voxel_size);
    if (code != CLI_EXIT_OK) {
        fabvdb_mesh_free(mesh);
        return code;
    }
    if (cli_get(run, "--thicken")->set) {
        options.thicken = cli_length_mm(run, "--thicken", diagonal);
        if (!(options.thicken > 0.0)) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--thicken must be positive");
        }
    }

    fabvdb_report* report = NULL;
    fabvdb_status status;
    if (cli_is_level_set_path(output)) {
        fabvdb_volume* volume = NULL;
        status = fabvdb_volume_from_mesh(run->ctx, mesh, &options, &volume, &report);
        if (status == FABVDB_OK) status = fabvdb_volume_write(run->ctx, volume, output);
        fabvdb_volume_free(volume);
    } else {
        fabvdb_mesh* repaired = NULL;
        /* The report (with its inspection of the input) only when someone reads it. */
        const int wanted = cli_get(run, "--report")->set || !run->quiet;
        status = fabvdb_mesh_repair(run->ctx, mesh, &options, &repaired, wanted ? &report : NULL);
        if (status == FABVDB_OK) status = fabvdb_mesh_write(run->ctx, repaired, output);
        if (status == FABVDB_OK && report) cli_print_warnings(run, report);
        fabvdb_mesh_free(repaired);
    }
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) {
        fabvdb_report_free(report);
        return cli_fail(run, status);
    }
    cli_note(run, "wrote %s", output);
    double mesh_level = 0, fixes = 0, voxel_shells = 0;
    if (report && fabvdb_report_number(run->ctx, report, "/mesh_level", &mesh_level) == FABVDB_OK) {
        fabvdb_report_number(run->ctx, report, "/fix_count", &fixes);
        fabvdb_report_number(run->ctx, report, "/volumetric_shell_count", &voxel_shells);
        if (!mesh_level)
            cli_note(run, "re-meshed through the level set");
        else if (voxel_shells > 0)
            cli_note(run, "fixed at mesh level where that sufficed; %.0f shells re-meshed through the level set",
                     voxel_shells);
        else
            cli_note(run, "%s", fixes == 0 ? "the input already was a clean solid: written as it is"
                                           : "fixed at mesh level, keeping the input's triangles");
    }
    code = cli_write_report(run, report);
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_repair = {
    "repair",
    "make a clean watertight solid of a dirty mesh (holes, self-intersections, soups, flipped shells)",
    "INPUT -o OUTPUT [--voxel LEN | --resolution N] [--volumetric] [--adaptivity A] [--no-snap] "
    "[--min-shell-volume V] [--thicken LEN] [--report R.json]",
    "Changes no more than it must. An INPUT that already is a clean solid is written as it is; one whose\n"
    "defects are exactly fixable at mesh level (unwelded points, degenerate or duplicate triangles, flipped\n"
    "shells, shells that cross: their union) keeps its own triangles (report: path \"input\" or \"mesh\").\n"
    "Anything else (holes, non-manifold or touching sheets), or with --volumetric, --thicken or\n"
    "--min-shell-volume, goes volumetric (path \"volumetric\"): INPUT becomes a narrow-band signed distance\n"
    "field whose inside is decided by the generalized\n"
    "winding number, so holes close smoothly, inverted shells count as solids and overlapping shells unite,\n"
    "then extracts its surface: closed, 2-manifold, outward-oriented, free of self-intersections. Output\n"
    "vertices within a voxel of a clean part of the input are snapped onto it (unless --no-snap). With\n"
    "-o FILE.vdb the level set itself is written. Before allocating, the memory is estimated; over\n"
    "--max-memory the command exits with 3 and proposes a voxel size that fits. An INPUT that encloses\n"
    "no volume (an open sheet, a single scan, a soup of unconnected triangles) is refused at once with\n"
    "exit 2 unless --thicken is given. The output is checked as written (closed, 2-manifold, no\n"
    "crossing, no degenerate triangle); a result that fails is not written (exit 4).",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_repair};
