/* testlib.h - a minimal check/count harness for the C tests. */
#ifndef TESTLIB_H
#define TESTLIB_H

#include <stdio.h>

static int tl_passed, tl_failed;

/* One check = one property; the message should carry the measured figure. */
#define CHECK(cond, ...)                                                   \
    do {                                                                   \
        if (cond) {                                                        \
            tl_passed++;                                                   \
            printf("  ok    ");                                            \
        } else {                                                           \
            tl_failed++;                                                   \
            printf("  FAIL  %s:%d: ", __FILE__, __LINE__);                 \
        }                                                                  \
        printf(__VA_ARGS__);                                               \
        printf("\n");                                                      \
    } while (0)

/* Prints "<name>: N passed, M failed" (collected by tests/run-all.py). */
static inline int tl_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, tl_passed, tl_failed);
    return tl_failed ? 1 : 0;
}

/* Deterministic xorshift64* so failures reproduce. */
static unsigned long long tl_rng_state = 0x9E3779B97F4A7C15ull;
static inline unsigned long long tl_rand(void)
{
    tl_rng_state ^= tl_rng_state >> 12;
    tl_rng_state ^= tl_rng_state << 25;
    tl_rng_state ^= tl_rng_state >> 27;
    return tl_rng_state * 2685821657736338717ull;
}
/* uniform in [lo, hi) */
static inline double tl_uniform(double lo, double hi)
{
    return lo + (hi - lo) * ((double)(tl_rand() >> 11) / 9007199254740992.0);
}

#endif
