/* stats.c - walking the counters of rt_stats.h by key. */
#include "rt_stats.h"

#include "geometry/prim_kinds.h"

#include <stddef.h>

/* A table rather than one call per counter: smaller on the board. */
static const struct {
    const char *key;
    uint16_t offset; /* in rt_stats_t */
} counters[] = {
#define RT_STATS_ROW(key, what) { #key, offsetof(rt_stats_t, key) },
    RT_STATS_COUNTERS(RT_STATS_ROW)
#undef RT_STATS_ROW
#define RT_STATS_ROW_TESTS(type, table, cap, KIND, name, use) \
    { #name "_tests", offsetof(rt_stats_t, prim_tests) + PRIM_##KIND * sizeof(uint64_t) },
    RT_PRIM_KINDS(RT_STATS_ROW_TESTS)
#undef RT_STATS_ROW_TESTS
};

void rt_stats_each(const rt_stats_t *st, rt_stats_visit_fn *visit, void *ctx)
{
    for (size_t i = 0; i < sizeof counters / sizeof counters[0]; i++)
        visit(ctx, counters[i].key, *(const uint64_t *)(const void *)((const char *)st + counters[i].offset));
}

_Static_assert(PRIM_KIND_COUNT <= RT_STATS_MAX_KINDS, "rt_stats_t has a counter per primitive kind");

uint64_t rt_stats_tests(const rt_stats_t *st)
{
    uint64_t n = 0;
    for (unsigned k = 0; k < PRIM_KIND_COUNT; k++)
        n += st->prim_tests[k];
    return n;
}

/* over the table too: smaller than one add per counter */
void rt_stats_add(rt_stats_t *sum, const rt_stats_t *part)
{
    for (size_t i = 0; i < sizeof counters / sizeof counters[0]; i++)
        *(uint64_t *)(void *)((char *)sum + counters[i].offset) +=
            *(const uint64_t *)(const void *)((const char *)part + counters[i].offset);
}
