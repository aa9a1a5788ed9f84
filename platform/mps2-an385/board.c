/*
 * board.c - the MPS2 AN385's side of the port contract (port.h): the
 * console is CMSDK APB UART0, the instruction counter CMSDK APB timer 0
 * (cmsdk.h). The MPS2 AN386 (Cortex-M4F) has the same memory map and
 * peripherals and uses this file too.
 */
#include "../arch/cortex-m/cmsdk.h" /* the MPS2 boards' UART and timer */
#include "port.h"

#define UART0 0x40004000u
/* Timer 0 counts down at 25 MHz; under qemu -icount shift=0 one guest
 * instruction takes 1 ns, so it decrements exactly once per 40. */
#define TIMER0 0x40000000u
#define INSTRUCTIONS_PER_TICK 40u

void port_init(void) { cmsdk_uart_init(UART0); }

void port_write(const void *data, size_t len) { cmsdk_uart_write(UART0, data, len); }

void port_icount_start(void) { cmsdk_timer_start(TIMER0); }

/* 2^32 ticks: 171.8e9 instructions, two hours of a 25 MHz core */
uint64_t port_icount_read(void) { return (uint64_t)cmsdk_timer_ticks(TIMER0) * INSTRUCTIONS_PER_TICK; }
