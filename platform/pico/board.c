/*
 * board.c - the Raspberry Pi Pico's (RP2040) side of the port contract
 * (port.h), for the chip: what runs after boot2 (boot2.S) has set up the
 * flash and jumped to the vector table.
 *
 *  - Clocks and resets: the 12 MHz crystal oscillator, PLL_SYS to
 *    125 MHz (VCO 1500 MHz / 6 / 2), clk_ref from the crystal, clk_sys
 *    from the PLL, clk_peri from clk_sys; every block the firmware uses
 *    taken out of reset. At reset clk_sys runs from the ring oscillator
 *    (about 6.5 MHz) and clk_peri is stopped, so nothing leaves the UART
 *    or the SPI before this.
 *  - Every wait has a bound. When one expires, the firmware says which
 *    over the UART (clocked from the ring oscillator then, so the baud
 *    rate is only close), leaves the LED off and stops with status 5.
 *  - Console: UART0 on GP0 (TX) and GP1 (RX), 115200 8N1.
 *  - Cycles: SysTick counts clk_sys cycles down from 2^24 - 1; its
 *    interrupt counts the wraps (every 0.134 s at 125 MHz). The M0+ has
 *    no instruction counter (BOARD_INSTR_COUNTER := 0): run.mjs counts
 *    instructions from outside, between the calls of port_cycles_read.
 *  - The on-board LED (GP25) blinks as bands are drawn, and stays on
 *    when the run ended well, off when it did not.
 *  - The end: the exit status as the last report line, the UART drained,
 *    then the core sleeps (WFI) with interrupts off. No semihosting: on a
 *    chip with no debugger a BKPT would be a HardFault.
 */
#include "../arch/cortex-m/systick.h"
#include "board.h"
#include "port.h"
#include "sink.h"

#define REG(addr) (*(volatile uint32_t *)(addr))
/* RP2040 atomic aliases of a register: +0x2000 sets bits, +0x3000 clears */
#define SET(addr) REG((addr) + 0x2000u)
#define CLR(addr) REG((addr) + 0x3000u)

/* RESETS */
#define RESETS_RESET 0x4000c000u
#define RESETS_DONE REG(0x4000c008u)
#define RESET_IO_BANK0 (1u << 5)
#define RESET_PADS_BANK0 (1u << 8)
#define RESET_PLL_SYS (1u << 12)
#define RESET_UART0 (1u << 22)

/* XOSC: the 1-15 MHz range, and its start-up delay in units of 256
 * crystal cycles: 1 ms at 12 MHz, rounded up (the datasheet's formula) */
#define XOSC_CTRL REG(0x40024000u)
#define XOSC_STATUS REG(0x40024004u)
#define XOSC_STARTUP REG(0x4002400cu)
#define XOSC_CTRL_1_15MHZ 0xaa0u
#define XOSC_CTRL_ENABLE (0xfabu << 12)
#define XOSC_STATUS_STABLE (1u << 31)
#define XOSC_HZ 12000000u
#define XOSC_STARTUP_DELAY ((XOSC_HZ / 1000u + 255u) / 256u)

/* PLL_SYS: 12 MHz / REFDIV 1 * FBDIV 125 = VCO 1500 MHz (750..1600
 * allowed), / POSTDIV1 6 / POSTDIV2 2 = 125 MHz */
#define PLL_SYS_CS REG(0x40028000u)
#define PLL_SYS_PWR 0x40028004u
#define PLL_SYS_FBDIV REG(0x40028008u)
#define PLL_SYS_PRIM REG(0x4002800cu)
#define PLL_CS_LOCK (1u << 31)
#define PLL_PWR_PD (1u << 0)
#define PLL_PWR_POSTDIVPD (1u << 3)
#define PLL_PWR_VCOPD (1u << 5)
#define PLL_FBDIV 125u
#define PLL_POSTDIV1 6u
#define PLL_POSTDIV2 2u
_Static_assert(XOSC_HZ / 1000u * PLL_FBDIV >= 750000u && XOSC_HZ / 1000u * PLL_FBDIV <= 1600000u,
               "the PLL's VCO must run at 750..1600 MHz");
_Static_assert(XOSC_HZ / 1000u * PLL_FBDIV / (PLL_POSTDIV1 * PLL_POSTDIV2) * 1000u == CLK_SYS_HZ,
               "CLK_SYS_HZ (board.h) is what the PLL makes");

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

