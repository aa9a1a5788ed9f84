/*
 * board.c - the HiFive1's (QEMU sifive_e) side of the port contract
 * (port.h): the console is UART0, the instruction counter the minstret
 * CSR.
 */
#include "../mmio.h"
#include "port.h"

#define UART0_TXDATA REG(0x10013000u) /* read: bit 31 = FIFO full; write: a byte */
#define UART0_TXCTRL REG(0x10013008u) /* bit 0: transmit enable */
#define UART0_TXFULL 0x80000000u

void port_init(void)
{
    /* The baud divisor (div, +0x18) is left as reset left it: it depends
     * on a bus clock this firmware does not set, and QEMU ignores it. */
    UART0_TXCTRL = 1u;
}

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (UART0_TXDATA & UART0_TXFULL)
            ;
        UART0_TXDATA = p[i];
    }
}

/* minstret counts retired instructions, exactly under qemu -icount
 * shift=0 (mcycle does too there: one instruction per cycle). */
static uint32_t minstret_lo(void)
{
    uint32_t v;
    __asm__ volatile("csrr %0, minstret" : "=r"(v));
    return v;
}

static uint32_t minstret_hi(void)
{
    uint32_t v;
    __asm__ volatile("csrr %0, minstreth" : "=r"(v));
    return v;
}

/* A 64-bit read on RV32: high, low, high again until the high word holds
 * still (the low word did not wrap in between). */
static uint64_t read_minstret(void)
{
    for (;;) {
        uint32_t hi = minstret_hi();
        uint32_t lo = minstret_lo();
        if (minstret_hi() == hi)
            return (uint64_t)hi << 32 | lo;
    }
}

static uint64_t icount_base;

void port_icount_start(void) { icount_base = read_minstret(); }

uint64_t port_icount_read(void) { return read_minstret() - icount_base; }
