/* cmd_studio.c — `fabvdb studio MODEL`: steer the mold decomposition of MODEL
 * in a web page served on 127.0.0.1 (tools/studio_server.c): prints the
 * page's URL (with this run's token), opens it where a desktop is available,
 * and serves until Ctrl-C or SIGTERM. */
#define _DEFAULT_SOURCE /* POSIX: sigaction, nanosleep */
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "cli/commands.h"
#include "common/spawn.h"
#include "studio_server.h"

static const cli_option options[] = {
    {"--decomposition", 0, CLI_STRING, "D.json", NULL,
     "start from this decomposition.json (of MODEL) instead of the automatic decomposition"},
    {"--output", 'o', CLI_STRING, "DIR", NULL,
     "where Save and Make molds write (DIR/decomposition/, DIR/edits.json, DIR/molds/); default MODEL-studio "
     "in the current folder"},
    {"--port", 0, CLI_INT, "N", "0", "port on 127.0.0.1; 0 takes a free one"},
    {"--no-browser", 0, CLI_FLAG, NULL, NULL, "do not open the page in a browser (it is never opened without a desktop)"},
    {"--shell", 0, CLI_LENGTH, "LEN", NULL,
     "shell thickness omega (3mm, or 2% of the diagonal); default 0.03 x the longest side"},
    {"--solid", 0, CLI_FLAG, NULL, NULL, "cast solid parts instead of shells"},
    {"--gamma", 0, CLI_NUMBER, "G", "0.05", "threshold on the total moldability energy (unit-cube area)"},
    {"--parts", 0, CLI_STRING, "auto|N", "auto", "part count of the automatic decomposition"},
    {"--draft", 0, CLI_ANGLE, "ANGLE", "1deg", "draft angle"},
    {"--low-res", 0, CLI_INT, "N", "10000", "triangles of the low-resolution surface the decomposition runs on"},
};

static volatile sig_atomic_t stop_requested = 0;

static void on_stop(int signal_number) {
    (void)signal_number;
    stop_requested = 1;
}

/* Opens url with the desktop's browser, only where there is a desktop and
 * not under CI; does not wait for it. */
static void open_browser(const char* url) {
    const char* display = getenv("DISPLAY");
    const char* wayland = getenv("WAYLAND_DISPLAY");
    const char* ci = getenv("CI");
    if ((!display || !*display) && (!wayland || !*wayland)) return;
    if (ci && *ci) return;
    char* argv[] = {"xdg-open", (char*)url, NULL};
    spawn_start("xdg-open", argv, NULL, NULL);
}

/* Whether Save can write into `output`: an existing folder, or a new one in
 * an existing folder (checked before the server starts, not at the first Save). */
static int output_usable(const char* output) {
    struct stat info;
    if (stat(output, &info) == 0) return S_ISDIR(info.st_mode);
    char parent[4096];
    snprintf(parent, sizeof parent, "%s", output);
    char* slash = strrchr(parent, '/');
    if (!slash) return 1;
    if (slash == parent) slash[1] = '\0';
    else *slash = '\0';
    return stat(parent, &info) == 0 && S_ISDIR(info.st_mode);
}

/* Keeps freed memory in the process: every edit builds and frees megabytes
 * of graph-cut networks and overlap lists, and glibc's defaults hand them
 * back to the system, so each edit pays a page fault per 4 KiB touched
 * again (a smoothing stroke on airplane: 250-420 ms with the defaults,
 * 48-84 ms with allocations under 32 MiB kept in the heap). */
static void keep_freed_memory(void) {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif
}

