/* cmd_hollow.c — `fabvdb hollow IN -o OUT --wall 3mm`: hollows a part for
 * printing (a wall under the outer surface, the rest emptied), optionally
 * with a rounded cavity (--closing) and small voids filled (--min-cavity);
 * writes the mesh and, with --report,
 * every figure as JSON. */
#include <stdio.h>
#include <string.h>

#include "commands.h"

static const cli_option options[] = {
    {"--output", 'o', CLI_STRING, "OUT", NULL, "the hollowed mesh (.stl .obj .ply .off .3mf), or the shell level set (.vdb)"},
    {"--wall", 0, CLI_LENGTH, "LEN", "3mm", "wall thickness (regions thinner than twice this stay solid)"},
    {"--closing", 0, CLI_LENGTH, "LEN", "0mm",
     "closing distance: offset the cavity by -(wall+closing) then +closing, rounding it (PrusaSlicer's meaning)"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL, "voxel size (default: wall/4; the wall is snapped exactly anyway); not with --resolution"},
    {"--resolution", 0, CLI_INT, "N", NULL, "voxel = longest bounding-box side / N (N >= 8); not with --voxel"},
    {"--adaptivity", 0, CLI_NUMBER, "A", "0", "simplification of the cavity surface, 0 (none) to 1"},
    {"--min-cavity", 0, CLI_NUMBER, "MM3", "0", "fill voids smaller than this volume (mm^3)"},
    {"--infill", 0, CLI_STRING, "PATTERN", NULL, "fill the cavity with an open-cell lattice joined to the wall: gyroid"},
    {"--cell", 0, CLI_LENGTH, "LEN", "10mm", "infill cell size"},
    {"--strut", 0, CLI_LENGTH, "LEN", "1.2mm", "infill strut diameter (at most cell/4; the automatic voxel is then strut/4)"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/hollow.md)"},
};

static int run_hollow(cli_run* run) {
    const cli_value* output = cli_get(run, "--output");
    if (!output->set) return cli_usage_error(run, "no output: give -o OUT");

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    const double diagonal = cli_mesh_diagonal(mesh);

    fabvdb_hollow_options opts;
    fabvdb_hollow_options_init(&opts);
    opts.wall = cli_length_mm(run, "--wall", diagonal);
    opts.closing = cli_length_mm(run, "--closing", diagonal);
    code = cli_voxel_size(run, mesh, &opts.voxel_size);
    if (code != CLI_EXIT_OK) {
        fabvdb_mesh_free(mesh);
        return code;
    }
    opts.adaptivity = cli_get(run, "--adaptivity")->number;
    opts.min_cavity_volume = cli_get(run, "--min-cavity")->number;
    const cli_value* infill = cli_get(run, "--infill");
    if (infill->set) {
        if (strcmp(infill->text, "gyroid") != 0) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--infill: unknown pattern '%s' (known: gyroid)", infill->text);
        }
        opts.infill_cell = cli_length_mm(run, "--cell", diagonal);
        opts.infill_strut = cli_length_mm(run, "--strut", diagonal);
    } else if (cli_get(run, "--cell")->given || cli_get(run, "--strut")->given) {
        fabvdb_mesh_free(mesh);
        return cli_usage_error(run, "--cell and --strut need --infill gyroid");
    }

    fabvdb_report* report = NULL;
    fabvdb_status status;
    if (cli_is_level_set_path(output->text)) {
        fabvdb_volume* shell = NULL;
        status = fabvdb_mesh_hollow_volume(run->ctx, mesh, &opts, &shell, &report);
        if (status == FABVDB_OK) status = fabvdb_volume_write(run->ctx, shell, output->text);
        fabvdb_volume_free(shell);
    } else {
        fabvdb_mesh* hollowed = NULL;
        status = fabvdb_mesh_hollow(run->ctx, mesh, &opts, &hollowed, &report);
        if (status == FABVDB_OK) status = fabvdb_mesh_write(run->ctx, hollowed, output->text);
        fabvdb_mesh_free(hollowed);
    }
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) {
        fabvdb_report_free(report);
        return cli_fail(run, status);
    }
    cli_note(run, "wrote %s", output->text);

    double solid = 0, shell_volume = 0, saved = 0, cavities = 0, voxel = 0;
    fabvdb_report_number(run->ctx, report, "/volume_solid", &solid);
    fabvdb_report_number(run->ctx, report, "/volume_shell", &shell_volume);
    fabvdb_report_number(run->ctx, report, "/material_saved_fraction", &saved);
    fabvdb_report_number(run->ctx, report, "/cavity_count", &cavities);
    fabvdb_report_number(run->ctx, report, "/voxel_size", &voxel);
    cli_note(run, "solid %.1f mm^3, shell %.1f mm^3, %.1f%% material saved, %.0f cavities (voxel %.3g mm)", solid,
             shell_volume, 100.0 * saved, cavities, voxel);
    cli_print_warnings(run, report);

    code = cli_write_report(run, report);
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_hollow = {
    "hollow",
    "hollow a part for printing: a wall under the surface, the inside emptied",
    "INPUT -o OUTPUT --wall LEN [--closing LEN] [--voxel LEN | --resolution N] [--infill gyroid --cell LEN "
    "--strut LEN] [--report R.json]",
    "Keeps a wall of --wall under the outer surface and empties the rest, as resin and powder printers\n"
    "want. A dirty input (holes, self-intersections, flipped triangles, several shells) is repaired\n"
    "through a robust signed distance first; a clean closed input keeps its own outer triangles.\n"
    "The cavity is the inward offset by the wall, snapped to the exact distance from the outer\n"
    "surface; --closing rounds it (offset by -(wall+closing), then +closing). Regions thinner than\n"
    "twice the wall stay solid; voids under --min-cavity are filled. The output has the outer shells\n"
    "facing out and the cavity shells facing in, all closed and disjoint; with -o FILE.vdb the shell\n"
    "level set (negative in the material) is written instead.\n"
    "--infill gyroid adds struts of diameter --strut along the skeleton of one gyroid labyrinth (the\n"
    "srs net, 12 struts per cubic cell of side --cell), unioned with the shell: every strut is joined\n"
    "to the wall and the void around them stays one open-cell region, so powder and resin drain.\n"
    "A part nowhere thicker than twice the wall comes back solid, with a warning and cavity_count 0.\n"
    "Exit 1 for a bad parameter (wall <= 0), 3 when the voxel size needs more memory than --max-memory.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_hollow};
