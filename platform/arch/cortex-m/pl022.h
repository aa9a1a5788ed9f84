/*
 * pl022.h - Arm's PrimeType PL022 synchronous serial port, the SPI
 * controller of the LM3S6965 (SSI0 at 0x40008000) and of the RP2040
 * (SPI0 at 0x4003c000, SPI1 at 0x40040000): each board passes its base.
 */
#ifndef PL022_H
#define PL022_H

#include <stdint.h>

#include "../../mmio.h"

#define PL022_REG(base, off) REG((base) + (off))
#define PL022_CR0(base) PL022_REG(base, 0x00)  /* SCR 15..8, SPH 7, SPO 6, frame format, data size - 1 */
#define PL022_CR1(base) PL022_REG(base, 0x04)  /* bit 1: enable (master when bit 2 is 0) */
#define PL022_DR(base) PL022_REG(base, 0x08)
#define PL022_SR(base) PL022_REG(base, 0x0C)
#define PL022_CPSR(base) PL022_REG(base, 0x10) /* even prescaler, 2..254 */
#define PL022_ICR(base) PL022_REG(base, 0x20)  /* bit 0: clears receive overrun */
#define PL022_DMACR(base) PL022_REG(base, 0x24) /* bit 1: transmit DMA */
#define PL022_SR_TNF (1u << 1) /* transmit FIFO not full */
#define PL022_SR_RNE (1u << 2) /* receive FIFO not empty */
#define PL022_SR_BSY (1u << 4)

/* Waits until the last frame is out, then empties the receive FIFO
 * (what came back: a full one stalls some transmitters): the bus is
 * idle, so a data/command line may change. */
static inline void pl022_idle(uintptr_t base)
{
    while (PL022_SR(base) & PL022_SR_BSY)
        ;
    while (PL022_SR(base) & PL022_SR_RNE)
        (void)PL022_DR(base);
}

/* One 8-bit frame out; returns with the bus idle. */
static inline void pl022_send(uintptr_t base, uint8_t byte)
{
    while (!(PL022_SR(base) & PL022_SR_TNF))
        ;
    PL022_DR(base) = byte;
    pl022_idle(base);
}

#endif
