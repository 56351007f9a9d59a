/* cmd_decompose.c — `fabvdb decompose IN -o OUTDIR`: cuts the thin shell of a
 * free-form object (thin features stay solid) into as few parts as possible,
 * each castable in a two-piece rigid mold, with a parting direction and a
 * parting line per part, then applies the user's edits (thesis chapter 3). */
#include <stdio.h>

#include "commands.h"

static const cli_option options[] = {
    {"--output", 'o', CLI_STRING, "OUTDIR", NULL,
     "folder for decomposition.json, decomposition.ply, deformation.ply (replaced atomically)"},
    {"--shell", 0, CLI_LENGTH, "LEN", NULL,
     "shell thickness omega (3mm, or 2% of the diagonal); default 0.03 x the longest side"},
    {"--solid", 0, CLI_FLAG, NULL, NULL, "cast solid parts instead of shells"},
    {"--gamma", 0, CLI_NUMBER, "G", "0.05", "threshold on the total moldability energy (unit-cube area)"},
    {"--parts", 0, CLI_STRING, "auto|N", "auto",
     "part count, at least 2 per piece of the model (1 with --solid): auto adds parts until the energy is under gamma"},
    {"--max-parts", 0, CLI_INT, "N", "16", "cap of the automatic part count"},
    {"--draft", 0, CLI_ANGLE, "ANGLE", "1deg", "draft angle"},
    {"--low-res", 0, CLI_INT, "N", "10000", "triangles of the low-resolution surface the decomposition runs on"},
    {"--smoothing", 0, CLI_INT, "N", "10", "boundary-smoothing (snake) iterations; 0 keeps the grown boundaries"},
    {"--smoothness", 0, CLI_NUMBER, "W", "1", "weight w_l of boundary smoothness against moldability"},
    {"--edits", 0, CLI_STRING, "EDITS.json", NULL,
     "no_cut / cut / merge / smooth edits in world coordinates, applied in order"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/decompose.md)"},
};

static int run_decompose(cli_run* run) {
    const cli_value* output = cli_get(run, "--output");
    if (!output->set) return cli_usage_error(run, "-o OUTDIR is required");
    fabvdb_decompose_options options;
    fabvdb_decompose_options_init(&options);
    options.gamma = cli_get(run, "--gamma")->number;
    options.max_parts = (int)cli_get(run, "--max-parts")->number;
    options.draft_degrees = cli_get(run, "--draft")->number;
    options.low_res_triangles = (int)cli_get(run, "--low-res")->number;
    options.smoothing_iterations = (int)cli_get(run, "--smoothing")->number;
    options.w_smooth = cli_get(run, "--smoothness")->number;
    if (cli_get(run, "--solid")->given) options.flags |= FABVDB_DECOMPOSE_SOLID;
    const int parts_code = cli_part_count(run, "--parts", &options.parts);
    if (parts_code != CLI_EXIT_OK) return parts_code;

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    if (cli_get(run, "--shell")->set) {
        options.shell_thickness = cli_length_mm(run, "--shell", cli_mesh_diagonal(mesh));
        if (!(options.shell_thickness > 0.0)) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--shell must be positive");
        }
    }
    const cli_value* edits = cli_get(run, "--edits");
    fabvdb_report* report = NULL;
    fabvdb_status status = fabvdb_mesh_decompose(run->ctx, mesh, &options, edits->set ? edits->text : NULL,
                                                 output->text, &report);
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) return cli_fail(run, status);
    double count = 0, energy = 0, under = 0, solid_chosen = 0;
    fabvdb_report_number(run->ctx, report, "/part_count", &count);
    fabvdb_report_number(run->ctx, report, "/total_moldability_energy", &energy);
    fabvdb_report_number(run->ctx, report, "/under_gamma", &under);
    fabvdb_report_number(run->ctx, report, "/solid_chosen", &solid_chosen);
    printf("%.0f parts, total moldability energy %.5f (gamma %g)%s%s\n", count, energy, options.gamma,
           under != 0 ? "" : "  WARNING: over gamma",
           solid_chosen != 0 ? "  NOTE: thinner than twice the shell everywhere, parts cast solid (as --solid)" : "");
    cli_print_warnings(run, report);
    cli_note(run, "wrote %s", output->text);
    code = cli_write_report(run, report);
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_decompose = {
    "decompose",
    "cut a free-form object into parts that each cast in a two-piece mold (parting lines, edits)",
    "INPUT -o OUTDIR [--shell LEN] [--solid] [--gamma G] [--parts auto|N] [--draft ANGLE] [--smoothing N] "
    "[--edits EDITS.json] [--report R.json]",
    "Decomposes the thin shell of INPUT (thickness --shell; thin features stay solid, and a part thin\n"
    "everywhere is decomposed solid, as with --solid) into as few parts as\n"
    "possible, each moldable in a two-piece rigid mold, by the method of chapter 3 of the thesis 'Fabrication-aware geometry optimization':\n"
    "a low-resolution surface and prisms from the robust level set, region growing over the 162 candidate\n"
    "parting directions, a graph-cut parting line per part made of one top and one bottom patch. Parts are\n"
    "added from 2 until the total moldability energy (overhang plus overlap area, measured with the model\n"
    "scaled to a unit cube) is under --gamma. The part boundaries are then smoothed as snakes (--smoothing\n"
    "iterations) without raising the energy over --gamma. --edits applies no_cut strokes, cuts, merges and\n"
    "smoothing strokes given in world coordinates; only the touched parts change. OUTDIR receives\n"
    "decomposition.json (everything mold generation needs), decomposition.ply (the input coloured by part,\n"
    "bottom patches darker) and deformation.ply (the estimated deformation as a heat map).",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_decompose};
