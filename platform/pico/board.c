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
 *    interrupt counts the wraps (every 0.134 s at 125 MHz). Each core has
 *    its own SysTick (in its own PPB) and its own count of wraps, started
 *    when that core starts: a difference of two readings holds only on
 *    one core. A time that starts on one core and may end on the other
 *    (the sink's) is the TIMER's instead: microseconds, one count for
 *    both, from the watchdog's tick at 1 MHz of the crystal. The M0+
 *    has no instruction counter (BOARD_INSTR_COUNTER := 0): run.mjs
 *    counts each core's instructions from outside, between its calls of
 *    port_cycles_read (core 1: around its whole share, core1_start).
 *  - Both cores (BOARD_CORES 2, port.h's multi-core part): core 1 waits
 *    in the boot ROM from reset until core 0 sends it the launch sequence
 *    over the inter-core FIFO (port_start_core1); it gets the vector table
 *    core 0 runs with (VTOR, 0x10000100) and its stack in SRAM4 (link.ld;
 *    core 0's is in SRAM5), starts its own SysTick and runs the entry.
 *    The atomic add takes SIO spinlock 31 (the M0+ has no LDREX/STREX);
 *    waiting and signalling are WFE and DSB + SEV
 *    (platform/arch/cortex-m/multicore.c). Each core divides on its own
 *    SIO divider (sio_div.h); no interrupt handler divides.
 *  - The on-board LED (GP25) blinks as bands are drawn, and stays on
 *    when the run ended well, off when it did not.
 *  - The end: the exit status as the last report line, the UART drained,
 *    then the core sleeps (WFI) with interrupts off. No semihosting: on a
 *    chip with no debugger a BKPT would be a HardFault.
 */
#include "../arch/cortex-m/systick.h"
#include "board.h"
#include "port.h"
#include "rp2040.h"
#include "sink.h"

/* XOSC: its start-up delay in units of 256 crystal cycles: 1 ms at
 * 12 MHz, rounded up (the datasheet's formula) */
#define XOSC_HZ 12000000u
#define XOSC_STARTUP_DELAY ((XOSC_HZ / 1000u + 255u) / 256u)
/* the watchdog's tick, which the TIMER counts: every XOSC_HZ / 1 MHz
 * cycles of clk_ref (the crystal, once clocks_init has switched it) */
#define TICK_CYCLES (XOSC_HZ / 1000000u)
_Static_assert(TICK_CYCLES * 1000000u == XOSC_HZ && TICK_CYCLES <= 0x1ffu, "the tick: a whole count of clk_ref cycles, 9 bits");

/* PLL_SYS: 12 MHz / REFDIV 1 * FBDIV 125 = VCO 1500 MHz (750..1600
 * allowed), / POSTDIV1 6 / POSTDIV2 2 = 125 MHz */
#define PLL_FBDIV 125u
#define PLL_POSTDIV1 6u
#define PLL_POSTDIV2 2u
_Static_assert(XOSC_HZ / 1000u * PLL_FBDIV >= 750000u && XOSC_HZ / 1000u * PLL_FBDIV <= 1600000u,
               "the PLL's VCO must run at 750..1600 MHz");
_Static_assert(XOSC_HZ / 1000u * PLL_FBDIV / (PLL_POSTDIV1 * PLL_POSTDIV2) * 1000u == CLK_SYS_HZ,
               "CLK_SYS_HZ (board.h) is what the PLL makes");

/* pins */
#define PIN_UART_TX 0u
#define PIN_UART_RX 1u
#define PIN_LED 25u

/* UART0 */
#define UART_BAUD 115200u
/* the PL011's divisor, clk_peri / (16 * baud), in 1/64ths, rounded */
#define UART_DIV64(hz) ((8u * (hz) / UART_BAUD + 1u) / 2u)
#define RING_OSC_HZ 6500000u /* nominal: 1.8 to 12 MHz across chips */

/* Polls before a wait gives up: far more than any of these needs (the
 * crystal's start-up, 1 ms, is about 2,000 polls at 6.5 MHz). */
#define WAIT_POLLS 1000000u

#ifndef BOARD_CORES
#define BOARD_CORES 1
#endif
/* The atomic add's lock (port_atomic_add): any of the 32 would do, as
 * the firmware takes no other. */
#define SIO_SPINLOCK_ATOMIC SIO_SPINLOCK(31u)

static volatile uint32_t systick_wraps[BOARD_CORES]; /* each core's own SysTick */
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

#if BOARD_CORES > 1
static inline unsigned this_core(void) { return SIO_CPUID; }
#else
static inline unsigned this_core(void) { return 0; }
#endif

void SysTick_Handler(void) { systick_wraps[this_core()]++; }

void port_init(void)
{
    int clocked = clocks_init();
    /* clk_peri: from clk_sys, whatever clk_sys runs from (the crystal's
     * PLL, or the ring oscillator when the bring-up failed) */
    CLK_PERI_CTRL = 0;
    CLK_PERI_CTRL = CLK_PERI_ENABLE;
    unreset(RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_UART0, "bring-up: IO_BANK0, PADS_BANK0 or UART0 did not leave reset");
    uart_init(clocked ? CLK_SYS_HZ : RING_OSC_HZ);
    GPIO_CTRL(PIN_LED) = FUNC_SIO;
    SIO_GPIO_OUT_CLR = 1u << PIN_LED;
    SIO_GPIO_OE_SET = 1u << PIN_LED;
    if (bringup_failed) {
        report_text(bringup_failed);
        port_exit(5);
    }
    WATCHDOG_TICK = WATCHDOG_TICK_ENABLE | TICK_CYCLES;
    board_unreset(RESET_TIMER, "bring-up: TIMER did not leave reset");
#if BOARD_CORES > 1
    SIO_SPINLOCK_ATOMIC = 1; /* free, even if held across a reset that left SIO alone (a debugger's) */
#endif
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

/* Cycles since the calling core's SysTick started: its wraps, then its
 * count down. A wrap between the two reads shows as a changed wrap
 * count: read again. */
uint64_t board_cycles(void)
{
    const volatile uint32_t *w = &systick_wraps[this_core()];
    uint32_t wraps, count;
    do {
        wraps = *w;
        count = SYST_CVR;
    } while (wraps != *w);
    return ((uint64_t)wraps << 24) + (SYST_TOP - count);
}

/* Microseconds by the TIMER, the same count on both cores (the low
 * word: differences hold for 71 minutes). */
uint32_t board_us(void) { return TIMER_TIMERAWL; }

/* The firmware's marks (render start and end, display output): run.mjs
 * counts each core's instructions between its calls of this very
 * function. no_icf: no other function (port_core_cycles_read) may be
 * folded into it, or its calls would be marks too. */
__attribute__((noinline, no_icf)) uint64_t port_cycles_read(void) { return board_cycles(); }

#if BOARD_CORES > 1
/* ---- two cores -------------------------------------------------------------- */

/* The launch: the ROM on core 1 echoes each word; a wrong echo starts the
 * sequence again. Each echo comes in microseconds; the wait for one is
 * bounded in cycles, and WFE wakes at least at each SysTick wrap. */
#define LAUNCH_ECHO_CYCLES (CLK_SYS_HZ / 2u) /* 0.5 s */
#define LAUNCH_TRIES 8u

extern uint32_t __stack1_top[];
static void (*volatile core1_entry)(void);

unsigned port_core_id(void) { return this_core(); }

uint64_t port_core_cycles_read(void) { return board_cycles(); }

/* Core 1 comes here from the ROM (blx), on __stack1_top, with VTOR set to
 * core 0's vector table; .data and .bss were set up by core 0. */
static void core1_start(void)
{
    SIO_FIFO_ST = 0; /* clears the ROM's sticky read-on-empty (ROE) */
    systick_start_wrapping(); /* core 1's own SysTick */
    __asm__ volatile("cpsie i" : : : "memory");
    (void)port_cycles_read(); /* core 1's marks for run.mjs: start, (its output's pairs,) end */
    core1_entry();
    (void)port_cycles_read();
    /* done: nothing left that could wake it */
    systick_stop();
    __asm__ volatile("cpsid i" : : : "memory");
    for (;;)
        __asm__ volatile("wfi");
}

/* Sends one word of the launch sequence and returns core 1's echo, or
 * stops the run (status 5) when core 1 does not answer. */
static uint32_t launch_word(uint32_t word)
{
    uint64_t deadline = board_cycles() + LAUNCH_ECHO_CYCLES;
    if (word == 0) { /* (the ROM reads a 0 as: start again) */
        while (SIO_FIFO_ST & FIFO_VLD) { /* what core 1 pushed before, such as the 0 it sends after its reset */
            (void)SIO_FIFO_RD;
            if (board_cycles() > deadline) {
                report_text("core 1 launch: the inter-core FIFO from core 1 never empties");
                port_exit(5);
            }
        }
        __asm__ volatile("sev" : : : "memory");
    }
    while (!(SIO_FIFO_ST & FIFO_RDY))
        if (board_cycles() > deadline) {
            report_text("core 1 launch: the inter-core FIFO to core 1 stayed full");
            port_exit(5);
        }
    SIO_FIFO_WR = word;
    __asm__ volatile("sev" : : : "memory");
    while (!(SIO_FIFO_ST & FIFO_VLD)) {
        if (board_cycles() > deadline) {
            report_text("core 1 launch: no echo from core 1's boot ROM");
            port_exit(5);
        }
        port_wait_event();
    }
    return SIO_FIFO_RD;
}

/* The boot ROM's launch sequence (RP2040 datasheet 2.8.2): 0, 0, 1, the
 * vector table (256-byte aligned: core 0's, VTOR), the stack pointer and
 * the entry with its Thumb bit, each echoed by core 1. */
void port_start_core1(void (*entry)(void))
{
    core1_entry = entry;
    const uint32_t seq[] = { 0, 0, 1, SCB_VTOR, (uint32_t)(uintptr_t)__stack1_top, (uint32_t)(uintptr_t)core1_start | 1u };
    /* the entry in memory before core 1 can run */
    __asm__ volatile("dsb" : : : "memory");
    unsigned i = 0, tries = 0;
    while (i < sizeof seq / sizeof seq[0]) {
        if (launch_word(seq[i]) == seq[i]) {
            i++;
        } else if (++tries < LAUNCH_TRIES) {
            i = 0;
        } else {
            report_text("core 1 launch: core 1 echoed a wrong word on every try");
            port_exit(5);
        }
    }
}

/* *p += v under the spinlock: a read claims it (non-zero once claimed),
 * a write frees it. The DMBs keep the update inside the lock, and plain
 * accesses on either side out of it. */
uint32_t port_atomic_add(volatile uint32_t *p, uint32_t v)
{
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    while (SIO_SPINLOCK_ATOMIC == 0)
        ;
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    uint32_t old = *p;
    *p = old + v;
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    SIO_SPINLOCK_ATOMIC = 1;
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    return old;
}
#endif

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