static int run_studio(cli_run* run) {
    keep_freed_memory();
    fabvdb_decompose_options decompose;
    fabvdb_decompose_options_init(&decompose);
    decompose.gamma = cli_get(run, "--gamma")->number;
    decompose.draft_degrees = cli_get(run, "--draft")->number;
    decompose.low_res_triangles = (int)cli_get(run, "--low-res")->number;
    if (cli_get(run, "--solid")->given) decompose.flags |= FABVDB_DECOMPOSE_SOLID;
    const int parts_code = cli_part_count(run, "--parts", &decompose.parts);
    if (parts_code != CLI_EXIT_OK) return parts_code;
    if (!(decompose.gamma > 0)) return cli_usage_error(run, "--gamma must be positive");
    if (!(decompose.draft_degrees >= 0 && decompose.draft_degrees <= 30))
        return cli_usage_error(run, "--draft must be between 0 and 30 degrees");
    if (decompose.low_res_triangles < 100) return cli_usage_error(run, "--low-res must be at least 100");
    const int port = (int)cli_get(run, "--port")->number;
    if (port < 0 || port > 65535) return cli_usage_error(run, "--port must be from 0 to 65535");

    char output[4096];
    const cli_value* output_option = cli_get(run, "--output");
    if (output_option->set) {
        snprintf(output, sizeof output, "%s", output_option->text);
    } else {
        const char* model = run->positional[0];
        const char* slash = strrchr(model, '/');
        const char* name = slash ? slash + 1 : model;
        const char* dot = strrchr(name, '.');
        const int length = dot && dot != name ? (int)(dot - name) : (int)strlen(name);
        snprintf(output, sizeof output, "%.*s-studio", length, name);
    }

    if (!output_usable(output)) {
        fprintf(stderr, "fabvdb studio: cannot save into %s: its folder does not exist\n", output);
        return CLI_EXIT_BAD_INPUT;
    }

    fabvdb_mesh* mesh = NULL;
    int code = cli_read_input(run, run->positional[0], &mesh);
    if (code != CLI_EXIT_OK) return code;
    if (cli_get(run, "--shell")->set) {
        decompose.shell_thickness = cli_length_mm(run, "--shell", cli_mesh_diagonal(mesh));
        if (!(decompose.shell_thickness > 0.0)) {
            fabvdb_mesh_free(mesh);
            return cli_usage_error(run, "--shell must be positive");
        }
    }
    /* The server reports progress to the page; Ctrl-C and SIGTERM stop it. */
    fabvdb_ctx_set_progress(run->ctx, NULL, NULL);
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_stop;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);

    const cli_value* decomposition = cli_get(run, "--decomposition");
    studio_config config = {run->ctx, mesh, &decompose, decomposition->set ? decomposition->text : NULL, output, port,
                            run->quiet};
    studio_server* server = studio_start(&config);
    if (!server) {
        fabvdb_mesh_free(mesh);
        return CLI_EXIT_INTERNAL;
    }
    printf("fabvdb studio: open %s\n", studio_url(server));
    printf("fabvdb studio: saves go to %s/ ; stop with Ctrl-C\n", output);
    fflush(stdout);
    if (!cli_get(run, "--no-browser")->given) open_browser(studio_url(server));
    const struct timespec pause = {0, 100 * 1000 * 1000};
    while (!stop_requested) nanosleep(&pause, NULL);
    studio_stop(server);
    fabvdb_mesh_free(mesh);
    cli_note(run, "studio stopped");
    return CLI_EXIT_OK;
}

const cli_command cmd_studio = {
    "studio",
    "steer the mold decomposition of a model interactively in a local web page",
    "MODEL [--decomposition D.json] [-o DIR] [--port N] [--no-browser] [--gamma G] [--parts auto|N] [--draft ANGLE]",
    "Decomposes MODEL as 'fabvdb decompose' does (or starts from --decomposition) and serves a page on\n"
    "127.0.0.1 to steer it: the parts in colour with their parting lines, the M+/M- sides, the deformation\n"
    "heat map, a draft/undercut map for any part's direction, each part's direction and energy, the total\n"
    "against gamma with a warning; a no-cut brush and a smoothing brush (radius on the mouse wheel), cuts\n"
    "through clicked points, merges of two clicked parts, undo/redo (Ctrl+Z, Ctrl+Shift+Z), re-runs with\n"
    "another gamma, part count or draft; Save writes DIR/decomposition/ (what 'fabvdb mold --decomposition'\n"
    "takes) and DIR/edits.json (what 'fabvdb decompose --edits' replays); Make molds runs 'fabvdb mold'\n"
    "into DIR/molds/ with a progress bar and Cancel, and shows the parts and mold pieces.\n"
    "The URL it prints carries a random token; requests without it, or from another origin, are refused.\n"
    "The page is built into fabvdb: no network is needed. It runs until Ctrl-C.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_studio};
