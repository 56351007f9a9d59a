/* orientation_file_test.c — tools/cli/orientation_file.c: "all" is the
 * library's set (no list); a file's directions with comments and blank
 * lines skipped; a bad line, an empty list and a missing file refused with
 * the file, line and status words on stderr and exit 2. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include "capi/check.h"
#include "cli/commands.h"
#include "cli/orientation_file.h"
#include "tools/temp_folder.h"

static char folder[4096];

/* Reads the orientations of `text` (NULL: the spec names no file); the exit
 * code, stderr in err. */
static int read_list(const cli_run* run, const char* spec, const char* text, double** values, size_t* count,
                     char* err, size_t size) {
    char path[4096], log[4096];
    if (text) temp_write(temp_path(path, folder, spec), text);
    const int saved = temp_stderr_begin(temp_path(log, folder, "stderr"));
    const int code = cli_read_orientations(run, text ? path : spec, values, count);
    temp_stderr_end(saved);
    temp_read(log, err, size);
    return code;
}

int main(void) {
    CHECK(temp_folder_make(folder) == 0);
    cli_run run;
    memset(&run, 0, sizeof run);
    run.command = &cmd_drain;
    double* values = NULL;
    size_t count = 7;
    char err[4096];
    CHECK(read_list(&run, "all", NULL, &values, &count, err, sizeof err) == CLI_EXIT_OK && !values && count == 0);
    CHECK(read_list(&run, "o.txt", "# gravity directions\n0 0 -1\n\n1 0 0  # sideways\n", &values, &count, err,
                    sizeof err) == CLI_EXIT_OK);
    CHECK(count == 2 && values && values[2] == -1 && values[3] == 1);
    free(values);
    CHECK(read_list(&run, "bad.txt", "0 0 -1\n0 0\n", &values, &count, err, sizeof err) == CLI_EXIT_BAD_INPUT);
    CHECK(strstr(err, "fabvdb drain: bad input: ") == err && strstr(err, "bad.txt:2: expected a direction") != NULL);
    CHECK(read_list(&run, "zero.txt", "0 0 0\n", &values, &count, err, sizeof err) == CLI_EXIT_BAD_INPUT);
    CHECK(read_list(&run, "empty.txt", "# nothing\n", &values, &count, err, sizeof err) == CLI_EXIT_BAD_INPUT);
    CHECK(strstr(err, "no orientation in the file") != NULL);
    CHECK(read_list(&run, "/no/such/file", NULL, &values, &count, err, sizeof err) == CLI_EXIT_BAD_INPUT);
    CHECK(strstr(err, "fabvdb drain: input/output error: /no/such/file: cannot open the orientations file") == err);
    temp_folder_remove(folder);
    return check_summary();
}
