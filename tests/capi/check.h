/* check.h — a minimal test harness for the C API tests: CHECK(condition)
 * counts passes and failures and prints each failure; check_summary() prints
 * the closing "N passed, N failed" line and gives the exit code. */
#ifndef FABVDB_CHECK_H
#define FABVDB_CHECK_H

#include <stdio.h>

static int check_passed = 0, check_failed = 0;

#define CHECK(condition)                                                        \
    do {                                                                        \
        if (condition) {                                                        \
            ++check_passed;                                                     \
        } else {                                                                \
            ++check_failed;                                                     \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #condition); \
        }                                                                       \
    } while (0)

static int check_summary(void) {
    printf("%d passed, %d failed\n", check_passed, check_failed);
    return check_failed == 0 ? 0 : 1;
}

#endif
