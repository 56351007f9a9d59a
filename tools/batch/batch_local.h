/* batch_local.h — runs tasks on this machine, several at once, under one
 * memory budget and one set of cores. At most `jobs` tasks run at a time;
 * each line starts with a share of the budget (the budget over the tasks that
 * can run at once) as its --max-memory, and with the cores over those tasks
 * as its --threads, so N tasks never run N x all-cores threads. The commands
 * estimate their memory before allocating: a line refused (exit 3) under its
 * share asks for twice as much, up to the whole budget, and waits until that
 * much is free (no other task starts before it); one refused under the whole
 * budget can never fit and fails with exit 3 and its message. A failing task
 * does not stop the others. SIGINT or SIGTERM stops the batch: the running
 * commands are cancelled (they remove their temporary files), their tasks
 * write no record, and the batch exits 130. */
#ifndef FABVDB_BATCH_LOCAL_H
#define FABVDB_BATCH_LOCAL_H

#include "batch_plan.h"

typedef struct batch_local_options {
    int jobs;          /* tasks at once, >= 1 */
    int cores;         /* cores the lines' threads share, >= 1 */
    double budget;     /* bytes all running lines share */
    int keep_going;    /* run a task's lines after a failing one */
    int quiet;
    const char* state; /* the state folder (tasks/ and logs/ exist) */
} batch_local_options;

/* Runs the tasks of `plan` whose indices are in todo[0..todo_count) (in that
 * order); `skipped` tasks were found done already (for the progress line).
 * Returns 0 when all of them are done, 130 when cancelled, else the exit code
 * of the first task (in todo order) that failed. */
int batch_run_local(const batch_plan* plan, const int* todo, int todo_count, int skipped,
                    const batch_local_options* options);

#endif
