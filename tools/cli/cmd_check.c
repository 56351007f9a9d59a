/* cmd_check.c — `fabvdb check INPUT`: will the part print in a process as it
 * is? Prints one line per check (status, figures, where to look), writes the
 * full report with --report and the wall-thickness heat map with
 * --thickness-map; exits 5 when the verdict reaches --fail-on, so a farm's
 * script can gate orders on it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"

static const cli_option options[] = {
    {"--process", 0, CLI_STRING, "sla|powder|fdm|FILE.json", "sla",
     "the process' thresholds: resin, powder bed (SLS, MJF, binder jetting), FDM, or a farm's own profile"},
    {"--up", 0, CLI_STRING, "+z|-z|+x|-x|+y|-y", "+z", "the part's axis that points up in the printer"},
    {"--orientation", 0, CLI_STRING, "X,Y,Z", NULL, "the build direction as a vector in the part's frame; not with --up"},
    {"--build-volume", 0, CLI_STRING, "XxYxZ", NULL, "the printer's build volume, e.g. 250x210x220mm (mm, cm or in)"},
    {"--thickness-map", 0, CLI_STRING, "MAP.ply", NULL,
     "write the surface coloured by wall thickness (PLY, viridis) and MAP.png, its legend"},
    {"--voxel", 0, CLI_LENGTH, "LEN", NULL, "voxel size (default: 400 along the part, kept between the minimum wall / 4 and / 2); not with --resolution"},
    {"--resolution", 0, CLI_INT, "N", NULL, "voxel = longest bounding-box side / N (N >= 8); not with --voxel"},
    {"--fail-on", 0, CLI_STRING, "warn|fail", "fail", "the verdict that makes the exit code 5"},
    {"--report", 0, CLI_STRING, "FILE.json", NULL, "also write every figure as JSON (keys: docs/check.md)"},
};

/* The order and names the summary prints the checks in. */
static const char* const checks[][2] = {
    {"mesh", "mesh"},
    {"units", "units"},
    {"wall_thickness", "wall thickness"},
    {"small_features", "small features"},
    {"holes", "holes, channels"},
    {"trapped_volumes", "trapped volumes"},
    {"cups", "cups"},
    {"overhangs", "overhangs"},
    {"build_volume", "build volume"},
};

/* "+z" and the like into a unit vector; returns 0 unless it is one. */
static int parse_axis(const char* text, double up[3]) {
    if (strlen(text) != 2 || (text[0] != '+' && text[0] != '-') || text[1] < 'x' || text[1] > 'z') return 0;
    up[0] = up[1] = up[2] = 0.0;
    up[text[1] - 'x'] = text[0] == '+' ? 1.0 : -1.0;
    return 1;
}

/* "X,Y,Z": three finite numbers, not all zero; returns 0 otherwise. */
static int parse_vector(const char* text, double v[3]) {
    const char* at = text;
    for (int k = 0; k < 3; ++k) {
        char* end = NULL;
        v[k] = strtod(at, &end);
        if (end == at || !isfinite(v[k])) return 0;
        if (k < 2 && *end != ',') return 0;
        at = end + (k < 2);
        if (k == 2 && *end != '\0') return 0;
    }
    return v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0;
}

/* "250x210x220mm" (mm, cm or in; bare numbers are mm) into mm; 0 unless all three are > 0. */
static int parse_build_volume(const char* text, double size[3]) {
    const char* at = text;
    for (int k = 0; k < 3; ++k) {
        char* end = NULL;
        size[k] = strtod(at, &end);
        if (end == at || !(size[k] > 0.0) || !isfinite(size[k])) return 0;
        if (k < 2 && *end != 'x') return 0;
        at = end + (k < 2);
    }
    double unit = 1.0;
    if (strcmp(at, "cm") == 0) unit = 10.0;
    else if (strcmp(at, "in") == 0) unit = 25.4;
    else if (strcmp(at, "mm") != 0 && *at != '\0') return 0;
    for (int k = 0; k < 3; ++k) size[k] *= unit;
    return 1;
}

/* Prints one check's line, and where its first region or item is. */
static void print_check(cli_run* run, const fabvdb_report* report, const char* key, const char* label) {
    char pointer[96];
    const char* status = NULL;
    const char* message = "";
    snprintf(pointer, sizeof pointer, "/checks/%s/status", key);
    if (fabvdb_report_string(run->ctx, report, pointer, &status) != FABVDB_OK) return;
    snprintf(pointer, sizeof pointer, "/checks/%s/message", key);
    fabvdb_report_string(run->ctx, report, pointer, &message);
    printf("  %-16s %-4s  %s\n", label, status, message);
    if (strcmp(status, "pass") == 0) return;
    static const char* const lists[] = {"regions", "pins", "fins", "small_pieces", "cavities", "cups"};
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; ++i) {
        double c[3];
        int found = 1;
        for (int k = 0; k < 3 && found; ++k) {
            snprintf(pointer, sizeof pointer, "/checks/%s/%s/0/center/%d", key, lists[i], k);
            found = fabvdb_report_number(run->ctx, report, pointer, &c[k]) == FABVDB_OK;
        }
        if (found) {
            printf("  %-16s       first of the %s at (%.2f, %.2f, %.2f)\n", "", lists[i], c[0], c[1], c[2]);
            return;
        }
    }
}

