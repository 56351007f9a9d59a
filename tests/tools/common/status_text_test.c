/* status_text_test.c — tools/common/status_text.c: every status's words come
 * from fabvdb_status_string, the message follows them, a short buffer is cut
 * but ended, and status_print writes "fabvdb PROGRAM: <status>: <message>". */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "capi/check.h"
#include "common/status_text.h"
#include "tools/temp_folder.h"

int main(void) {
    const fabvdb_status statuses[] = {FABVDB_ERR_INVALID_ARGUMENT, FABVDB_ERR_IO,        FABVDB_ERR_BAD_INPUT,
                                      FABVDB_ERR_OUT_OF_BUDGET,    FABVDB_ERR_OUT_OF_MEMORY, FABVDB_ERR_CANCELLED,
                                      FABVDB_ERR_INTERNAL,         FABVDB_ERR_NOT_FOUND};
    for (size_t i = 0; i < sizeof statuses / sizeof statuses[0]; ++i) {
        char text[256], wanted[256];
        status_text(text, sizeof text, statuses[i], "%s: %d", "file.stl", 7);
        snprintf(wanted, sizeof wanted, "%s: file.stl: 7", fabvdb_status_string(statuses[i]));
        CHECK(strcmp(text, wanted) == 0);
    }
    char text[256];
    status_text(text, sizeof text, FABVDB_ERR_IO, "x");
    CHECK(strcmp(text, "input/output error: x") == 0);
    char small[8];
    status_text(small, sizeof small, FABVDB_ERR_IO, "a long message");
    CHECK(strlen(small) == sizeof small - 1 && strncmp(small, "input/o", 7) == 0);
    status_text(small, sizeof small, FABVDB_ERR_BAD_INPUT, "ok"); /* "bad input: " is longer than 7 */
    CHECK(strlen(small) == 7);

    char folder[4096], path[4096];
    CHECK(temp_folder_make(folder) == 0);
    temp_path(path, folder, "stderr");
    const int saved = temp_stderr_begin(path);
    CHECK(saved >= 0);
    status_print("batch", FABVDB_ERR_BAD_INPUT, "%s: no command '%s'", "job.job:3", "hollw");
    temp_stderr_end(saved);
    CHECK(temp_read(path, text, sizeof text) == 0);
    CHECK(strcmp(text, "fabvdb batch: bad input: job.job:3: no command 'hollw'\n") == 0);
    temp_folder_remove(folder);
    return check_summary();
}
