/* libFuzzer target: the job-file reader of `fabvdb batch` on arbitrary
 * bytes: each line through the tokenizer (tools/common/job.c), and the whole
 * as a job file through batch_plan_read (tools/batch/batch_plan.c: the
 * header, 'directory', 'task' and 'line' lines, placeholders, each command's
 * options), read from an in-memory file. A plan it accepts is written out and
 * read back. */
#define _GNU_SOURCE /* memfd_create */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "batch/batch_plan.h"
#include "common/job.h"

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    char* text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = 0;
    job_line line;
    const char* error = NULL;
    for (char* start = text; start; ) {
        char* end = strchr(start, '\n');
        if (end) *end = 0;
        if (job_tokenize(start, &line, &error) == 0) job_line_free(&line);
        if (end) *end = '\n';
        start = end ? end + 1 : NULL;
    }
    free(text);

    const int fd = memfd_create("job", 0);
    if (fd < 0) return 0;
    if (write(fd, data, size) == (ssize_t)size) {
        char path[64], message[4096];
        snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
        batch_plan plan;
        if (batch_plan_read(path, NULL, NULL, &plan, message, sizeof message) == 0) {
            char written[] = "/dev/shm/fuzz_job_plan_XXXXXX";
            const int out = mkstemp(written);
            if (out >= 0) {
                close(out);
                batch_plan again;
                if (batch_plan_write(&plan, "fuzz", written) == 0 &&
                    batch_plan_read(written, NULL, NULL, &again, message, sizeof message) == 0) {
                    if (again.task_count != plan.task_count) abort(); /* the plan reads back as written */
                    batch_plan_free(&again);
                }
                unlink(written);
            }
            batch_plan_free(&plan);
        }
    }
    close(fd);
    return 0;
}
