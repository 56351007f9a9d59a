/* job_test.c — tools/common/job.c: job lines split into words (bare, quoted
 * with \" and \\, a # where a word would start ending the line), the two
 * defects, and job_write_token read back by job_tokenize. */
#define _GNU_SOURCE /* open_memstream */
#include "capi/check.h"
#include "common/job.h"

#include <stdlib.h>
#include <string.h>

int main(void) {
    job_line line;
    const char* error = NULL;
    CHECK(job_tokenize("  hollow in.stl \"-o\" \"out dir/o.stl\" --wall=3mm # a comment\n", &line, &error) == 0);
    CHECK(line.count == 5);
    CHECK(line.count == 5 && strcmp(line.tokens[0], "hollow") == 0 && strcmp(line.tokens[3], "out dir/o.stl") == 0 &&
          strcmp(line.tokens[4], "--wall=3mm") == 0);
    job_line_free(&line);
    CHECK(line.count == 0);

    CHECK(job_tokenize("say \"a \\\"quoted\\\" word\" \"back\\\\slash\" a#b \"\"", &line, &error) == 0);
    CHECK(line.count == 5 && strcmp(line.tokens[1], "a \"quoted\" word") == 0 &&
          strcmp(line.tokens[2], "back\\slash") == 0 && strcmp(line.tokens[3], "a#b") == 0 &&
          strcmp(line.tokens[4], "") == 0);
    job_line_free(&line);

    CHECK(job_tokenize("   # only a comment", &line, &error) == 0 && line.count == 0);
    CHECK(job_tokenize("", &line, &error) == 0 && line.count == 0);

    error = NULL;
    CHECK(job_tokenize("hollow \"not closed", &line, &error) == -1 && line.count == 0);
    CHECK(error && strcmp(error, "a quoted word is not closed") == 0);

    /* One word more than a line holds. */
    char* many = malloc(2 * (JOB_MAX_TOKENS + 1) + 1);
    for (int i = 0; i <= JOB_MAX_TOKENS; ++i) many[2 * i] = 'w', many[2 * i + 1] = ' ';
    many[2 * (JOB_MAX_TOKENS + 1)] = 0;
    error = NULL;
    CHECK(job_tokenize(many, &line, &error) == -1 && line.count == 0);
    CHECK(error && strcmp(error, "too many words on one line") == 0);
    many[2 * JOB_MAX_TOKENS] = 0; /* exactly the most */
    CHECK(job_tokenize(many, &line, &error) == 0 && line.count == JOB_MAX_TOKENS);
    job_line_free(&line);
    free(many);

    /* Written tokens read back as they were. */
    const char* const words[] = {"plain", "with space", "quote\"inside", "back\\slash", "#hash", ""};
    char* text = NULL;
    size_t size = 0;
    FILE* out = open_memstream(&text, &size);
    for (size_t i = 0; i < sizeof words / sizeof words[0]; ++i) {
        job_write_token(out, words[i]);
        fputc(' ', out);
    }
    fclose(out);
    CHECK(job_tokenize(text, &line, &error) == 0 && line.count == (int)(sizeof words / sizeof words[0]));
    for (int i = 0; i < line.count; ++i) CHECK(strcmp(line.tokens[i], words[i]) == 0);
    job_line_free(&line);
    free(text);
    return check_summary();
}
