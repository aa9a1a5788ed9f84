/*
 * board.c - the MPS2 AN385's side of the port contract (port.h): the
 * console is CMSDK APB UART0, the instruction counter CMSDK APB timer 0.
 * The MPS2 AN386 (Cortex-M4F) has the same memory map and peripherals
 * and uses this file too.
 */
#include "port.h"

#define REG(addr) (*(volatile uint32_t *)(addr))

#define UART0_DATA REG(0x40004000u)
#define UART0_STATE REG(0x40004004u)   /* bit 0: TX full */
#define UART0_CTRL REG(0x40004008u)    /* bit 0: TX enable */
#define UART0_BAUDDIV REG(0x40004010u) /* must be >= 16 before enabling */

/* Timer 0 counts down at 25 MHz; under qemu -icount shift=0 one guest
 * instruction takes 1 ns, so it decrements exactly once per 40. */
#define TIMER0_CTRL REG(0x40000000u)
#define TIMER0_VALUE REG(0x40000004u)
#define TIMER0_RELOAD REG(0x40000008u)
#define INSTRUCTIONS_PER_TICK 40u

void port_init(void)
{
    UART0_BAUDDIV = 16; /* the minimum the model accepts; QEMU ignores the rate */
    UART0_CTRL = 1;
}

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (UART0_STATE & 1u)
            ;
        UART0_DATA = p[i];
    }
}

static uint32_t last_value;
static uint64_t ticks;

void port_icount_start(void)
{
    TIMER0_CTRL = 0;
    TIMER0_RELOAD = 0xFFFFFFFFu;
    TIMER0_VALUE = 0xFFFFFFFFu;
    TIMER0_CTRL = 1; /* enable */
    last_value = 0xFFFFFFFFu;
    ticks = 0;
}

uint64_t port_icount_read(void)
{
    uint32_t v = TIMER0_VALUE;
    ticks += (uint32_t)(last_value - v); /* counts down; wraps modulo 2^32 */
    last_value = v;
    return ticks * INSTRUCTIONS_PER_TICK;
}
