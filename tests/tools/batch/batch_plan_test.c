/* batch_plan_test.c — tools/batch/batch_plan.c: a job file's lines become
 * tasks (one task without 'task' lines, one per 'task' line with them), in
 * the directory its 'directory' lines name; a recipe applied to --inputs
 * with its placeholders replaced; each defect refused with its line, its
 * status words (tools/common/status_text.h) and exit code; the plan written
 * and read back the same. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "batch/batch_plan.h"
#include "capi/check.h"
#include "cli/cli.h"
#include "tools/temp_folder.h"

static char folder[4096];

/* Reads the job text; returns the exit code, the message in error. */
static int read_job(const char* text, const char* inputs, const char* out, batch_plan* plan, char* error,
                    size_t size) {
    char path[4096];
    temp_write(temp_path(path, folder, "job.job"), text);
    return batch_plan_read(path, inputs, out, plan, error, size);
}

static void check_defect(const char* text, int wanted_code, const char* wanted) {
    batch_plan plan;
    char error[4096];
    const int code = read_job(text, NULL, NULL, &plan, error, sizeof error);
    CHECK(code == wanted_code);
    CHECK(strstr(error, wanted) != NULL);
    if (code != wanted_code || !strstr(error, wanted)) fprintf(stderr, "  %d: %s\n", code, error);
}