/* IO_BANK0 and SIO */
#define GPIO_CTRL(n) REG(0x40014004u + 8u * (n))
#define FUNC_UART 2u
#define FUNC_SIO 5u
#define SIO_GPIO_OUT_SET REG(0xd0000014u)
#define SIO_GPIO_OUT_CLR REG(0xd0000018u)
#define SIO_GPIO_OUT_XOR REG(0xd000001cu)
#define SIO_GPIO_OE_SET REG(0xd0000024u)
#define PIN_UART_TX 0u
#define PIN_UART_RX 1u
#define PIN_LED 25u

/* UART0 (a PL011) */
#define UART0_DR REG(0x40034000u)
#define UART0_FR REG(0x40034018u)
#define UART0_IBRD REG(0x40034024u)
#define UART0_FBRD REG(0x40034028u)
#define UART0_LCR_H REG(0x4003402cu)
#define UART0_CR REG(0x40034030u)
#define UART_FR_BUSY (1u << 3)
#define UART_FR_TXFF (1u << 5)
#define UART_BAUD 115200u
/* the PL011's divisor, clk_peri / (16 * baud), in 1/64ths, rounded */
#define UART_DIV64(hz) ((8u * (hz) / UART_BAUD + 1u) / 2u)
#define RING_OSC_HZ 6500000u /* nominal: 1.8 to 12 MHz across chips */

/* Polls before a wait gives up: far more than any of these needs (the
 * crystal's start-up, 1 ms, is about 2,000 polls at 6.5 MHz). */
#define WAIT_POLLS 1000000u

static volatile uint32_t systick_wraps;
static const char *bringup_failed; /* the wait that expired, or 0 */

/* Waits until (*reg & mask) == want, at most WAIT_POLLS reads; on
 * expiry notes `what` (the first such) and returns 0. */
static int wait_for(const volatile uint32_t *reg, uint32_t mask, uint32_t want, const char *what)
{
    for (uint32_t n = 0; n < WAIT_POLLS; n++)
        if ((*reg & mask) == want)
            return 1;
    if (!bringup_failed)
        bringup_failed = what;
    return 0;
}

static int unreset(uint32_t blocks, const char *what)
{
    CLR(RESETS_RESET) = blocks;
    return wait_for(&RESETS_DONE, blocks, blocks, what);
}

/* XOSC, PLL_SYS, then clk_ref, clk_sys and clk_peri. Returns 0 when a
 * wait expired: clk_sys and clk_ref then stay on the ring oscillator. */
static int clocks_init(void)
{
    XOSC_CTRL = XOSC_CTRL_1_15MHZ;
    XOSC_STARTUP = XOSC_STARTUP_DELAY;
    XOSC_CTRL = XOSC_CTRL_1_15MHZ | XOSC_CTRL_ENABLE;
    if (!wait_for(&XOSC_STATUS, XOSC_STATUS_STABLE, XOSC_STATUS_STABLE,
                  "clock bring-up: the 12 MHz crystal oscillator (XOSC) never became stable"))
        return 0;
    /* clk_sys off the auxiliary mux (to clk_ref) before the PLL changes */
    CLK_SYS_CTRL = 0;
    if (!wait_for(&CLK_SYS_SELECTED, 1u, 1u, "clock bring-up: clk_sys did not switch to clk_ref"))
        return 0;
    CLK_REF_CTRL = CLK_REF_SRC_XOSC;
    if (!wait_for(&CLK_REF_SELECTED, 1u << CLK_REF_SRC_XOSC, 1u << CLK_REF_SRC_XOSC,
                  "clock bring-up: clk_ref did not switch to the crystal"))
        return 0;
    if (!unreset(RESET_PLL_SYS, "clock bring-up: PLL_SYS did not leave reset"))
        return 0;
    PLL_SYS_CS = 1u; /* REFDIV 1 */
    PLL_SYS_FBDIV = PLL_FBDIV;
    CLR(PLL_SYS_PWR) = PLL_PWR_PD | PLL_PWR_VCOPD;
    if (!wait_for(&PLL_SYS_CS, PLL_CS_LOCK, PLL_CS_LOCK, "clock bring-up: PLL_SYS never locked"))
        return 0;
    PLL_SYS_PRIM = PLL_POSTDIV1 << 16 | PLL_POSTDIV2 << 12;
    CLR(PLL_SYS_PWR) = PLL_PWR_POSTDIVPD;
    CLK_SYS_DIV = 1u << 8; /* divide by 1 */
    CLK_SYS_CTRL = 0;      /* auxiliary source 0: PLL_SYS (SRC still clk_ref) */
    CLK_SYS_CTRL = CLK_SYS_SRC_AUX;
    if (!wait_for(&CLK_SYS_SELECTED, 1u << CLK_SYS_SRC_AUX, 1u << CLK_SYS_SRC_AUX,
                  "clock bring-up: clk_sys did not switch to PLL_SYS"))
        return 0;
    return 1;
}

