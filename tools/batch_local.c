/* batch_local.c — the local scheduler (batch_local.h). Signals (SIGCHLD,
 * SIGINT, SIGTERM) are blocked and taken with sigtimedwait, so ended children
 * are reaped at once and the progress line is redrawn every second. */
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
#include "cli.h"

typedef enum slot_state { SLOT_FREE, SLOT_RUNNING, SLOT_WAITING } slot_state;

typedef struct slot {
    slot_state state;
    int todo_index;
    batch_task_run run;
} slot;

int batch_run_local(const batch_plan* plan, const int* todo, int todo_count, int skipped,
                    const batch_local_options* options) {
    const int jobs = options->jobs < todo_count ? options->jobs : (todo_count > 0 ? todo_count : 1);
    slot* slots = calloc((size_t)jobs, sizeof *slots);
    int* codes = calloc((size_t)(todo_count > 0 ? todo_count : 1), sizeof *codes);
    if (!slots || !codes) {
        free(slots);
        free(codes);
        fprintf(stderr, "fabvdb batch: out of memory\n");
        return CLI_EXIT_BUDGET;
    }
    sigset_t signals, previous;
    sigemptyset(&signals);
    sigaddset(&signals, SIGCHLD);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigprocmask(SIG_BLOCK, &signals, &previous);

    batch_progress progress;
    batch_progress_start(&progress, todo_count + skipped, skipped, options->quiet);
    int next = 0, cancelled = 0, unfinished = todo_count;
    double reserved = 0;
    for (;;) {
        /* Start what fits: tasks between lines first, then new ones, in order;
         * the first that does not fit waits and nothing starts before it. */
        while (!cancelled) {
            slot* chosen = NULL;
            for (int s = 0; s < jobs && !chosen; ++s)
                if (slots[s].state == SLOT_WAITING) chosen = &slots[s];
            if (!chosen && next < todo_count)
                for (int s = 0; s < jobs && !chosen; ++s)
                    if (slots[s].state == SLOT_FREE) chosen = &slots[s];
            if (!chosen) break;
            const int width = unfinished < jobs ? unfinished : jobs;
            if (chosen->state == SLOT_FREE) {
                chosen->todo_index = next++;
                const batch_task* task = &plan->tasks[todo[chosen->todo_index]];
                if (batch_task_begin(&chosen->run, task, options->state, options->keep_going) != 0) {
                    batch_task_end(&chosen->run);
                    codes[chosen->todo_index] = chosen->run.record.exit_code;
                    batch_progress_task_ended(&progress, task->name, 0, 0, chosen->run.record.message);
                    batch_task_free(&chosen->run);
                    --unfinished;
                    continue;
                }
                chosen->run.reservation = options->budget / width;
                chosen->state = SLOT_WAITING;
            }
            const double own = batch_task_own_budget(&chosen->run);
            double need = own > 0 ? own : chosen->run.reservation;
            if (need > options->budget) need = options->budget;
            if (reserved > 0 && reserved + need > options->budget) break;
            int threads = options->cores / width;
            if (threads < 1) threads = 1;
            chosen->run.reservation = need;
            if (batch_task_spawn(&chosen->run, threads, own > 0 ? 0 : need) < 0) {
                batch_task_end(&chosen->run);
                codes[chosen->todo_index] = chosen->run.record.exit_code;
                batch_progress_task_ended(&progress, chosen->run.task->name, 0, 0, chosen->run.record.message);
                batch_task_free(&chosen->run);
                chosen->state = SLOT_FREE;
                --unfinished;
                continue;
            }
            reserved += need;
            chosen->state = SLOT_RUNNING;
            ++progress.running;
        }
        if (progress.running == 0 && (cancelled || next >= todo_count)) {
            int waiting = 0;
            for (int s = 0; s < jobs; ++s) waiting |= slots[s].state == SLOT_WAITING;
            if (!waiting || cancelled) break;
        }
        batch_progress_draw(&progress);
        const struct timespec second = {1, 0};
        const int signal_number = sigtimedwait(&signals, NULL, &second);
        if (signal_number == SIGINT || signal_number == SIGTERM) {
            if (!cancelled) {
                cancelled = 1;
                for (int s = 0; s < jobs; ++s)
                    if (slots[s].state == SLOT_RUNNING) kill(slots[s].run.pid, SIGTERM);
            }
            continue;
        }
        int status;
        struct rusage usage;
        pid_t pid;
        while ((pid = wait4(-1, &status, WNOHANG, &usage)) > 0) {
            slot* owner = NULL;
            for (int s = 0; s < jobs && !owner; ++s)
                if (slots[s].state == SLOT_RUNNING && slots[s].run.pid == pid) owner = &slots[s];
            if (!owner) continue;
            --progress.running;
            reserved -= owner->run.reservation;
            if (reserved < 1) reserved = 0;
            const batch_line_outcome outcome = batch_task_reaped(&owner->run, status, &usage, options->budget);
            if (cancelled) {
                /* Interrupted: no record, the task counts as not run. */
                batch_task_free(&owner->run);
                owner->state = SLOT_FREE;
                continue;
            }
            if (outcome == BATCH_LINE_OVER_BUDGET) {
                owner->run.reservation *= 2;
                if (owner->run.reservation > options->budget) owner->run.reservation = options->budget;
                owner->state = SLOT_WAITING;
                continue;
            }
            if (outcome == BATCH_LINE_NEXT) {
                owner->run.reservation = options->budget / (unfinished < jobs ? unfinished : jobs);
                owner->state = SLOT_WAITING;
                continue;
            }
            const batch_record* record = &owner->run.record;
            if (batch_task_end(&owner->run) != 0) {
                batch_progress_clear(&progress);
                fprintf(stderr, "fabvdb batch: input/output error: cannot write the record of task '%s' into %s/tasks\n",
                        owner->run.task->name, options->state);
                codes[owner->todo_index] = CLI_EXIT_BAD_INPUT;
            } else {
                codes[owner->todo_index] = record->done ? CLI_EXIT_OK : record->exit_code;
            }
            batch_progress_task_ended(&progress, owner->run.task->name, record->done, record->ended - record->started,
                                      record->message);
            batch_task_free(&owner->run);
            owner->state = SLOT_FREE;
            --unfinished;
        }
    }
    for (int s = 0; s < jobs; ++s)
        if (slots[s].state != SLOT_FREE) batch_task_free(&slots[s].run);
    batch_progress_clear(&progress);
    sigprocmask(SIG_SETMASK, &previous, NULL);
    int code = cancelled ? CLI_EXIT_CANCELLED : CLI_EXIT_OK;
    for (int i = 0; i < todo_count && code == CLI_EXIT_OK; ++i) code = codes[i];
    free(slots);
    free(codes);
    return code;
}
