/* spawn.h — starting another program as a child process, the one fork/exec
 * of tools/: batch runs each command line as a child of the same binary
 * (/proc/self/exe), asks Slurm through its commands (sbatch, squeue,
 * scontrol), and the studio opens the page with xdg-open. The child reads
 * /dev/null, writes where it is told, starts with no signal blocked and
 * SIGINT and SIGTERM at their defaults, and runs no shell. Whether the exec
 * (and the change of directory before it) succeeded is known before
 * spawn_start returns: the child reports a failure through a close-on-exec
 * pipe. Costs one fork, one pipe and a read that ends at the exec. */
#ifndef FABVDB_SPAWN_H
#define FABVDB_SPAWN_H

#include <stddef.h>
#include <sys/types.h>

typedef struct spawn_options {
    const char* directory; /* the child's working directory, or NULL: this process's */
    int output_fd;         /* the child's stdout and stderr, or -1: /dev/null */
    int die_with_parent;   /* the child gets SIGTERM when this process ends (Linux) */
} spawn_options;

/* What failed when spawn_start returns -1. */
typedef enum spawn_failure {
    SPAWN_NO_PROCESS,  /* fork or pipe failed */
    SPAWN_NO_DIRECTORY, /* the child could not enter options->directory */
    SPAWN_NO_PROGRAM    /* the exec failed (missing, not executable) */
} spawn_failure;

/* Starts `program` (searched in PATH unless it holds a '/') with argv
 * (argv[0] the name it sees, NULL-terminated). options: NULL for the
 * defaults above (own directory, output to /dev/null, not tied to this
 * process). Returns the child's pid (the caller reaps it), or -1 with errno
 * set and, when `failure` is not NULL, what failed in *failure. */
pid_t spawn_start(const char* program, char* const argv[], const spawn_options* options, spawn_failure* failure);

/* Runs `program` with argv to its end, its stdout and stderr kept in out
 * (NUL-terminated, the rest dropped when longer than size - 1). Returns its
 * exit code, or -1 when it could not run or a signal ended it (out then says
 * why, when it could not run). */
int spawn_capture(const char* program, char* const argv[], char* out, size_t size);

#endif