int main(void) {
    CHECK(temp_folder_make(folder) == 0);
    char sub[4096], error[4096], path[4096];
    temp_path(sub, folder, "sub");
    CHECK(mkdir(sub, 0755) == 0);

    /* Without 'task' lines: one task named after the job file. */
    batch_plan plan;
    char text[8192];
    snprintf(text, sizeof text, "fabvdb-job 1\n# two lines\ndirectory \"%s\"\nrepair in.stl -o a.stl\nhollow {prev} -o b.stl\n",
             sub);
    CHECK(read_job(text, NULL, NULL, &plan, error, sizeof error) == 0);
    CHECK(plan.task_count == 1 && strcmp(plan.tasks[0].name, "job") == 0 && plan.tasks[0].line_count == 2);
    if (plan.task_count == 1 && plan.tasks[0].line_count == 2) {
        const batch_plan_line* second = &plan.tasks[0].lines[1];
        CHECK(second->source_line == 5);
        CHECK(strcmp(second->directory, sub) == 0);
        temp_path(path, sub, "a.stl");
        CHECK(strcmp(second->line.tokens[1], path) == 0); /* {prev}: the line above's output, absolute */
    }
    batch_plan_free(&plan);

    /* 'task' lines: one task each; the plan written reads back the same. */
    CHECK(read_job("fabvdb-job 1\ntask first\ninfo a.stl\ntask second\ninfo \"b c.stl\"\ninfo {{literal}}\n", NULL, NULL,
                   &plan, error, sizeof error) == 0);
    CHECK(plan.task_count == 2 && batch_plan_find(&plan, "second") == 1 && batch_plan_find(&plan, "third") == -1);
    temp_path(path, folder, "plan.job");
    CHECK(batch_plan_write(&plan, "job.job", path) == 0);
    batch_plan again;
    CHECK(batch_plan_read(path, NULL, NULL, &again, error, sizeof error) == 0);
    CHECK(again.task_count == 2);
    for (int k = 0; k < plan.task_count && k < again.task_count; ++k) {
        CHECK(strcmp(plan.tasks[k].name, again.tasks[k].name) == 0);
        CHECK(plan.tasks[k].line_count == again.tasks[k].line_count);
        for (int i = 0; i < plan.tasks[k].line_count && i < again.tasks[k].line_count; ++i) {
            const job_line* a = &plan.tasks[k].lines[i].line, *b = &again.tasks[k].lines[i].line;
            CHECK(a->count == b->count && plan.tasks[k].lines[i].source_line == again.tasks[k].lines[i].source_line);
            for (int t = 0; t < a->count && t < b->count; ++t) CHECK(strcmp(a->tokens[t], b->tokens[t]) == 0);
        }
    }
    CHECK(plan.task_count == 2 && plan.tasks[1].line_count == 2 &&
          strcmp(plan.tasks[1].lines[1].line.tokens[1], "{literal}") == 0);
    batch_plan_free(&again);
    batch_plan_free(&plan);

    /* A recipe over a folder of inputs: one task per mesh, named by its stem. */
    char inputs[4096], out[4096];
    temp_path(inputs, folder, "inputs");
    CHECK(mkdir(inputs, 0755) == 0);
    temp_write(temp_path(path, inputs, "b part.stl"), "");
    temp_write(temp_path(path, inputs, "a.obj"), "");
    temp_write(temp_path(path, inputs, "notes.txt"), "");
    temp_path(out, folder, "out");
    CHECK(read_job("fabvdb-job 1\nrepair {input} -o {out}/{stem}.stl\n", inputs, out, &plan, error, sizeof error) == 0);
    CHECK(plan.recipe && plan.task_count == 2);
    if (plan.task_count == 2) {
        CHECK(strcmp(plan.tasks[0].name, "a") == 0 && strcmp(plan.tasks[1].name, "b_part") == 0);
        temp_path(path, out, "b_part/b part.stl");
        CHECK(strcmp(plan.tasks[1].lines[0].line.tokens[3], path) == 0);
        CHECK(strstr(plan.tasks[1].input, "/inputs/b part.stl") != NULL);
    }
    batch_plan_free(&plan);

    /* Defects: the line, the status words, the exit code. */
    check_defect("", CLI_EXIT_BAD_INPUT, "bad input: ");
    check_defect("not a job\n", CLI_EXIT_BAD_INPUT, "bad input: ");
    check_defect("fabvdb-job 2\n", CLI_EXIT_BAD_INPUT, "job.job:1: not a fabvdb job file of a version this fabvdb reads");
    check_defect("fabvdb-job 1\nhollw in.stl\n", CLI_EXIT_BAD_INPUT, "bad input: ");
    check_defect("fabvdb-job 1\nhollw in.stl\n", CLI_EXIT_BAD_INPUT, "job.job:2: no command 'hollw'");
    check_defect("fabvdb-job 1\nbatch x.job\n", CLI_EXIT_BAD_INPUT, "job.job:2: no command 'batch'");
    check_defect("fabvdb-job 1\nhollow \"open\n", CLI_EXIT_BAD_INPUT, "job.job:2: a quoted word is not closed");
    check_defect("fabvdb-job 1\nhollow in.stl --wal 3\n", CLI_EXIT_BAD_INPUT, "an option the command does not have");
    check_defect("fabvdb-job 1\nhollow {nope}\n", CLI_EXIT_BAD_INPUT, "an unknown placeholder");
    check_defect("fabvdb-job 1\ndirectory missing-folder\ninfo a.stl\n", CLI_EXIT_BAD_INPUT,
                 "job.job:2: cannot enter the directory 'missing-folder'");
    check_defect("fabvdb-job 1\ninfo a.stl\ntask late\ninfo b.stl\n", CLI_EXIT_BAD_INPUT,
                 "a command line before the first 'task' line");
    check_defect("fabvdb-job 1\ntask one\ninfo a\ntask one\ninfo b\n", CLI_EXIT_BAD_INPUT, "a second task called 'one'");
    check_defect("fabvdb-job 1\ntask bad/name\ninfo a\n", CLI_EXIT_BAD_INPUT, "a task name takes letters");
    check_defect("fabvdb-job 1\ntask empty\n", CLI_EXIT_BAD_INPUT, "the task 'empty' has no command line");
    check_defect("fabvdb-job 1\n", CLI_EXIT_BAD_INPUT, "no command line");
    check_defect("fabvdb-job 1\nrepair {input} -o x.stl\n", CLI_EXIT_USAGE, "give --inputs");
    CHECK(read_job("fabvdb-job 1\ninfo a.stl\n", inputs, NULL, &plan, error, sizeof error) == CLI_EXIT_USAGE);
    CHECK(strstr(error, "--inputs needs a recipe") != NULL);
    CHECK(batch_plan_read(temp_path(path, folder, "missing.job"), NULL, NULL, &plan, error, sizeof error) ==
          CLI_EXIT_BAD_INPUT);
    CHECK(strstr(error, "input/output error: ") == error && strstr(error, "cannot open the job file") != NULL);
    temp_path(path, folder, "empty-inputs");
    CHECK(mkdir(path, 0755) == 0);
    CHECK(read_job("fabvdb-job 1\ninfo {input}\n", path, NULL, &plan, error, sizeof error) == CLI_EXIT_BAD_INPUT);
    CHECK(strstr(error, "no input file matches") != NULL);

    temp_folder_remove(folder);
    return check_summary();
}
