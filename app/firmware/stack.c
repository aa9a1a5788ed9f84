/*
 * stack.c - stack measurement for every port: main() paints the free
 * stack with a pattern first; after the render the deepest word no longer
 * holding it gives the high-water mark, and the guard words at the
 * stack's low end must still hold it (an overflow on a board whose RAM
 * ignores stray writes would otherwise go unnoticed).
 *
 * A board with two cores (BOARD_CORES 2) has a second stack, .stack1 in
 * its link.ld, with the same size and guard: stack_paint() paints the one
 * it runs on, the *_core() functions measure either. A single-core build
 * compiles exactly the functions it always had.
 */
#include "port.h"

#ifndef BOARD_CORES
#define BOARD_CORES 1
#endif

extern uint32_t __stack_limit[], __stack_top[], __stack_guard_end[];
#if BOARD_CORES > 1
extern uint32_t __stack1_limit[], __stack1_top[], __stack1_guard_end[];
#endif
/* Each start/end pair above bounds one region of the linker script: the
 * loops below compare pointers within it, which cppcheck cannot know. */

#define STACK_PAINT 0xA5A5A5A5u

/* noinline: its frame is below the caller's, and it paints below its own */
__attribute__((noinline)) void stack_paint(void)
{
    volatile uint32_t *p = __stack_limit;
    const volatile uint32_t *own = (const volatile uint32_t *)__builtin_frame_address(0) - 32;
#if BOARD_CORES > 1
    /* on core 1's stack: paint that one (the address tells, no core id needed) */
    if ((uintptr_t)own >= (uintptr_t)__stack1_limit && (uintptr_t)own < (uintptr_t)__stack1_top)
        p = __stack1_limit;
#endif
    /* cppcheck-suppress comparePointers ; one region: the stack */
    while (p < own)
        *p++ = STACK_PAINT;
}

static inline uint32_t region_size(const uint32_t *limit, const uint32_t *top)
{
    return (uint32_t)((uintptr_t)top - (uintptr_t)limit);
}

static inline uint32_t region_high_water(const uint32_t *limit, const uint32_t *top)
{
    const uint32_t *p = limit;
    /* cppcheck-suppress comparePointers ; one region: the stack */
    while (p < top && *p == STACK_PAINT)
        p++;
    return (uint32_t)((uintptr_t)top - (uintptr_t)p);
}

static inline int region_guard_intact(const uint32_t *limit, const uint32_t *guard_end)
{
    /* cppcheck-suppress comparePointers ; one region: the stack's guard */
    for (const uint32_t *p = limit; p < guard_end; p++)
        if (*p != STACK_PAINT)
            return 0;
    return 1;
}

uint32_t stack_size(void) { return region_size(__stack_limit, __stack_top); }

uint32_t stack_high_water(void) { return region_high_water(__stack_limit, __stack_top); }

int stack_guard_intact(void) { return region_guard_intact(__stack_limit, __stack_guard_end); }

#if BOARD_CORES > 1
_Static_assert(BOARD_CORES == 2, "stack.c knows two stacks: .stack (core 0) and .stack1 (core 1)");

uint32_t stack_high_water_core(unsigned core)
{
    return core ? region_high_water(__stack1_limit, __stack1_top) : stack_high_water();
}

int stack_guard_intact_core(unsigned core)
{
    return core ? region_guard_intact(__stack1_limit, __stack1_guard_end) : stack_guard_intact();
}
#endif
