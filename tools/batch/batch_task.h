/* batch_task.h — running one task: each of its lines is a child process of
 * the same fabvdb binary (fork, exec /proc/self/exe), so a crash of one
 * command cannot take the batch down and its peak memory is read from
 * wait4's rusage. The child's output goes to the task's log in the state
 * folder (STATE/logs/NAME.log); it dies with a SIGTERM (it cancels and
 * removes its temporary files) if the batch dies. A line is started with the
 * threads and memory budget the scheduler gives it, unless the line sets
 * --threads or --max-memory itself. When the task ends, its record is written
 * (batch_record.h); a task interrupted by the batch's own cancellation writes
 * none, so it counts as not run. */
#ifndef FABVDB_BATCH_TASK_H
#define FABVDB_BATCH_TASK_H

#include <sys/resource.h>
#include <sys/types.h>

#include "batch_record.h"

typedef struct batch_task_run {
    const batch_task* task;
    const char* state;
    batch_record record;
    int next_line;      /* the line to start next, or the running one */
    pid_t pid;          /* the running child, or 0 */
    double reservation; /* bytes the running (or next) line reserves */
    int log_fd;
    long log_offset;    /* where the running line's output starts in the log */
    int keep_going;     /* run the lines after a failing one */
    int failed;         /* a line failed (with keep_going) */
} batch_task_run;

typedef enum batch_line_outcome {
    BATCH_LINE_NEXT,        /* the line ended, another follows */
    BATCH_LINE_OVER_BUDGET, /* refused with exit 3 under a share smaller than the whole budget: run it again */
    BATCH_TASK_ENDED        /* the task has ended (record.done says how) */
} batch_line_outcome;

/* Prepares the task: removes its old record and log, creates its output
 * folder, hashes its inputs. Returns 0, or -1 with the reason in
 * run->record.message (the task then ends failed). */
int batch_task_begin(batch_task_run* run, const batch_task* task, const char* state, int keep_going);
/* The --max-memory the next line sets itself, in bytes, or 0. */
double batch_task_own_budget(const batch_task_run* run);
/* Starts the next line with `threads` and `max_memory` bytes (0: leave them
 * to the line). Returns the child's pid, or -1 (the task has then failed). */
pid_t batch_task_spawn(batch_task_run* run, int threads, double max_memory);
/* Takes the ended child's wait status and usage. `whole_budget` is what the
 * batch can give one line at most. */
batch_line_outcome batch_task_reaped(batch_task_run* run, int status, const struct rusage* usage, double whole_budget);
/* Hashes the outputs and writes the record. Returns 0, or -1 with errno. */
int batch_task_end(batch_task_run* run);
/* Frees what the run holds (also for a task left unfinished). */
void batch_task_free(batch_task_run* run);

#endif
