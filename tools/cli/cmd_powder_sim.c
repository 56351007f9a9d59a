/* cmd_powder_sim.c — `fabvdb powder-sim IN --holes-from R.json`: the reference
 * powder simulation. Fills the cavity of IN (a hollow part, drilled or not)
 * with powder, opens the holes of a drain report, and runs sand-pile rules
 * through an operator's routine of turns; reports the powder left inside. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "common/file_text.h"
#include "common/status_text.h"
#include "orientation_file.h"

static const cli_option options[] = {
    {"--holes-from", 0, CLI_STRING, "R.json", NULL, "the holes to open: a `fabvdb drain` report's holes[] array"},
    {"--orientations", 0, CLI_STRING, "all|FILE", "all", "the set later turns are drawn from (as for drain)"},
    {"--turns", 0, CLI_INT, "N", "10", "turns of the routine, the first (as printed, -z down) included"},
    {"--seed", 0, CLI_INT, "S", "1", "seed of the draws of the later turns"},
    {"--repose", 0, CLI_ANGLE, "ANGLE", "35deg", "the powder's angle of repose"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL, "sand-pile cell size (default: diagonal / 150, at most a quarter hole)"},
    {"--routine", 0, CLI_STRING, "R.json", NULL,
     "replay exactly this routine: a drain report's routine[] (or an array of gravities)"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/powder-sim.md)"},
};

/* The whole file of an option, or NULL after printing why. */
static char* read_text(const cli_run* run, const char* path, const char* what) {
    char* text = file_text_read(path, NULL);
    if (!text) status_print(run->command->name, FABVDB_ERR_IO, "%s: cannot read the %s file", path, what);
    return text;
}

static int run_powder_sim(cli_run* run) {
    const cli_value* holes_path = cli_get(run, "--holes-from");
    if (!holes_path->set) return cli_usage_error(run, "--holes-from R.json is required");
    fabvdb_powder_options powder;
    fabvdb_powder_options_init(&powder);
    powder.turns = (int)cli_get(run, "--turns")->number;
    powder.seed = (uint64_t)cli_get(run, "--seed")->number;
    powder.repose_degrees = cli_get(run, "--repose")->number;
    if (cli_get(run, "--seed")->number < 0) return cli_usage_error(run, "--seed must be >= 0");

    const cli_value* routine_path = cli_get(run, "--routine");
    if (routine_path->set && (cli_get(run, "--turns")->given || cli_get(run, "--seed")->given))
        return cli_usage_error(run, "--routine replays its own turns: --turns and --seed do not apply");
    char* holes = read_text(run, holes_path->text, "holes");
    if (!holes) return CLI_EXIT_BAD_INPUT;
    char* routine = NULL;
    if (routine_path->set) {
        routine = read_text(run, routine_path->text, "routine");
        if (!routine) {
            free(holes);
            return CLI_EXIT_BAD_INPUT;
        }
        powder.routine_json = routine;
    }
    double* orientations = NULL;
    int code = cli_read_orientations(run, cli_get(run, "--orientations")->text, &orientations,
                                     &powder.orientation_count);
    if (code != CLI_EXIT_OK) {
        free(holes);
        free(routine);
        return code;
    }
    powder.orientations = orientations;
    fabvdb_mesh* mesh = NULL;
    code = cli_read_input(run, run->positional[0], &mesh);
    if (code == CLI_EXIT_OK) code = cli_voxel_size(run, mesh, &powder.voxel_size);
    fabvdb_report* report = NULL;
    fabvdb_status status = FABVDB_OK;
    if (code == CLI_EXIT_OK) status = fabvdb_powder_simulate(run->ctx, mesh, holes, &powder, &report);
    fabvdb_mesh_free(mesh);
    free(holes);
    free(routine);
    free(orientations);
    if (code != CLI_EXIT_OK) return code;
    if (status != FABVDB_OK) return cli_fail(run, status);
    const int written = cli_write_report(run, report);
    if (written != CLI_EXIT_OK) {
        fabvdb_report_free(report);
        return written;
    }
    double initial = 0, residual = 0, fraction = 0;
    fabvdb_report_number(run->ctx, report, "/initial_volume", &initial);
    fabvdb_report_number(run->ctx, report, "/residual_volume", &residual);
    fabvdb_report_number(run->ctx, report, "/residual_fraction", &fraction);
    double turns = powder.turns;
    fabvdb_report_number(run->ctx, report, "/turns", &turns);
    printf("powder left inside after %.0f turns: %.1f mm^3 of %.1f mm^3 (%.2f%%)\n", turns, residual, initial,
           100.0 * fraction);
    fabvdb_report_free(report);
    return CLI_EXIT_OK;
}

const cli_command cmd_powder_sim = {
    "powder-sim",
    "simulate how much powder stays trapped in a drilled hollow part (reference check)",
    "IN --holes-from R.json [--orientations all|FILE] [--turns N] [--seed S | --routine R.json] [--report FILE.json]",
    "Independent of the drainability model behind `fabvdb drain`: fills the cavity of IN with voxels of\n"
    "powder, opens the holes listed in R.json, and runs sand-pile rules with the angle of repose through\n"
    "a routine like an operator's: first as printed (-z down), then turns drawn with --seed from the\n"
    "orientation set, or exactly the routine of --routine (the cleaning routine a drain report recommends).\n"
    "Prints and reports the powder left inside.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_powder_sim};
