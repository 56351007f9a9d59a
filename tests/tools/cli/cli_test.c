/* cli_test.c — tools/cli/cli.c beyond what the command-line tests see:
 * values with units, options found by name, the one rule for options that
 * set one thing two ways (--voxel or --resolution, --scale or --fit: never
 * both, in every command that has both), one meaning for an option name
 * across commands, the one rule of --voxel and --resolution, warnings
 * printed from a report
 * through the report API, and --save-job's file read back. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include <math.h>

#include "capi/check.h"
#include "cli/commands.h"
#include "common/job.h"
#include "tools/temp_folder.h"

static char folder[4096];

/* Runs `command` with the words of argv and returns its exit code, its
 * stderr in err. */
static int run(const cli_command* command, int argc, char** argv, char* err, size_t size) {
    char path[4096];
    const int saved = temp_stderr_begin(temp_path(path, folder, "stderr"));
    const int code = cli_main(command, argc, argv);
    temp_stderr_end(saved);
    temp_read(path, err, size);
    return code;
}

static void check_values(void) {
    double number = 0;
    int relative = 0;
    CHECK(cli_parse_value(CLI_LENGTH, "3", &number, &relative) == 0 && number == 3 && !relative);
    CHECK(cli_parse_value(CLI_LENGTH, "0.3cm", &number, &relative) == 0 && fabs(number - 3) < 1e-12);
    CHECK(cli_parse_value(CLI_LENGTH, "1in", &number, &relative) == 0 && number == 25.4);
    CHECK(cli_parse_value(CLI_LENGTH, "2%", &number, &relative) == 0 && number == 0.02 && relative);
    CHECK(cli_parse_value(CLI_LENGTH, "3parsecs", &number, &relative) != 0);
    CHECK(cli_parse_value(CLI_ANGLE, "35deg", &number, &relative) == 0 && number == 35);
    CHECK(cli_parse_value(CLI_ANGLE, "1rad", &number, &relative) == 0 && fabs(number - 180 / M_PI) < 1e-12);
    CHECK(cli_parse_value(CLI_SIZE, "2G", &number, &relative) == 0 && number == 2.0 * 1024 * 1024 * 1024);
    CHECK(cli_parse_value(CLI_INT, "2.5", &number, &relative) != 0);
    CHECK(cli_parse_value(CLI_NUMBER, "nan", &number, &relative) != 0);

    CHECK(cli_option_named(&cmd_hollow, "--wall=3mm", 6, 0) != NULL);
    CHECK(cli_option_named(&cmd_hollow, NULL, 0, 'o') == cli_option_named(&cmd_hollow, "--output", 8, 0));
    CHECK(cli_option_named(&cmd_hollow, "--threads", 9, 0) != NULL); /* a common option */
    CHECK(cli_option_named(&cmd_hollow, "--wal", 5, 0) == NULL);
}

static void check_alternatives(void) {
    char err[4096];
    char* repair[] = {"repair", "missing.stl", "-o", "out.stl", "--voxel", "1mm", "--resolution", "100"};
    CHECK(run(&cmd_repair, 8, repair, err, sizeof err) == CLI_EXIT_USAGE);
    CHECK(strstr(err, "fabvdb repair: give --voxel or --resolution, not both") != NULL);
    char* hollow[] = {"hollow", "missing.stl", "-o", "out.stl", "--resolution=50", "--voxel=1mm"};
    CHECK(run(&cmd_hollow, 6, hollow, err, sizeof err) == CLI_EXIT_USAGE);
    CHECK(strstr(err, "fabvdb hollow: give --voxel or --resolution, not both") != NULL);
    char* info[] = {"info", "missing.stl", "--scale", "2", "--fit", "10mm"};
    CHECK(run(&cmd_info, 6, info, err, sizeof err) == CLI_EXIT_USAGE);
    CHECK(strstr(err, "fabvdb info: give --scale or --fit, not both") != NULL);
    /* One of them alone passes the rule (and the run then fails on the input). */
    char* one[] = {"repair", "missing.stl", "-o", "out.stl", "--voxel", "1mm"};
    CHECK(run(&cmd_repair, 6, one, err, sizeof err) == CLI_EXIT_BAD_INPUT);
    CHECK(strstr(err, "not both") == NULL);
}

