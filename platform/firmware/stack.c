/*
 * stack.c - stack measurement for every port: main() paints the free
 * stack with a pattern first; after the render the deepest word no longer
 * holding it gives the high-water mark, and the guard words at the
 * stack's low end must still hold it (an overflow on a board whose RAM
 * ignores stray writes would otherwise go unnoticed).
 */
#include "port.h"

extern uint32_t __stack_limit[], __stack_top[], __stack_guard_end[];
/* Each start/end pair above bounds one region of the linker script: the
 * loops below compare pointers within it, which cppcheck cannot know. */

#define STACK_PAINT 0xA5A5A5A5u

/* noinline: its frame is below the caller's, and it paints below its own */
__attribute__((noinline)) void stack_paint(void)
{
    volatile uint32_t *p = __stack_limit;
    const volatile uint32_t *own = (const volatile uint32_t *)__builtin_frame_address(0) - 32;
    /* cppcheck-suppress comparePointers ; one region: the stack */
    while (p < own)
        *p++ = STACK_PAINT;
}

uint32_t stack_size(void) { return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)__stack_limit); }

uint32_t stack_high_water(void)
{
    const uint32_t *p = __stack_limit;
    /* cppcheck-suppress comparePointers ; one region: the stack */
    while (p < __stack_top && *p == STACK_PAINT)
        p++;
    return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)p);
}

int stack_guard_intact(void)
{
    /* cppcheck-suppress comparePointers ; one region: the stack's guard */
    for (const uint32_t *p = __stack_limit; p < __stack_guard_end; p++)
        if (*p != STACK_PAINT)
            return 0;
    return 1;
}
