/* cmd_drain.c — `fabvdb drain IN -o OUT`: for powder printing, hollows a solid
 * part (or takes a hollow shell as is), finds where trapped powder can escape
 * and drills the best drain holes, with a report of the holes and the powder
 * predicted to stay, against holes at the lowest points. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "orientation_file.h"

static const cli_option options[] = {
    {"--output", 'o', CLI_STRING, "OUT", NULL, "the drilled part (.stl .obj .ply .off .3mf)"},
    {"--wall", 0, CLI_LENGTH, "LEN", "3mm", "wall thickness when a solid input is hollowed"},
    {"--holes", 0, CLI_STRING, "auto|K", "auto",
     "number of holes; auto: at least 2 per cavity, the fewest whose prediction under the cleaning routine is under --target"},
    {"--hole-diameter", 0, CLI_LENGTH, "LEN", "4mm", "drain hole diameter"},
    {"--repose", 0, CLI_ANGLE, "ANGLE", "35deg", "the powder's angle of repose"},
    {"--orientations", 0, CLI_STRING, "all|FILE", "all",
     "gravity directions the operator turns the part to: all = 162 icosphere directions, or a file of \"x y z\" lines"},
    {"--effort", 0, CLI_NUMBER, "RHO", "0.9", "chance the operator turns the part once more (about 1/(1-RHO) turns)"},
    {"--target", 0, CLI_STRING, "PCT", "1%",
     "automatic mode: the powder left under the cleaning routine that is good enough, a share of the cavity (1% or 0.01)"},
    {"--keep-out", 0, CLI_STRING, "FILE", NULL, "no hole here: a JSON file of spheres or a closed mesh"},
    {"--heatmap", 0, CLI_STRING, "HEAT.ply", NULL,
     "heat maps of the cavity: share of the powder that drains, and HEAT_left.ply, the powder left (+ PNG legends)"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL, "voxel size of the level sets (default: wall / 4)"},
    {"--patches", 0, CLI_INT, "N", "2000", "cavity surface patches of the drainability model"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/drain.md)"},
};

/* A share of the cavity: "1%" or "0.01" (both 0.01); false unless in [0, 1). */
static int parse_share(const char* text, double* share) {
    char* end = NULL;
    double value = strtod(text, &end);
    if (end == text) return 0;
    if (*end == '%') {
        value /= 100.0;
        ++end;
    }
    if (*end != '\0' || !(value >= 0.0 && value < 1.0)) return 0;
    *share = value;
    return 1;
}

/* Prints the report's cleaning routine, one line a turn. */
static void print_routine(cli_run* run, const fabvdb_report* report) {
    double routine = 0, mean = 0, spread = 0;
    if (fabvdb_report_number(run->ctx, report, "/routine_residual_fraction", &routine) != FABVDB_OK) return;
    fabvdb_report_number(run->ctx, report, "/random_routines/mean_fraction", &mean);
    fabvdb_report_number(run->ctx, report, "/random_routines/std_fraction", &spread);
    printf("cleaning routine (predicted powder left: %.2f%%; random turns instead: %.2f%% +- %.2f%%):\n",
           100.0 * routine, 100.0 * mean, 100.0 * spread);
    size_t steps = 0;
    fabvdb_report_count(run->ctx, report, "/routine", &steps);
    for (int step = 0; step < (int)steps; ++step) {
        char pointer[64];
        double tilt = 0.0, down, lowest, axis[3];
        snprintf(pointer, sizeof pointer, "/routine/%d/tilt_degrees", step);
        fabvdb_report_number(run->ctx, report, pointer, &tilt);
        for (int k = 0; k < 3; ++k) {
            snprintf(pointer, sizeof pointer, "/routine/%d/tilt_axis/%d", step, k);
            fabvdb_report_number(run->ctx, report, pointer, &axis[k]);
        }
        char where[64] = "";
        snprintf(pointer, sizeof pointer, "/routine/%d/hole_down", step);
        if (fabvdb_report_number(run->ctx, report, pointer, &down) == FABVDB_OK) {
            snprintf(where, sizeof where, "hole %.0f points down", down + 1);
        } else {
            snprintf(pointer, sizeof pointer, "/routine/%d/lowest_hole", step);
            if (fabvdb_report_number(run->ctx, report, pointer, &lowest) == FABVDB_OK)
                snprintf(where, sizeof where, "no hole points down; hole %.0f is lowest", lowest + 1);
        }
        if (step == 0)
            printf("  %2d. as printed: %s\n", step + 1, where);
        else if (tilt < 0.5)
            printf("  %2d. keep it as it is, tap it: %s\n", step + 1, where);
        else if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0)
            printf("  %2d. turn it upside down: %s\n", step + 1, where);
        else
            printf("  %2d. tilt %3.0f deg about (%5.2f, %5.2f, %5.2f): %s\n", step + 1, tilt, axis[0], axis[1], axis[2],
                   where);
    }
}