/* Options that share a name across commands share their kind of value: the
 * same type, short name and value name. Only -o/--output names a file in
 * some commands and a folder in others (OUT, OUTDIR, DIR): the command's
 * result either way. */
static void check_shared_names(void) {
    for (size_t a = 0; a < fabvdb_command_count; ++a)
        for (size_t b = a + 1; b < fabvdb_command_count; ++b)
            for (size_t i = 0; i < fabvdb_commands[a]->option_count; ++i) {
                const cli_option* one = &fabvdb_commands[a]->options[i];
                const cli_option* other =
                    cli_option_named(fabvdb_commands[b], one->name, strlen(one->name), 0);
                if (!other) continue;
                const int same_value = (!one->value_name && !other->value_name) ||
                                       (one->value_name && other->value_name &&
                                        strcmp(one->value_name, other->value_name) == 0) ||
                                       strcmp(one->name, "--output") == 0;
                if (one->type != other->type || one->short_name != other->short_name || !same_value) {
                    fprintf(stderr, "%s of %s and of %s differ\n", one->name, fabvdb_commands[a]->name,
                            fabvdb_commands[b]->name);
                    CHECK(0);
                }
            }
}

/* --voxel and --resolution against a box 100 x 50 x 20 mm: the voxel from
 * either, a % of the diagonal, the bounds, and neither (0: the default). */
static void check_voxel_size(void) {
    const double vertices[] = {0, 0, 0, 100, 0, 0, 0, 50, 0, 0, 0, 20};
    const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    fabvdb_ctx* ctx = NULL;
    CHECK(fabvdb_ctx_new(&ctx) == FABVDB_OK);
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_new(ctx, vertices, 4, triangles, 4, &mesh) == FABVDB_OK);
    const double diagonal = sqrt(100.0 * 100.0 + 50.0 * 50.0 + 20.0 * 20.0);
    const struct {
        const cli_command* command;
        const char* option;
        const char* value;
        int code;
        double voxel;
    } cases[] = {
        {&cmd_hollow, "--resolution", "50", CLI_EXIT_OK, 2.0},   {&cmd_repair, "--resolution", "200", CLI_EXIT_OK, 0.5},
        {&cmd_check, "--resolution", "1000", CLI_EXIT_OK, 0.1},  {&cmd_check, "--resolution", "7", CLI_EXIT_USAGE, 0},
        {&cmd_repair, "--voxel", "0.3mm", CLI_EXIT_OK, 0.3},     {&cmd_powder_sim, "--voxel", "1%", CLI_EXIT_OK, 0},
        {&cmd_drain, "--voxel", "0mm", CLI_EXIT_USAGE, 0},       {&cmd_mold, "--voxel", NULL, CLI_EXIT_OK, 0},
        {&cmd_repair, "--resolution", NULL, CLI_EXIT_OK, 0},
    };
    char path[4096];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        cli_run run;
        memset(&run, 0, sizeof run);
        run.command = cases[i].command;
        run.ctx = ctx;
        cli_value* value = (cli_value*)cli_get(&run, cases[i].option);
        if (cases[i].value) {
            value->set = value->given = 1;
            value->text = cases[i].value;
            CHECK(cli_parse_value(cli_option_named(run.command, cases[i].option, strlen(cases[i].option), 0)->type,
                                  cases[i].value, &value->number, &value->relative) == 0);
        }
        double voxel = -1;
        const int saved = temp_stderr_begin(temp_path(path, folder, "voxel"));
        const int code = cli_voxel_size(&run, mesh, &voxel);
        temp_stderr_end(saved);
        const double wanted = strcmp(cases[i].value ? cases[i].value : "", "1%") == 0 ? 0.01 * diagonal
                                                                                     : cases[i].voxel;
        CHECK(code == cases[i].code);
        if (code == CLI_EXIT_OK) CHECK(fabs(voxel - wanted) < 1e-12);
    }
    fabvdb_mesh_free(mesh);
    fabvdb_ctx_free(ctx);
}

