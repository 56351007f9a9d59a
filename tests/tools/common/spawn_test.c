/* spawn_test.c — tools/common/spawn.c: a child's exit code and output
 * captured (and cut at the buffer's end), a missing program and a missing
 * directory known before spawn_start returns, the child's working
 * directory, output file and empty signal mask. */
#define _GNU_SOURCE /* mkdtemp, nftw */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>

#include "capi/check.h"
#include "common/spawn.h"
#include "tools/temp_folder.h"

int main(void) {
    char out[256];
    char* echo[] = {"sh", "-c", "echo out; echo err >&2; exit 3", NULL};
    CHECK(spawn_capture("sh", echo, out, sizeof out) == 3);
    CHECK(strcmp(out, "out\nerr\n") == 0);

    /* Output longer than the buffer: the start is kept, the rest drained. */
    char small[5];
    char* yes[] = {"sh", "-c", "i=0; while [ $i -lt 2000 ]; do echo line; i=$((i+1)); done", NULL};
    CHECK(spawn_capture("sh", yes, small, sizeof small) == 0);
    CHECK(strcmp(small, "line") == 0);

    char* missing[] = {"no-such-program-fabvdb", NULL};
    CHECK(spawn_capture("no-such-program-fabvdb", missing, out, sizeof out) == -1);
    CHECK(strstr(out, "cannot run no-such-program-fabvdb") != NULL);
    spawn_failure failure = SPAWN_NO_PROCESS;
    errno = 0;
    CHECK(spawn_start("no-such-program-fabvdb", missing, NULL, &failure) == -1);
    CHECK(failure == SPAWN_NO_PROGRAM && errno == ENOENT);

    char folder[4096], path[4096], text[4200];
    CHECK(temp_folder_make(folder) == 0);
    temp_path(path, folder, "missing-folder");
    spawn_options in_missing = {path, -1, 0};
    char* truth[] = {"true", NULL};
    errno = 0;
    CHECK(spawn_start("true", truth, &in_missing, &failure) == -1);
    CHECK(failure == SPAWN_NO_DIRECTORY && errno == ENOENT);

    /* Its directory, its output into a file, no signal blocked although this
     * process blocks SIGTERM, stdin empty. */
    sigset_t block;
    sigemptyset(&block);
    sigaddset(&block, SIGTERM);
    sigprocmask(SIG_BLOCK, &block, NULL);
    const int log_fd = open(temp_path(path, folder, "log"), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    CHECK(log_fd >= 0);
    spawn_options options = {folder, log_fd, 1};
    char* report[] = {"sh", "-c", "pwd; grep '^SigBlk' /proc/self/status; cat; echo end", NULL};
    const pid_t pid = spawn_start("/bin/sh", report, &options, &failure);
    CHECK(pid > 0);
    int status = 0;
    CHECK(waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0);
    close(log_fd);
    CHECK(temp_read(path, text, sizeof text) == 0);
    char wanted[4200];
    snprintf(wanted, sizeof wanted, "%s\nSigBlk:\t0000000000000000\nend\n", folder);
    CHECK(strcmp(text, wanted) == 0);
    if (strcmp(text, wanted) != 0) fprintf(stderr, "  got: %s", text);

    temp_folder_remove(folder);
    return check_summary();
}
