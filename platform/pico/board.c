/*
 * board.c - the Raspberry Pi Pico's (RP2040) side of the port contract
 * (port.h), as run under rp2040js by run.mjs: the console is UART0, the
 * instruction and cycle counters are the runner's.
 *
 * The RP2040's Cortex-M0+ has no instruction counter (no DWT), so the
 * counts come from a block run.mjs maps at 0x40068000, an APB slot the
 * chip leaves empty: the emulator's instruction and cycle totals, both
 * exact by its timing model (each read costs 3 cycles, as an APB load).
 * On a real Pico nothing answers there: a build for the silicon would
 * count cycles with SysTick (the processor clock, 24 bits, wrapping every
 * 0.13 s at 125 MHz) and could count no instructions.
 */
#include "port.h"

#define REG(addr) (*(volatile uint32_t *)(addr))

/* RESETS: writing a mask to the clear alias (+0x3000) of RESET takes
 * those blocks out of reset; RESET_DONE says when they are. */
#define RESETS_RESET_CLR REG(0x4000f000u)
#define RESETS_DONE REG(0x4000c008u)
#define RESET_IO_BANK0 (1u << 5)
#define RESET_PADS_BANK0 (1u << 8)
#define RESET_UART0 (1u << 22)

/* IO_BANK0: GPIO0 (TX) and GPIO1 (RX) to UART0 (function 2) */
#define GPIO_CTRL(n) REG(0x40014004u + 8u * (n))

/* UART0 (PL011) */
#define UART0_DR REG(0x40034000u)
#define UART0_FR REG(0x40034018u)
#define UART0_IBRD REG(0x40034024u)
#define UART0_FBRD REG(0x40034028u)
#define UART0_LCR_H REG(0x4003402cu)
#define UART0_CR REG(0x40034030u)
#define UART_FR_TXFF (1u << 5)

/* run.mjs's counter block: reading +0 latches both 64-bit totals */
#define COUNT_INSTR_LO REG(0x40068000u)
#define COUNT_INSTR_HI REG(0x40068004u)
#define COUNT_CYCLES_LO REG(0x40068008u)
#define COUNT_CYCLES_HI REG(0x4006800cu)

void port_init(void)
{
    RESETS_RESET_CLR = RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_UART0;
    while ((RESETS_DONE & RESET_UART0) == 0)
        ;
    GPIO_CTRL(0) = 2;
    GPIO_CTRL(1) = 2;
    /* 115200 baud from the 125 MHz peripheral clock: 125e6 / (16 * 115200) = 67.82 */
    UART0_IBRD = 67;
    UART0_FBRD = 52;
    UART0_LCR_H = 0x70; /* 8 data bits, FIFOs on */
    UART0_CR = 0x301;   /* UART, transmitter and receiver enabled */
}

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (UART0_FR & UART_FR_TXFF)
            ;
        UART0_DR = p[i];
    }
}

void port_icount_start(void) {}

uint64_t port_icount_read(void)
{
    uint32_t lo = COUNT_INSTR_LO;
    return (uint64_t)COUNT_INSTR_HI << 32 | lo;
}

uint64_t port_cycles_read(void)
{
    (void)COUNT_INSTR_LO; /* latch */
    uint32_t lo = COUNT_CYCLES_LO;
    return (uint64_t)COUNT_CYCLES_HI << 32 | lo;
}
