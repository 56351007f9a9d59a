/* cmd_mold.c — `fabvdb mold IN -o OUTDIR`: turns each part of a mold
 * decomposition (read from --decomposition, or computed first) into a
 * cast-ready part and a two-piece rigid mold with gate, runner, sprue, vents
 * and registration keys (thesis section 3.6). */
#include <stdio.h>

#include "commands.h"

static const cli_option options[] = {
    {"--output", 'o', CLI_STRING, "OUTDIR", NULL,
     "folder for parts/part_NN.stl and molds/part_NN_{top,bottom}.stl (replaced atomically)"},
    {"--decomposition", 0, CLI_STRING, "D.json", NULL,
     "decomposition.json from `fabvdb decompose` of this input at this scale; default: decompose first"},
    {"--common-mold", 0, CLI_FLAG, NULL, NULL,
     "one mold pair for all parts side by side (molds/common_{top,bottom}.stl) instead of one per part"},
    {"--mold-margin", 0, CLI_LENGTH, "LEN", "10mm", "block margin around each part (also sizes runner and keys)"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL, "level-set voxel of restoration and sweeping; default diagonal / 250"},
    {"--grid-step", 0, CLI_LENGTH, "LEN", NULL, "parting-surface grid step; default margin / 8"},
    {"--density", 0, CLI_NUMBER, "G_PER_CM3", "1.1", "casting material density for the weights in the report"},
    {"--shell", 0, CLI_LENGTH, "LEN", NULL, "decomposition (without --decomposition): shell thickness omega"},
    {"--solid", 0, CLI_FLAG, NULL, NULL, "decomposition (without --decomposition): cast solid parts"},
    {"--gamma", 0, CLI_NUMBER, "G", "0.05", "decomposition (without --decomposition): moldability energy threshold"},
    {"--parts", 0, CLI_STRING, "auto|N", "auto", "decomposition (without --decomposition): part count"},
    {"--low-res", 0, CLI_INT, "N", "10000", "decomposition (without --decomposition): low-resolution triangles"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/mold.md)"},
};

static int run_mold(cli_run* run) {
    const cli_value* output = cli_get(run, "--output");
    if (!output->set) return cli_usage_error(run, "-o OUTDIR is required");
    const cli_value* decomposition = cli_get(run, "--decomposition");
    fabvdb_decompose_options decompose;
    fabvdb_decompose_options_init(&decompose);
    decompose.gamma = cli_get(run, "--gamma")->number;
    const int parts_code = cli_part_count(run, "--parts", &decompose.parts);
    if (parts_code != CLI_EXIT_OK) return parts_code;
    decompose.low_res_triangles = (int)cli_get(run, "--low-res")->number;
    if (cli_get(run, "--solid")->given) decompose.flags |= FABVDB_DECOMPOSE_SOLID;
    if (decomposition->set && (cli_get(run, "--shell")->given || cli_get(run, "--solid")->given ||
                               cli_get(run, "--gamma")->given || cli_get(run, "--parts")->given ||
                               cli_get(run, "--low-res")->given))
        return cli_usage_error(run, "--shell, --solid, --gamma, --parts and --low-res set up a decomposition; "
                                    "they do not go with --decomposition");
    fabvdb_mold_options options;
    fabvdb_mold_options_init(&options);
    options.density = cli_get(run, "--density")->number;
    if (cli_get(run, "--common-mold")->given) options.flags |= FABVDB_MOLD_COMMON;

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    const double diagonal = cli_mesh_diagonal(mesh);
    options.margin = cli_length_mm(run, "--mold-margin", diagonal);
    code = cli_voxel_size(run, mesh, &options.voxel_size);
    if (code != CLI_EXIT_OK) {
        fabvdb_mesh_free(mesh);
        return code;
    }
    if (cli_get(run, "--grid-step")->set) options.grid_step = cli_length_mm(run, "--grid-step", diagonal);
    if (cli_get(run, "--shell")->set) decompose.shell_thickness = cli_length_mm(run, "--shell", diagonal);
    if (!(options.margin > 0) || (cli_get(run, "--grid-step")->set && !(options.grid_step > 0)) ||
        (cli_get(run, "--shell")->set && !(decompose.shell_thickness > 0))) {
        fabvdb_mesh_free(mesh);
        return cli_usage_error(run, "--mold-margin, --grid-step and --shell must be positive");
    }
    fabvdb_report* report = NULL;
    fabvdb_status status = fabvdb_mesh_mold(run->ctx, mesh, decomposition->set ? decomposition->text : NULL,
                                            &decompose, &options, output->text, &report);
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) return cli_fail(run, status);
    double count = 0, mean = 0, hausdorff = 0;
    fabvdb_report_number(run->ctx, report, "/part_count", &count);
    fabvdb_report_number(run->ctx, report, "/mean_distance_ratio", &mean);
    fabvdb_report_number(run->ctx, report, "/hausdorff_ratio", &hausdorff);
    printf("%.0f parts with their molds; distance to the input: mean %.4f%%, max %.3f%% of the diagonal\n", count,
           100 * mean, 100 * hausdorff);
    cli_print_warnings(run, report);
    cli_note(run, "wrote %s", output->text);
    code = cli_write_report(run, report);
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_mold = {
    "mold",
    "make cast-ready parts and two-piece molds (gate, runner, sprue, vents, keys) from a decomposition",
    "INPUT -o OUTDIR [--decomposition D.json | --shell LEN --solid --gamma G --parts N --low-res N] "
    "[--common-mold] [--mold-margin LEN] "
    "[--density D] [--report R.json]",
    "Turns each part of a mold decomposition of INPUT (--decomposition, from `fabvdb decompose` of the same\n"
    "input at the same scale; without it the decomposition runs first and its files go to\n"
    "OUTDIR/decomposition/) into a cast-ready part and a two-piece rigid mold (thesis 'Fabrication-aware\n"
    "geometry optimization', section 3.6): the part's outer surface restored from the full-resolution input,\n"
    "the part made moldable along its parting direction by sweeping (material added, never inside another\n"
    "part), then a block with --mold-margin around it split by a smooth parting surface through the parting\n"
    "line, with a gate at the parting line's lowest point, a runner and a sprue to the block's top, vents,\n"
    "and registration pins and holes. OUTDIR receives parts/part_NN.stl and molds/part_NN_top.stl,\n"
    "molds/part_NN_bottom.stl (--common-mold: molds/common_top.stl and molds/common_bottom.stl, the parts in\n"
    "a row, one gate each on a shared runner). The top piece lifts off along the part's parting direction, the bottom along\n"
    "the opposite. The report gives per part its volume, weight at --density, the volume the sweep added,\n"
    "and how far the input lies from the parts (over the bounding-box diagonal).",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_mold};
