/*
 * board.c - the micro:bit's (nRF51822) side of the port contract
 * (port.h): the console is UART0, the instruction counter TIMER0.
 */
#include "../mmio.h"
#include "port.h"

/* UART0: only ENABLE = 4 and STARTTX matter to QEMU's model (no pins,
 * no baud rate); without STARTTX, TXDRDY never rises. */
#define UART0_STARTTX REG(0x40002008u)
#define UART0_TXDRDY REG(0x4000211Cu)
#define UART0_ENABLE REG(0x40002500u)
#define UART0_TXD REG(0x4000251Cu)

/* TIMER0 as a free-running 32-bit counter at 16 MHz: under qemu -icount
 * shift=0 (1 ns per instruction) one tick is exactly 62.5 instructions.
 * The counter is read by capturing it into CC[0]. */
#define TIMER0_START REG(0x40008000u)
#define TIMER0_CLEAR REG(0x4000800Cu)
#define TIMER0_CAPTURE0 REG(0x40008040u)
#define TIMER0_MODE REG(0x40008504u)
#define TIMER0_BITMODE REG(0x40008508u)
#define TIMER0_PRESCALER REG(0x40008510u)
#define TIMER0_CC0 REG(0x40008540u)

void port_init(void)
{
    UART0_ENABLE = 4;
    UART0_STARTTX = 1;
}

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        UART0_TXDRDY = 0;
        UART0_TXD = p[i];
        while (UART0_TXDRDY == 0)
            ;
    }
}

static uint32_t last_value;
static uint64_t ticks;

void port_icount_start(void)
{
    TIMER0_MODE = 0;    /* timer */
    TIMER0_BITMODE = 3; /* 32 bits */
    TIMER0_PRESCALER = 0;
    TIMER0_CLEAR = 1;
    TIMER0_START = 1;
    last_value = 0;
    ticks = 0;
}

uint64_t port_icount_read(void)
{
    TIMER0_CAPTURE0 = 1;
    uint32_t v = TIMER0_CC0;
    ticks += (uint32_t)(v - last_value); /* counts up; wraps modulo 2^32 */
    last_value = v;
    return ticks * 125 / 2; /* 62.5 instructions a tick */
}