static void uart_init(uint32_t clk_peri_hz)
{
    GPIO_CTRL(PIN_UART_TX) = FUNC_UART;
    GPIO_CTRL(PIN_UART_RX) = FUNC_UART;
    uint32_t div64 = UART_DIV64(clk_peri_hz);
    UART0_IBRD = div64 / 64u;
    UART0_FBRD = div64 % 64u;
    UART0_LCR_H = 0x70u; /* 8 data bits, FIFOs on (latches IBRD/FBRD) */
    UART0_CR = 0x301u;   /* UART, transmitter and receiver enabled */
}
_Static_assert(UART_DIV64(125000000u) == 67u * 64u + 52u, "115200 baud from 125 MHz: IBRD 67, FBRD 52");

void SysTick_Handler(void) { systick_wraps++; }

void port_init(void)
{
    int clocked = clocks_init();
    /* clk_peri: from clk_sys, whatever clk_sys runs from (the crystal's
     * PLL, or the ring oscillator when the bring-up failed) */
    CLK_PERI_CTRL = 0;
#ifndef PICO_OMIT_CLK_PERI /* (run.mjs's tests: an image that forgets it) */
    CLK_PERI_CTRL = CLK_PERI_ENABLE;
#endif
    unreset(RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_UART0, "bring-up: IO_BANK0, PADS_BANK0 or UART0 did not leave reset");
    uart_init(clocked ? CLK_SYS_HZ : RING_OSC_HZ);
    GPIO_CTRL(PIN_LED) = FUNC_SIO;
    SIO_GPIO_OUT_CLR = 1u << PIN_LED;
    SIO_GPIO_OE_SET = 1u << PIN_LED;
    if (bringup_failed) {
        report_text(bringup_failed);
        port_exit(5);
    }
    systick_start_wrapping();
}

void board_unreset(uint32_t blocks, const char *what)
{
    if (unreset(blocks, what))
        return;
    report_text(what);
    port_exit(5);
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

/* Cycles since SysTick started: its wraps, then its count down. A wrap
 * between the two reads shows as a changed wrap count: read again. */
uint64_t board_cycles(void)
{
    uint32_t wraps, count;
    do {
        wraps = systick_wraps;
        count = SYST_CVR;
    } while (wraps != systick_wraps);
    return ((uint64_t)wraps << 24) + (SYST_TOP - count);
}

/* The firmware's marks (render start and end, display output): run.mjs
 * counts instructions between the calls of this very function. */
uint64_t port_cycles_read(void) { return board_cycles(); }

void port_heartbeat(void) { SIO_GPIO_OUT_XOR = 1u << PIN_LED; }

/* (out of LTO with the rest of this file, and kept a call: the runner
 * finds it by name and stops at its first instruction) */
__attribute__((noinline)) void board_pass_shown(unsigned pass) { __asm__ volatile("" : : "r"(pass) : "memory"); }

void port_exit(int status)
{
    /* (after the frame: a report line before it would hide the UART
     * stream's frame header) */
    report_value("clk_sys_hz", bringup_failed ? 0 : CLK_SYS_HZ); /* 0: not as set */
    report_value("clk_peri_hz", bringup_failed ? 0 : CLK_SYS_HZ);
    report_value("exit_status", (uint64_t)(uint32_t)status);
    /* the last byte out of the UART before the core sleeps */
    for (uint32_t n = 0; n < WAIT_POLLS && (UART0_FR & UART_FR_BUSY); n++)
        ;
    systick_stop();
    if (status == 0)
        SIO_GPIO_OUT_SET = 1u << PIN_LED;
    else
        SIO_GPIO_OUT_CLR = 1u << PIN_LED;
    __asm__ volatile("cpsid i" : : : "memory");
    for (;;)
        __asm__ volatile("wfi");
}
