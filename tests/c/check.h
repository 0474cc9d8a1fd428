/* Assert-style checks shared by the C test programs (valid C11 and C++17).
 * A failed check prints file:line, what failed and this thread's last orthoslip error
 * message, then exits with status 1. */
#ifndef ORTHOSLIP_TEST_CHECK_H
#define ORTHOSLIP_TEST_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "orthoslip.h"

static inline void check_fail(const char *file, int line, const char *what)
{
    char msg[1024];
    size_t n = orthoslip_last_error_message(msg, sizeof msg);
    fprintf(stderr, "%s:%d: check failed: %s\n  last orthoslip error: %s\n", file, line, what,
            n > 0 ? msg : "(none)");
    exit(1);
}

/* ORTHOSLIP_TEST_QUICK is set (by the harness, under valgrind): same code paths, less work. */
static inline int test_quick(void)
{
    return getenv("ORTHOSLIP_TEST_QUICK") != NULL;
}

#define CHECK(cond)                                                                          \
    do {                                                                                     \
        if (!(cond)) check_fail(__FILE__, __LINE__, #cond);                                  \
    } while (0)

/* expr must return exactly the status want. */
#define CHECK_STATUS(expr, want)                                                             \
    do {                                                                                     \
        orthoslip_status check_got_ = (expr);                                                \
        if (check_got_ != (want)) {                                                          \
            fprintf(stderr, "%s:%d: got %s, expected %s\n", __FILE__, __LINE__,              \
                    orthoslip_status_string(check_got_), orthoslip_status_string(want));     \
            check_fail(__FILE__, __LINE__, #expr);                                           \
        }                                                                                    \
    } while (0)

#define CHECK_OK(expr) CHECK_STATUS(expr, ORTHOSLIP_OK)

/* a <= b for doubles (false for NaN), printing both values on failure. */
#define CHECK_LE(a, b)                                                                       \
    do {                                                                                     \
        double check_a_ = (a), check_b_ = (b);                                               \
        if (!(check_a_ <= check_b_)) {                                                       \
            fprintf(stderr, "%s:%d: %s = %.17g is not <= %s = %.17g\n", __FILE__, __LINE__,  \
                    #a, check_a_, #b, check_b_);                                             \
            check_fail(__FILE__, __LINE__, #a " <= " #b);                                    \
        }                                                                                    \
    } while (0)

/* This thread's last error message names `function` and contains `fragment` (a failure
 * reports the caller's line). */
#define CHECK_MESSAGE(function, fragment)                                                    \
    do {                                                                                     \
        char check_msg_[1024];                                                               \
        orthoslip_last_error_message(check_msg_, sizeof check_msg_);                         \
        if (strstr(check_msg_, (function)) == NULL || strstr(check_msg_, (fragment)) == NULL) \
            check_fail(__FILE__, __LINE__, "message names " #function " and " #fragment);   \
    } while (0)

#endif