static int run_drain(cli_run* run) {
    const cli_value* output = cli_get(run, "--output");
    if (!output->set) return cli_usage_error(run, "-o OUT is required");
    fabvdb_drain_options drain;
    fabvdb_drain_options_init(&drain);
    const char* holes = cli_get(run, "--holes")->text;
    if (strcmp(holes, "auto") != 0) {
        char* end = NULL;
        const long k = strtol(holes, &end, 10);
        if (!end || *end != '\0' || k < 1 || k > INT_MAX) return cli_usage_error(run, "--holes takes auto or a count >= 1");
        drain.hole_count = (int)k;
    }
    drain.repose_degrees = cli_get(run, "--repose")->number;
    drain.effort = cli_get(run, "--effort")->number;
    if (!parse_share(cli_get(run, "--target")->text, &drain.target_residual))
        return cli_usage_error(run, "--target takes a percentage (1%) or a fraction (0.01) in [0, 1)");
    drain.patch_count = (int)cli_get(run, "--patches")->number;
    drain.keep_out_path = cli_get(run, "--keep-out")->set ? cli_get(run, "--keep-out")->text : NULL;
    drain.heatmap_path = cli_get(run, "--heatmap")->set ? cli_get(run, "--heatmap")->text : NULL;

    double* orientations = NULL;
    int code = cli_read_orientations(run, cli_get(run, "--orientations")->text, &orientations,
                                     &drain.orientation_count);
    if (code != CLI_EXIT_OK) return code;
    drain.orientations = orientations;

    fabvdb_mesh* mesh = NULL;
    code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) {
        free(orientations);
        return code;
    }
    const double diagonal = cli_mesh_diagonal(mesh);
    drain.wall = cli_length_mm(run, "--wall", diagonal);
    drain.hole_diameter = cli_length_mm(run, "--hole-diameter", diagonal);
    code = cli_voxel_size(run, mesh, &drain.voxel_size);
    if (code != CLI_EXIT_OK) {
        fabvdb_mesh_free(mesh);
        free(orientations);
        return code;
    }

    fabvdb_mesh* drilled = NULL;
    fabvdb_report* report = NULL;
    fabvdb_status status = fabvdb_mesh_drain(run->ctx, mesh, &drain, &drilled, &report);
    fabvdb_mesh_free(mesh);
    free(orientations);
    if (status != FABVDB_OK) return cli_fail(run, status);
    status = fabvdb_mesh_write(run->ctx, drilled, output->text);
    fabvdb_mesh_free(drilled);
    if (status != FABVDB_OK) {
        fabvdb_report_free(report);
        return cli_fail(run, status);
    }
    double cavities = 0;
    fabvdb_report_number(run->ctx, report, "/cavity_count", &cavities);
    cli_note(run, "wrote %s", output->text);
    if (drain.heatmap_path && cavities > 0)
        cli_note(run, "wrote %s, the powder-left map and their legends beside it", drain.heatmap_path);
    const int written = cli_write_report(run, report);
    if (written != CLI_EXIT_OK) {
        fabvdb_report_free(report);
        return written;
    }
    double predicted = 0, baseline = 0;
    size_t holes_count = 0;
    fabvdb_report_number(run->ctx, report, "/predicted_residual_fraction", &predicted);
    fabvdb_report_number(run->ctx, report, "/baseline_residual_fraction", &baseline);
    fabvdb_report_count(run->ctx, report, "/holes", &holes_count);
    cli_print_warnings(run, report);
    if (cavities > 0) {
        printf("%zu drain holes; predicted powder left inside: %.2f%% (lowest-point holes: %.2f%%)\n", holes_count,
               100.0 * predicted, 100.0 * baseline);
        print_routine(run, report);
    } else {
        printf("no cavity: no drain holes needed; the part is written solid\n");
    }
    fabvdb_report_free(report);
    return CLI_EXIT_OK;
}

const cli_command cmd_drain = {
    "drain",
    "place and drill drain holes so trapped powder can escape (powder printing)",
    "IN -o OUT [--wall 3mm] [--holes auto|K] [--hole-diameter 4mm] [--repose 35deg] [--orientations all|FILE]\n"
    "       [--keep-out FILE] [--heatmap HEAT.ply] [--report R.json]",
    "Hollows a solid IN with --wall (an IN that already is a hollow shell is used as is), models how loose\n"
    "powder moves in the cavity as the operator turns the part (floors flatter than the angle of repose\n"
    "hold it, steeper walls shed it, overhangs drop it; holes absorb it when their tunnel points down), and\n"
    "drills the holes that leave the least powder inside. Holes pass cleanly through the wall, keep a\n"
    "diameter apart and stay out of --keep-out regions; every cavity gets its own. The holes are never\n"
    "predicted to leave more than as many holes at the lowest points of the part as printed (-z down).\n"
    "Prints the cleaning routine for the holes: the turns, in words, that drain the most (replay it with\n"
    "`fabvdb powder-sim --routine`), with the powder predicted to stay under it and under random turns.\n"
    "A part with no cavity (nowhere thicker than twice the wall) needs no holes: it is written solid and\n"
    "undrilled, with a warning, and exit 0. A cavity that no hole of --hole-diameter reaches cleanly\n"
    "(too small, or behind a wall over twice --wall) is filled solid, with a warning.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_drain};
