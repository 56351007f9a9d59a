/* batch_local.c — the local scheduler (batch_local.h). Signals (SIGCHLD,
 * SIGINT, SIGTERM) are blocked and taken with sigtimedwait, so ended children
 * are reaped at once and the progress line is redrawn every second. Each turn
 * of its loop has three phases: start what fits, wait for a signal, reap. */
#define _GNU_SOURCE /* sigtimedwait, wait4 */
#include "batch_local.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>

#include "batch_progress.h"
#include "batch_task.h"
#include "cli/cli.h"
#include "common/status_text.h"

typedef enum slot_state { SLOT_FREE, SLOT_RUNNING, SLOT_WAITING } slot_state;

typedef struct slot {
    slot_state state;
    int todo_index;
    batch_task_run run;
} slot;

/* The state of one run of the scheduler. */
typedef struct scheduler {
    const batch_plan* plan;
    const int* todo;
    int todo_count;
    const batch_local_options* options;
    int jobs;         /* slots */
    slot* slots;
    int* codes;       /* per todo index: the task's exit code */
    batch_progress progress;
    int next;         /* the next todo index to start */
    int cancelled;
    int unfinished;   /* tasks not ended yet */
    double reserved;  /* bytes the running lines reserve */
} scheduler;

/* Tasks that share the machine now: at most `jobs`, fewer near the end. */
static int width(const scheduler* s) { return s->unfinished < s->jobs ? s->unfinished : s->jobs; }

/* A task has ended (done, failed, or failed to start): its exit code, its
 * line of progress, its slot freed. */
static void end_task(scheduler* s, slot* chosen, int code) {
    const batch_record* record = &chosen->run.record;
    s->codes[chosen->todo_index] = code;
    batch_progress_task_ended(&s->progress, chosen->run.task->name, record->done, record->ended - record->started,
                              record->message);
    batch_task_free(&chosen->run);
    chosen->state = SLOT_FREE;
    --s->unfinished;
}

/* Writes the record of a task that ended and ends it. */
static void record_task(scheduler* s, slot* chosen) {
    int code;
    if (batch_task_end(&chosen->run) != 0) {
        batch_progress_clear(&s->progress);
        status_print("batch", FABVDB_ERR_IO, "cannot write the record of task '%s' into %s/tasks",
                     chosen->run.task->name, s->options->state);
        code = cli_exit_code(FABVDB_ERR_IO);
    } else {
        code = chosen->run.record.done ? CLI_EXIT_OK : chosen->run.record.exit_code;
    }
    end_task(s, chosen, code);
}

/* The slot to start next: a task between lines first, then a new one. */
static slot* next_slot(scheduler* s) {
    for (int k = 0; k < s->jobs; ++k)
        if (s->slots[k].state == SLOT_WAITING) return &s->slots[k];
    if (s->next >= s->todo_count) return NULL;
    for (int k = 0; k < s->jobs; ++k)
        if (s->slots[k].state == SLOT_FREE) return &s->slots[k];
    return NULL;
}

/* Phase 1: starts what fits, in order; the first that does not fit waits and
 * nothing starts before it. */
static void start_what_fits(scheduler* s) {
    const batch_local_options* options = s->options;
    while (!s->cancelled) {
        slot* chosen = next_slot(s);
        if (!chosen) return;
        if (chosen->state == SLOT_FREE) {
            chosen->todo_index = s->next++;
            const batch_task* task = &s->plan->tasks[s->todo[chosen->todo_index]];
            if (batch_task_begin(&chosen->run, task, options->state, options->keep_going) != 0) {
                batch_task_end(&chosen->run);
                end_task(s, chosen, chosen->run.record.exit_code);
                continue;
            }
            chosen->run.reservation = options->budget / width(s);
            chosen->state = SLOT_WAITING;
        }
        const double own = batch_task_own_budget(&chosen->run);
        double need = own > 0 ? own : chosen->run.reservation;
        if (need > options->budget) need = options->budget;
        if (s->reserved > 0 && s->reserved + need > options->budget) return;
        int threads = options->cores / width(s);
        if (threads < 1) threads = 1;
        chosen->run.reservation = need;
        if (batch_task_spawn(&chosen->run, threads, own > 0 ? 0 : need) < 0) {
            batch_task_end(&chosen->run);
            end_task(s, chosen, chosen->run.record.exit_code);
            continue;
        }
        s->reserved += need;
        chosen->state = SLOT_RUNNING;
        ++s->progress.running;
    }
}