/* Prints on stderr, even with --quiet, why the verdict is what it is: the
 * first check with that status, "fabvdb check: fail: wall thickness: ..."
 * (the line `fabvdb batch` records as the task's message). */
static void print_reason(cli_run* run, const fabvdb_report* report, const char* verdict) {
    for (size_t i = 0; i < sizeof checks / sizeof checks[0]; ++i) {
        char pointer[96];
        const char* status = NULL;
        const char* message = "";
        snprintf(pointer, sizeof pointer, "/checks/%s/status", checks[i][0]);
        if (fabvdb_report_string(run->ctx, report, pointer, &status) != FABVDB_OK || strcmp(status, verdict) != 0)
            continue;
        snprintf(pointer, sizeof pointer, "/checks/%s/message", checks[i][0]);
        fabvdb_report_string(run->ctx, report, pointer, &message);
        fprintf(stderr, "fabvdb check: %s: %s: %s\n", verdict, checks[i][1], message);
        return;
    }
}

static int run_check(cli_run* run) {
    const char* fail_on = cli_get(run, "--fail-on")->text;
    if (strcmp(fail_on, "warn") != 0 && strcmp(fail_on, "fail") != 0)
        return cli_usage_error(run, "--fail-on takes warn or fail, not '%s'", fail_on);
    fabvdb_check_options opts;
    fabvdb_check_options_init(&opts);
    opts.process = cli_get(run, "--process")->text;
    const cli_value* orientation = cli_get(run, "--orientation");
    if (orientation->given) {
        if (!parse_vector(orientation->text, opts.up))
            return cli_usage_error(run, "--orientation takes a non-zero vector X,Y,Z, not '%s'", orientation->text);
    } else if (!parse_axis(cli_get(run, "--up")->text, opts.up)) {
        return cli_usage_error(run, "--up takes +x, -x, +y, -y, +z or -z, not '%s'", cli_get(run, "--up")->text);
    }
    const cli_value* build = cli_get(run, "--build-volume");
    if (build->given && !parse_build_volume(build->text, opts.build_volume))
        return cli_usage_error(run, "--build-volume takes XxYxZ sizes > 0 such as 250x210x220mm, not '%s'", build->text);
    const cli_value* map = cli_get(run, "--thickness-map");
    if (map->given) opts.thickness_map_path = map->text;

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    code = cli_voxel_size(run, mesh, &opts.voxel_size);
    if (code != CLI_EXIT_OK) {
        fabvdb_mesh_free(mesh);
        return code;
    }
    fabvdb_report* report = NULL;
    fabvdb_status status = fabvdb_mesh_check(run->ctx, mesh, &opts, &report);
    fabvdb_mesh_free(mesh);
    if (status != FABVDB_OK) return cli_fail(run, status);

    const char* verdict = "fail";
    const char* process = "";
    double voxel = 0.0;
    fabvdb_report_string(run->ctx, report, "/verdict", &verdict);
    fabvdb_report_string(run->ctx, report, "/process/name", &process);
    fabvdb_report_number(run->ctx, report, "/voxel_size", &voxel);
    printf("%s: %s for %s (voxel %.3g mm)\n", run->positional[0], verdict, process, voxel);
    for (size_t i = 0; i < sizeof checks / sizeof checks[0]; ++i) print_check(run, report, checks[i][0], checks[i][1]);
    if (map->given) cli_note(run, "wrote %s and its legend beside it", map->text);
    cli_print_warnings(run, report);
    code = cli_write_report(run, report);
    const int gated = strcmp(verdict, "fail") == 0 || (strcmp(fail_on, "warn") == 0 && strcmp(verdict, "warn") == 0);
    if (code == CLI_EXIT_OK && gated) {
        print_reason(run, report, verdict);
        code = CLI_EXIT_VERDICT;
    }
    fabvdb_report_free(report);
    return code;
}

const cli_command cmd_check = {
    "check",
    "will the part print in a process as it is? walls, features, holes, cavities, units, overhangs, fit",
    "INPUT [--process sla|powder|fdm|FILE.json] [--up +z | --orientation X,Y,Z] [--build-volume 250x210x220mm]\n"
    "       [--thickness-map MAP.ply] [--report R.json] [--fail-on warn|fail]",
    "Judges INPUT against a process' thresholds (docs/check.md gives each value and its source) and prints\n"
    "one line per check with its status (pass, warn, fail), its figures in mm and where to look: the mesh's\n"
    "defects and the path `repair` would take; a size that suggests metres, inches or centimetres, with the\n"
    "--scale that fixes it; walls under the minimum, by local thickness from the solid's signed distance\n"
    "(twice the radius of the largest ball inside, reached by climbing to the medial surface: edges do not\n"
    "read thin); pins under the minimum diameter, fins (thin walls held along one edge only) and pieces under\n"
    "the minimum feature; holes, channels and gaps under the minimum width; sealed cavities that trap resin\n"
    "or powder; for resin cups, pockets the layers seal against the vat film (suction, trapped resin);\n"
    "overhang area for the build direction (--up or --orientation); and, with --build-volume, whether the\n"
    "part fits as placed or turned.\n"
    "A dirty mesh is judged as the solid its winding numbers enclose (as `repair` makes it). A figure under\n"
    "its minimum fails, one within the profile's margin above it warns; the verdict is the worst check.\n"
    "Exit 0 when the verdict is under --fail-on, 5 when it reaches it; 1 for a bad option or unknown process,\n"
    "2 for a missing or malformed input or profile.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_check};
