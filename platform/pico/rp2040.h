/*
 * rp2040.h - the RP2040's registers the Pico's port uses (board.c,
 * st7789.c) and the runner's test images use (tests/boards/pico_core1.c):
 * addresses and bit fields from the datasheet, one definition each. What
 * the board chooses (clocks, pins, baud rate) stays in its files; the
 * divider's registers are sio_div.h's.
 */
#ifndef PICO_RP2040_H
#define PICO_RP2040_H

#include "../mmio.h"

/* Atomic aliases of a peripheral register: +0x2000 sets bits, +0x3000
 * clears them (SIO has none) */
#define SET(addr) REG((addr) + 0x2000u)
#define CLR(addr) REG((addr) + 0x3000u)

/* RESETS: a block's bit set in RESETS_RESET holds it in reset; its bit
 * in RESETS_DONE says it has left */
#define RESETS_RESET 0x4000c000u
#define RESETS_DONE REG(0x4000c008u)
#define RESET_DMA (1u << 2)
#define RESET_IO_BANK0 (1u << 5)
#define RESET_PADS_BANK0 (1u << 8)
#define RESET_PLL_SYS (1u << 12)
#define RESET_SPI0 (1u << 16)
#define RESET_TIMER (1u << 21)
#define RESET_UART0 (1u << 22)

/* XOSC: the 1-15 MHz range; STARTUP counts in units of 256 crystal cycles */
#define XOSC_CTRL REG(0x40024000u)
#define XOSC_STATUS REG(0x40024004u)
#define XOSC_STARTUP REG(0x4002400cu)
#define XOSC_CTRL_1_15MHZ 0xaa0u
#define XOSC_CTRL_ENABLE (0xfabu << 12)
#define XOSC_STATUS_STABLE (1u << 31)

/* PLL_SYS */
#define PLL_SYS_CS REG(0x40028000u)
#define PLL_SYS_PWR 0x40028004u
#define PLL_SYS_FBDIV REG(0x40028008u)
#define PLL_SYS_PRIM REG(0x4002800cu)
#define PLL_CS_LOCK (1u << 31)
#define PLL_PWR_PD (1u << 0)
#define PLL_PWR_POSTDIVPD (1u << 3)
#define PLL_PWR_VCOPD (1u << 5)

/* CLOCKS: clk_ref's source 2 is the crystal; clk_sys's source 1 is its
 * auxiliary mux, whose source 0 is PLL_SYS; clk_peri's auxiliary source 0
 * is clk_sys. *_SELECTED has one bit per source, set once the glitchless
 * mux has switched. */
#define CLK_REF_CTRL REG(0x40008030u)
#define CLK_REF_SELECTED REG(0x40008038u)
#define CLK_SYS_CTRL REG(0x4000803cu)
#define CLK_SYS_DIV REG(0x40008040u)
#define CLK_SYS_SELECTED REG(0x40008044u)
#define CLK_PERI_CTRL REG(0x40008048u)
#define CLK_REF_SRC_XOSC 2u
#define CLK_SYS_SRC_AUX 1u
#define CLK_PERI_ENABLE (1u << 11)

/* WATCHDOG's tick generator: a tick every CYCLES clk_ref cycles, the
 * TIMER's count (the block is outside RESETS) */
#define WATCHDOG_TICK REG(0x4005802cu)
#define WATCHDOG_TICK_ENABLE (1u << 9)

/* TIMER: a 64-bit count of the watchdog's ticks, one block for both
 * cores; TIMERAWL is its low word, read without the TIMELR/TIMEHR latch
 * (which the two cores would share) */
#define TIMER_TIMERAWL REG(0x40054028u)

/* IO_BANK0: each pin's function */
#define GPIO_CTRL(n) REG(0x40014004u + 8u * (n))
#define FUNC_SPI 1u
#define FUNC_UART 2u
#define FUNC_SIO 5u

/* UART0 (a PL011) */
#define UART0_DR REG(0x40034000u)
#define UART0_FR REG(0x40034018u)
#define UART0_IBRD REG(0x40034024u)
#define UART0_FBRD REG(0x40034028u)
#define UART0_LCR_H REG(0x4003402cu)
#define UART0_CR REG(0x40034030u)
#define UART_FR_BUSY (1u << 3)
#define UART_FR_TXFF (1u << 5)

/* SPI0 (a PL022: platform/arch/cortex-m/pl022.h) */
#define SPI0 0x4003c000u

/* DMA channel 0 */
#define DMA_READ_ADDR REG(0x50000000u)
#define DMA_WRITE_ADDR REG(0x50000004u)
#define DMA_TRANS_COUNT REG(0x50000008u)
#define DMA_CTRL_TRIG REG(0x5000000cu)
#define DMA_EN (1u << 0)
#define DMA_INCR_READ (1u << 4)
#define DMA_CHAIN_TO_SELF (0u << 11) /* chaining to itself: none */
#define DMA_TREQ_SPI0_TX (16u << 15)
#define DMA_BUSY (1u << 24)

/* SIO: each core sees its own CPUID and FIFOs at the same addresses */
#define SIO_CPUID REG(0xd0000000u) /* 0 on core 0, 1 on core 1 */
#define SIO_GPIO_OUT_SET REG(0xd0000014u)
#define SIO_GPIO_OUT_CLR REG(0xd0000018u)
#define SIO_GPIO_OUT_XOR REG(0xd000001cu)
#define SIO_GPIO_OE_SET REG(0xd0000024u)
#define SIO_FIFO_ST REG(0xd0000050u)
#define SIO_FIFO_WR REG(0xd0000054u)
#define SIO_FIFO_RD REG(0xd0000058u)
#define FIFO_VLD (1u << 0) /* this core's receive FIFO has a word */
#define FIFO_RDY (1u << 1) /* this core's send FIFO has room */
#define SIO_SPINLOCK_ST REG(0xd000005cu)
#define SIO_SPINLOCK(n) REG(0xd0000100u + 4u * (n))

/* The Cortex-M0+'s vector table offset (each core has its own) */
#define SCB_VTOR REG(0xe000ed08u)

#endif