/* Whether the loop is over: nothing runs and nothing is left to start. */
static int finished(const scheduler* s) {
    if (s->progress.running > 0 || (!s->cancelled && s->next < s->todo_count)) return 0;
    if (s->cancelled) return 1;
    for (int k = 0; k < s->jobs; ++k)
        if (s->slots[k].state == SLOT_WAITING) return 0;
    return 1;
}

/* Phase 3: takes every ended child and moves its task on. */
static void reap(scheduler* s) {
    int status;
    struct rusage usage;
    pid_t pid;
    while ((pid = wait4(-1, &status, WNOHANG, &usage)) > 0) {
        slot* owner = NULL;
        for (int k = 0; k < s->jobs && !owner; ++k)
            if (s->slots[k].state == SLOT_RUNNING && s->slots[k].run.pid == pid) owner = &s->slots[k];
        if (!owner) continue;
        --s->progress.running;
        s->reserved -= owner->run.reservation;
        if (s->reserved < 1) s->reserved = 0;
        const batch_line_outcome outcome = batch_task_reaped(&owner->run, status, &usage, s->options->budget);
        if (s->cancelled) {
            /* Interrupted: no record, the task counts as not run. */
            batch_task_free(&owner->run);
            owner->state = SLOT_FREE;
        } else if (outcome == BATCH_LINE_OVER_BUDGET) {
            owner->run.reservation *= 2;
            if (owner->run.reservation > s->options->budget) owner->run.reservation = s->options->budget;
            owner->state = SLOT_WAITING;
        } else if (outcome == BATCH_LINE_NEXT) {
            owner->run.reservation = s->options->budget / width(s);
            owner->state = SLOT_WAITING;
        } else {
            record_task(s, owner);
        }
    }
}

/* Phase 2: waits for a child to end, an interruption or a second; on the
 * first interruption every running task is sent SIGTERM. Returns whether
 * there may be children to reap. */
static int wait_for_signal(scheduler* s, const sigset_t* signals) {
    batch_progress_draw(&s->progress);
    const struct timespec second = {1, 0};
    const int signal_number = sigtimedwait(signals, NULL, &second);
    if (signal_number != SIGINT && signal_number != SIGTERM) return 1;
    if (!s->cancelled) {
        s->cancelled = 1;
        for (int k = 0; k < s->jobs; ++k)
            if (s->slots[k].state == SLOT_RUNNING) kill(s->slots[k].run.pid, SIGTERM);
    }
    return 0;
}

int batch_run_local(const batch_plan* plan, const int* todo, int todo_count, int skipped,
                    const batch_local_options* options) {
    scheduler s;
    memset(&s, 0, sizeof s);
    s.plan = plan;
    s.todo = todo;
    s.todo_count = todo_count;
    s.options = options;
    s.jobs = options->jobs < todo_count ? options->jobs : (todo_count > 0 ? todo_count : 1);
    s.unfinished = todo_count;
    s.slots = calloc((size_t)s.jobs, sizeof *s.slots);
    s.codes = calloc((size_t)(todo_count > 0 ? todo_count : 1), sizeof *s.codes);
    if (!s.slots || !s.codes) {
        free(s.slots);
        free(s.codes);
        fprintf(stderr, "fabvdb batch: out of memory\n");
        return CLI_EXIT_BUDGET;
    }
    sigset_t signals, previous;
    sigemptyset(&signals);
    sigaddset(&signals, SIGCHLD);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigprocmask(SIG_BLOCK, &signals, &previous);

    batch_progress_start(&s.progress, todo_count + skipped, skipped, options->quiet);
    for (;;) {
        start_what_fits(&s);
        if (finished(&s)) break;
        if (wait_for_signal(&s, &signals)) reap(&s);
    }
    for (int k = 0; k < s.jobs; ++k)
        if (s.slots[k].state != SLOT_FREE) batch_task_free(&s.slots[k].run);
    batch_progress_clear(&s.progress);
    sigprocmask(SIG_SETMASK, &previous, NULL);
    int code = s.cancelled ? CLI_EXIT_CANCELLED : CLI_EXIT_OK;
    for (int i = 0; i < todo_count && code == CLI_EXIT_OK; ++i) code = s.codes[i];
    free(s.slots);
    free(s.codes);
    return code;
}
