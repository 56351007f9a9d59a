/* cmd_repair.c — `fabvdb repair IN -o OUT`: turns a dirty mesh (holes,
 * self-intersections, flipped or duplicated triangles, soups, overlapping
 * shells) into a clean watertight solid through a robust level set, or writes
 * the level set itself when OUT ends in .vdb. */
#include <stdio.h>
#include <string.h>

#include "commands.h"

static const cli_option options[] = {
    {"--output", 'o', CLI_STRING, "OUT", NULL, "the repaired mesh (.stl .obj .ply .off .3mf), or the level set (.vdb)"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL, "voxel size (e.g. 0.2mm, or 0.1% of the diagonal); overrides --resolution"},
    {"--resolution", 0, CLI_INT, "N", "400", "voxels along the longest bounding-box side (0.25 mm on a 100 mm part)"},
    {"--adaptivity", 0, CLI_NUMBER, "A", "0", "extraction adaptivity 0..1: fewer triangles on flat regions"},
    {"--no-snap", 0, CLI_FLAG, NULL, NULL, "keep output vertices where the voxels put them (no snapping onto the input)"},
    {"--min-shell-volume", 0, CLI_NUMBER, "MM3", "0", "drop solid shells under this volume in mm^3 (0 keeps all)"},
    {"--thicken", 0, CLI_LENGTH, "LEN", NULL, "turn an input that encloses no volume (an open sheet) into a sheet this thick"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: README 'fabvdb repair')"},
};

static int run_repair(cli_run* run) {
    const char* output = cli_get(run, "--output")->text;
    if (!cli_get(run, "--output")->set) return cli_usage_error(run, "-o OUT is required");
    fabvdb_volume_options options;
    fabvdb_volume_options_init(&options);
    options.resolution = (int)cli_get(run, "--resolution")->number;
    options.adaptivity = cli_get(run, "--adaptivity")->number;
    options.min_shell_volume = cli_get(run, "--min-shell-volume")->number;
    if (cli_get(run, "--no-snap")->given) options.flags |= FABVDB_REPAIR_NO_SNAP;
    if (options.resolution < 8) return cli_usage_error(run, "--resolution must be at least 8");
    if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0))
        return cli_usage_error(run, "--adaptivity must be between 0 and 1");
    if (!(options.min_shell_volume >= 0.0)) return cli_usage_error(run, "--min-shell-volume must be >= 0");

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    const double diagonal = cli_mesh_diagonal(mesh);
    if (cli_get(run, "--voxel")->set) {
        options.voxel_size = cli_length_mm(run, "--voxel", diagonal);
        if (!(options.voxel_size > 0.0)) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--voxel must be positive");
        }
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
        status = fabvdb_mesh_repair(run->ctx, mesh, &options, &repaired,
                                    cli_get(run, "--report")->set ? &report : NULL);
        if (status == FABVDB_OK) status = fabvdb_mesh_write(run->ctx, repaired, output);
        fabvdb_mesh_free(repaired);
    }
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) {
        fabvdb_report_free(report);
        return cli_fail(run, status);
    }
    cli_note(run, "wrote %s", output);
    code = cli_write_report(run, report);
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_repair = {
    "repair",
    "make a clean watertight solid of a dirty mesh (holes, self-intersections, soups, flipped shells)",
    "INPUT -o OUTPUT [--voxel LEN | --resolution N] [--adaptivity A] [--no-snap] [--min-shell-volume V] "
    "[--thicken LEN] [--report R.json]",
    "Converts INPUT to a narrow-band signed distance field whose inside is decided by the generalized\n"
    "winding number, so holes close smoothly, inverted shells count as solids and overlapping shells unite,\n"
    "then extracts its surface: closed, 2-manifold, outward-oriented, free of self-intersections. Output\n"
    "vertices within a voxel of a clean part of the input are snapped onto it (unless --no-snap). With\n"
    "-o FILE.vdb the level set itself is written. Before allocating, the memory is estimated; over\n"
    "--max-memory the command exits with 3 and proposes a voxel size that fits.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_repair};
