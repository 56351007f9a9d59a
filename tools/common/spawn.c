/* spawn.c — fork, exec and the report of a failed exec (spawn.h). */
#define _GNU_SOURCE /* pipe2, prctl */
#include "spawn.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

/* In the child: reports what failed (and errno) to the parent and ends. */
static void child_failed(int report_fd, spawn_failure failure) {
    const int report[2] = {(int)failure, errno};
    ssize_t written = write(report_fd, report, sizeof report);
    (void)written;
    _exit(127);
}

pid_t spawn_start(const char* program, char* const argv[], const spawn_options* options, spawn_failure* failure) {
    const spawn_options defaults = {NULL, -1, 0};
    if (!options) options = &defaults;
    spawn_failure ignored;
    if (!failure) failure = &ignored;
    *failure = SPAWN_NO_PROCESS;
    int report[2];
    if (pipe2(report, O_CLOEXEC) != 0) return -1;
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) {
        const int error = errno;
        close(report[0]);
        close(report[1]);
        errno = error;
        return -1;
    }
    if (pid == 0) {
        close(report[0]);
        if (options->die_with_parent) {
            prctl(PR_SET_PDEATHSIG, SIGTERM);
            if (getppid() != parent) _exit(127); /* the parent ended already */
        }
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, NULL);
        const int null_fd = open("/dev/null", O_RDWR);
        if (null_fd >= 0) dup2(null_fd, STDIN_FILENO);
        const int output_fd = options->output_fd >= 0 ? options->output_fd : null_fd;
        if (output_fd >= 0) {
            dup2(output_fd, STDOUT_FILENO);
            dup2(output_fd, STDERR_FILENO);
        }
        if (options->directory && chdir(options->directory) != 0) child_failed(report[1], SPAWN_NO_DIRECTORY);
        if (strchr(program, '/')) execv(program, argv);
        else execvp(program, argv);
        child_failed(report[1], SPAWN_NO_PROGRAM);
    }
    close(report[1]);
    int told[2];
    ssize_t got;
    while ((got = read(report[0], told, sizeof told)) < 0 && errno == EINTR) {
    }
    close(report[0]);
    if (got != (ssize_t)sizeof told) return pid; /* the exec closed the pipe: running */
    while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {
    }
    *failure = (spawn_failure)told[0];
    errno = told[1];
    return -1;
}

int spawn_capture(const char* program, char* const argv[], char* out, size_t size) {
    out[0] = 0;
    int output[2];
    if (pipe2(output, O_CLOEXEC) != 0) {
        snprintf(out, size, "cannot run %s: %s", program, strerror(errno));
        return -1;
    }
    const spawn_options options = {NULL, output[1], 0};
    const pid_t pid = spawn_start(program, argv, &options, NULL);
    const int error = errno;
    close(output[1]);
    if (pid < 0) {
        close(output[0]);
        snprintf(out, size, "cannot run %s: %s", program, strerror(error));
        return -1;
    }
    size_t n = 0;
    ssize_t got;
    char sink[4096];
    while ((got = read(output[0], n + 1 < size ? out + n : sink, n + 1 < size ? size - n - 1 : sizeof sink)) > 0 ||
           (got < 0 && errno == EINTR))
        if (got > 0 && n + 1 < size) n += (size_t)got;
    out[n] = 0;
    close(output[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
