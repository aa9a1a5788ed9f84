/*
 * sio_div.h - the RP2040's hardware divider (SIO, one per core) as the
 * core's 32-bit division (RT_UDIV32, include/rt_config.h; board.mk names this
 * header): the Cortex-M0+ has no divide instruction.
 *
 * Write the dividend and the divisor, and the quotient is valid 8 cycles
 * later (the CSR's READY bit says when). SIO accesses take one cycle.
 * Each core has its own divider at the same address, and no interrupt
 * handler of this firmware divides (SysTick's only counts), so nothing
 * can come between the writes and the read: no state is saved around it.
 * run.mjs times the divider as the silicon does (READY 8 cycles after the
 * last operand write; a quotient read before then fails the run).
 */
#ifndef SIO_DIV_H
#define SIO_DIV_H

#include <stdint.h>

#define SIO_DIV_UDIVIDEND (*(volatile uint32_t *)0xd0000060u)
#define SIO_DIV_UDIVISOR (*(volatile uint32_t *)0xd0000064u)
#define SIO_DIV_QUOTIENT (*(volatile uint32_t *)0xd0000070u)
#define SIO_DIV_CSR (*(volatile uint32_t *)0xd0000078u)

static inline uint32_t sio_udiv32(uint32_t n, uint32_t d)
{
    SIO_DIV_UDIVIDEND = n;
    SIO_DIV_UDIVISOR = d;
    while ((SIO_DIV_CSR & 1u) == 0) /* READY */
        ;
    return SIO_DIV_QUOTIENT;
}

#endif
