/* batch_progress_test.c — tools/batch/batch_progress.c off a terminal (as in
 * a log): one line per task that ends, counted against the total and the
 * tasks done already; nothing with --quiet. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "batch/batch_progress.h"
#include "capi/check.h"
#include "tools/temp_folder.h"

int main(void) {
    char folder[4096], path[4096], text[4096];
    CHECK(temp_folder_make(folder) == 0);
    temp_path(path, folder, "stderr");
    int saved = temp_stderr_begin(path);
    batch_progress progress;
    batch_progress_start(&progress, 4, 1, 0);
    batch_progress_draw(&progress); /* off a terminal: nothing */
    batch_progress_task_ended(&progress, "bunny", 1, 1.25, "");
    batch_progress_task_ended(&progress, "teapot", 0, 0.5, "fabvdb repair: bad input: teapot.obj: no triangles");
    batch_progress_clear(&progress);
    temp_stderr_end(saved);
    CHECK(temp_read(path, text, sizeof text) == 0);
    CHECK(strcmp(text, "batch: [2/4] bunny done in 1.2 s\n"
                       "batch: [3/4] teapot failed in 0.5 s: fabvdb repair: bad input: teapot.obj: no triangles\n") == 0);
    if (strstr(text, "bunny") == NULL) fprintf(stderr, "  got: %s\n", text);
    CHECK(progress.done == 1 && progress.failed == 1);

    saved = temp_stderr_begin(path);
    batch_progress_start(&progress, 2, 0, 1);
    batch_progress_task_ended(&progress, "quiet", 1, 1, "");
    temp_stderr_end(saved);
    CHECK(temp_read(path, text, sizeof text) == 0 && text[0] == 0);
    CHECK(progress.done == 1);
    temp_folder_remove(folder);
    return check_summary();
}