static void check_warnings(void) {
    /* A tetrahedron 0.045 mm across: the inspection warns that it is tiny. */
    const double s = 0.045;
    const double vertices[] = {0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s};
    const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    cli_run run_info;
    memset(&run_info, 0, sizeof run_info);
    run_info.command = &cmd_info;
    CHECK(fabvdb_ctx_new(&run_info.ctx) == FABVDB_OK);
    fabvdb_mesh* mesh = NULL;
    CHECK(fabvdb_mesh_new(run_info.ctx, vertices, 4, triangles, 4, &mesh) == FABVDB_OK);
    fabvdb_report* report = NULL;
    CHECK(fabvdb_mesh_inspect(run_info.ctx, mesh, &report) == FABVDB_OK);
    size_t count = 0;
    CHECK(fabvdb_report_count(run_info.ctx, report, "/warnings", &count) == FABVDB_OK && count >= 1);
    const char* first = NULL;
    CHECK(fabvdb_report_string(run_info.ctx, report, "/warnings/0", &first) == FABVDB_OK);
    char path[4096], err[8192], wanted[4096];
    int saved = temp_stderr_begin(temp_path(path, folder, "warnings"));
    cli_print_warnings(&run_info, report);
    cli_print_warnings(&run_info, NULL); /* no report: nothing */
    temp_stderr_end(saved);
    temp_read(path, err, sizeof err);
    snprintf(wanted, sizeof wanted, "fabvdb info: warning: %s\n", first ? first : "?");
    CHECK(strncmp(err, wanted, strlen(wanted)) == 0);
    CHECK(strstr(err, "only 0.045 mm across") != NULL);
    int lines = 0;
    for (const char* p = err; *p; ++p) lines += *p == '\n';
    CHECK(lines == (int)count);
    fabvdb_report_free(report);
    /* A report without warnings prints nothing. */
    report = NULL;
    fabvdb_mesh* scaled = NULL;
    CHECK(fabvdb_mesh_scale(run_info.ctx, mesh, 1000.0, &scaled) == FABVDB_OK);
    CHECK(fabvdb_mesh_inspect(run_info.ctx, scaled, &report) == FABVDB_OK);
    saved = temp_stderr_begin(path);
    cli_print_warnings(&run_info, report);
    temp_stderr_end(saved);
    temp_read(path, err, sizeof err);
    CHECK(err[0] == 0);
    fabvdb_report_free(report);
    fabvdb_mesh_free(scaled);
    fabvdb_mesh_free(mesh);
    fabvdb_ctx_free(run_info.ctx);
}

static void check_save_job(void) {
    char path[4096], text[8192];
    temp_path(path, folder, "run.job");
    char* argv[] = {"hollow", "in put.stl", "--save-job", path, "-o", "out.stl", "--save-job=other.job", "--wall", "2mm"};
    CHECK(cli_write_job(path, "hollow", 9, argv) == 0);
    CHECK(temp_count(folder, ".partial-") == 0);
    CHECK(temp_read(path, text, sizeof text) == 0);
    CHECK(strncmp(text, "fabvdb-job 1\n# written by fabvdb ", 33) == 0);
    const char* command = strstr(text, "\nhollow ");
    job_line line;
    const char* error = NULL;
    CHECK(command && job_tokenize(command + 1, &line, &error) == 0);
    const char* const wanted[] = {"hollow", "in put.stl", "-o", "out.stl", "--wall", "2mm"};
    CHECK(line.count == 6);
    for (int i = 0; i < line.count && i < 6; ++i) CHECK(strcmp(line.tokens[i], wanted[i]) == 0);
    job_line_free(&line);
    CHECK(strstr(text, "\ndirectory \"") != NULL);
    temp_path(path, folder, "missing/run.job");
    CHECK(cli_write_job(path, "hollow", 1, argv) != 0);
}

int main(void) {
    CHECK(temp_folder_make(folder) == 0);
    check_values();
    check_alternatives();
    check_shared_names();
    check_voxel_size();
    check_warnings();
    check_save_job();
    temp_folder_remove(folder);
    return check_summary();
}
