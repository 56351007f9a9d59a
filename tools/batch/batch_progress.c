/* batch_progress.c — the batch's progress line and per-task notes
 * (batch_progress.h). */
#include "batch_progress.h"

#include <stdio.h>
#include <unistd.h>

#include "batch_record.h"

static void format_duration(double seconds, char* text, size_t size) {
    const long s = (long)(seconds + 0.5);
    if (s >= 3600) snprintf(text, size, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else snprintf(text, size, "%ld:%02ld", s / 60, s % 60);
}

void batch_progress_start(batch_progress* p, int total, int skipped, int quiet) {
    p->total = total;
    p->skipped = skipped;
    p->done = p->failed = p->running = p->shown = 0;
    p->started = batch_now();
    p->quiet = quiet;
    p->terminal = isatty(STDERR_FILENO);
}

void batch_progress_draw(batch_progress* p) {
    if (p->quiet || !p->terminal) return;
    const double elapsed = batch_now() - p->started;
    const int finished = p->done + p->failed;
    const int left = p->total - p->skipped - finished - p->running;
    char elapsed_text[32], eta[48] = "";
    format_duration(elapsed, elapsed_text, sizeof elapsed_text);
    if (finished > 0) {
        /* Tasks end at the rate seen so far; the running ones are half done. */
        char left_text[32];
        format_duration(elapsed / finished * (left + 0.5 * p->running), left_text, sizeof left_text);
        snprintf(eta, sizeof eta, ", ~%s left", left_text);
    }
    fprintf(stderr, "\r\033[Kbatch: %d done, %d failed, %d running, %d left; %s elapsed%s", p->done, p->failed,
            p->running, left, elapsed_text, eta);
    if (p->skipped) fprintf(stderr, " [%d already done]", p->skipped);
    fflush(stderr);
    p->shown = 1;
}

void batch_progress_clear(batch_progress* p) {
    if (!p->shown) return;
    fputs("\r\033[K", stderr);
    fflush(stderr);
    p->shown = 0;
}

void batch_progress_task_ended(batch_progress* p, const char* name, int done, double seconds, const char* message) {
    if (done) ++p->done;
    else ++p->failed;
    if (p->quiet) return;
    if (p->terminal) {
        if (!done) {
            batch_progress_clear(p);
            fprintf(stderr, "batch: %s failed: %s\n", name, message);
        }
        batch_progress_draw(p);
        return;
    }
    fprintf(stderr, "batch: [%d/%d] %s %s in %.1f s%s%s\n", p->skipped + p->done + p->failed, p->total, name,
            done ? "done" : "failed", seconds, done ? "" : ": ", done ? "" : message);
}
