/* icount.c - instruction counting with CMSDK APB timer 0 (25 MHz).
 * Under qemu -icount shift=0 one guest instruction takes 1 ns, so the
 * timer decrements exactly once per 40 instructions. */
#include "board.h"

#define TIMER0_BASE 0x40000000u
#define TIMER_CTRL (*(volatile uint32_t *)(TIMER0_BASE + 0x0))
#define TIMER_VALUE (*(volatile uint32_t *)(TIMER0_BASE + 0x4))
#define TIMER_RELOAD (*(volatile uint32_t *)(TIMER0_BASE + 0x8))

#define INSTRUCTIONS_PER_TICK 40u

static uint32_t last_value;
static uint64_t ticks;

void icount_start(void)
{
    TIMER_CTRL = 0;
    TIMER_RELOAD = 0xFFFFFFFFu;
    TIMER_VALUE = 0xFFFFFFFFu;
    TIMER_CTRL = 1; /* enable */
    last_value = 0xFFFFFFFFu;
    ticks = 0;
}

uint64_t icount_read(void)
{
    uint32_t v = TIMER_VALUE;
    ticks += (uint32_t)(last_value - v); /* counts down; wraps modulo 2^32 */
    last_value = v;
    return ticks * INSTRUCTIONS_PER_TICK;
}
