/* batch_progress.h — a batch's progress on stderr: on a terminal one line
 * redrawn in place (tasks done / failed / running / left, elapsed time and an
 * estimate of the time left); otherwise one line per task that ends, for
 * logs; nothing with --quiet. */
#ifndef FABVDB_BATCH_PROGRESS_H
#define FABVDB_BATCH_PROGRESS_H

typedef struct batch_progress {
    int total, done, failed, running, skipped;
    double started;  /* seconds since the epoch */
    int quiet;
    int terminal;    /* stderr is a terminal */
    int shown;       /* a progress line is on screen */
} batch_progress;

void batch_progress_start(batch_progress* p, int total, int skipped, int quiet);
/* Redraws the line (terminal only). */
void batch_progress_draw(batch_progress* p);
/* A task ended: counts it and, off a terminal, prints a line for it. */
void batch_progress_task_ended(batch_progress* p, const char* name, int done, double seconds, const char* message);
/* Clears the line before other output. */
void batch_progress_clear(batch_progress* p);

#endif
