/* cmd_batch.c — `fabvdb batch JOB.job`: runs the command lines of a job file in
 * order (tools/job.h has the format), as `--save-job` wrote them or as a farm
 * script lists its work. Stops at the first failing line with its exit code,
 * unless --keep-going; then the exit code is the first failure's. */
#define _DEFAULT_SOURCE /* POSIX: sigaction, mkdtemp, chdir, getcwd */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"
#include "job.h"

static const cli_option options[] = {
    {"--keep-going", 'k', CLI_FLAG, NULL, NULL, "run the remaining lines after a failure"},
    {"--dry-run", 'n', CLI_FLAG, NULL, NULL, "check the job file and print its commands without running them"},
};

static int run_batch(cli_run* run) {
    const char* path = run->positional[0];
    FILE* in = fopen(path, "r");
    if (!in) {
        fprintf(stderr, "fabvdb batch: input/output error: %s: cannot open the job file\n", path);
        return CLI_EXIT_BAD_INPUT;
    }
    const int keep_going = cli_get(run, "--keep-going")->given;
    const int dry_run = cli_get(run, "--dry-run")->given;
    char text[65536];
    int line_number = 0, header_seen = 0, first_failure = CLI_EXIT_OK, commands_run = 0;
    while (fgets(text, sizeof text, in)) {
        ++line_number;
        if (!strchr(text, '\n') && !feof(in)) {
            fprintf(stderr, "fabvdb batch: bad input: %s:%d: line too long\n", path, line_number);
            fclose(in);
            return CLI_EXIT_BAD_INPUT;
        }
        job_line line;
        const char* error = NULL;
        if (job_tokenize(text, &line, &error) != 0) {
            fprintf(stderr, "fabvdb batch: bad input: %s:%d: %s\n", path, line_number, error);
            fclose(in);
            return CLI_EXIT_BAD_INPUT;
        }
        text[strcspn(text, "\r\n")] = 0;
        if (line.count == 0) continue;
        if (!header_seen) {
            if (line.count != 2 || strcmp(line.tokens[0], "fabvdb-job") != 0 || atoi(line.tokens[1]) < 1 ||
                atoi(line.tokens[1]) > JOB_FORMAT_VERSION) {
                fprintf(stderr,
                        "fabvdb batch: bad input: %s:%d: not a fabvdb job file of a version this fabvdb reads "
                        "(the first line must be 'fabvdb-job %d')\n",
                        path, line_number, JOB_FORMAT_VERSION);
                job_line_free(&line);
                fclose(in);
                return CLI_EXIT_BAD_INPUT;
            }
            header_seen = 1;
            job_line_free(&line);
            continue;
        }
        if (strcmp(line.tokens[0], "directory") == 0) {
            if (line.count != 2 || (!dry_run && chdir(line.tokens[1]) != 0)) {
                fprintf(stderr, "fabvdb batch: bad input: %s:%d: cannot enter the directory '%s'\n", path,
                        line_number, line.count > 1 ? line.tokens[1] : "");
                job_line_free(&line);
                fclose(in);
                return CLI_EXIT_BAD_INPUT;
            }
            job_line_free(&line);
            continue;
        }
        const cli_command* command = command_named(line.tokens[0]);
        if (!command || command == &cmd_batch) {
            fprintf(stderr, "fabvdb batch: bad input: %s:%d: no command '%s'\n", path, line_number, line.tokens[0]);
            job_line_free(&line);
            fclose(in);
            return CLI_EXIT_BAD_INPUT;
        }
        cli_note(run, "[%s:%d] fabvdb %s", path, line_number, text);
        int code = CLI_EXIT_OK;
        if (dry_run)
            printf("fabvdb %s\n", text);
        else
            code = cli_main(command, line.count, line.tokens);
        ++commands_run;
        job_line_free(&line);
        if (code != CLI_EXIT_OK) {
            if (first_failure == CLI_EXIT_OK) first_failure = code;
            if (!keep_going || code == CLI_EXIT_CANCELLED) break;
        }
    }
    fclose(in);
    if (!header_seen) {
        fprintf(stderr, "fabvdb batch: bad input: %s: empty job file\n", path);
        return CLI_EXIT_BAD_INPUT;
    }
    cli_note(run, "batch: %d command(s) %s", commands_run, dry_run ? "checked" : "run");
    return first_failure;
}

const cli_command cmd_batch = {
    "batch",
    "run the command lines of a job file (replays --save-job)",
    "JOB.job [--keep-going] [--dry-run]",
    "A job file is text: the first line is 'fabvdb-job 1'; then one fabvdb command line per line\n"
    "(without the word fabvdb), words bare or in double quotes, '#' comments, and optionally\n"
    "'directory PATH' to resolve relative paths from PATH. Any command run with --save-job FILE writes\n"
    "such a file, so the run can be replayed exactly. Lines run in order; the first failure stops the\n"
    "batch (unless --keep-going) and gives its exit code.",
    options, sizeof(options) / sizeof(options[0]), 1, 1, run_batch};
