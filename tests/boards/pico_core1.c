/*
 * pico_core1.c - small images for run.mjs's model of the RP2040's second
 * core (tools/emu/pico/core1.mjs), for tests/boards/board-pico-tests.sh. Built
 * with tests/boards/pico_core1.ld after our boot2, run from flash at the ring
 * oscillator's clock (no PLL: nothing here needs speed).
 *
 * Without a CASE_ define: the checks that must pass. Core 0 reports what
 * it saw as report lines after a 1x1 frame on the UART stream (so the
 * runner takes the stream, not a panel); the test script compares each
 * value with the datasheet's:
 *   stale_vld, stale_word   core 1's stale 0, waiting before the launch
 *   launched                the launch's echoes all came back (1)
 *   roe_at_entry            core 1's FIFO_ST at its entry (ROE, from the
 *                           ROM's unchecked read, and RDY)
 *   cpuid0, cpuid1          SIO CPUID on each core
 *   div0, div1              each core's own quotient, core 1 dividing
 *                           between core 0's write and read
 *   locked_count            both cores' 100 additions each to a counter
 *                           under spinlock 3, at once: 200 (each core
 *                           marks its additions' start and end with
 *                           port_cycles_read, which run.mjs counts from)
 *   sev_woke                core 1 left `while (!flag) wfe` after SEV
 *   wfi_after_sev           core 1 in WFI still asleep after core 0's SEV (0)
 *   wfi_irq_word            ... and woken by its FIFO interrupt, whose
 *                           handler read the word core 0 sent (77)
 *   own_event               core 0's `sev; wfe` did not sleep
 *   lock_first, lock_again, lock_st, lock_core1_held, lock_core1_freed
 *                           spinlock 5: claimed, held, SPINLOCK_ST, core
 *                           1 refused while held and granted once freed
 *   fifo_full_st, fifo_cleared_st, fifo_empty_read, fifo_roe_st,
 *   irq15_roe, irq15_clear  FIFO_ST after 9 writes (WOF, not RDY), after
 *                           a write to FIFO_ST, a read when empty (0,
 *                           ROE), and SIO_IRQ_PROC0 pending with ROE and
 *                           not once cleared
 *   reset_stale             after PSM FRCE_OFF.PROC1: core 1 drained the
 *                           8 words and pushed its stale 0 again
 *   relaunched              a second launch after that reset
 *   tie_core0, tie_core1    both cores woken by one TIMER alarm run the
 *                           same handler; its first load claims spinlock
 *                           7 at the same cycle: core 0 gets it
 * With CASE_x: an image the runner must fail, with its reason:
 *   CASE_ONE_ZERO   the launch sends 0, 1 (one 0)
 *   CASE_NO_DRAIN   the sender does not drain its FIFO first: it takes
 *                   core 1's stale 0 for an echo and falls out of step
 *   CASE_NO_THUMB   the entry without its Thumb bit
 *   CASE_VTOR       a vector table not aligned to 256 bytes
 *   CASE_DIV_EARLY  core 1 reads DIV_QUOTIENT right after the divisor
 *   CASE_BUSY       core 1 still computing when core 0's report ends
 *   CASE_UNGUARDED  core 1 adds to the guarded counter without its lock
 */
#include <stdint.h>

#include "rp2040.h"  /* platform/pico/: the registers the port uses too */
#include "sio_div.h" /* the divider's registers */

#define NVIC_ISER REG(0xe000e100u)
#define NVIC_ICER REG(0xe000e180u)
#define NVIC_ISPR REG(0xe000e200u)

#define PSM_FRCE_OFF 0x40010004u
#define PSM_PROC1 (1u << 16)
#define TIMER_ALARM0 REG(0x40054010u)
#define TIMER_INTR REG(0x40054034u)
#define TIMER_INTE REG(0x40054038u)
#define TIMER_IRQ_0 0u
#define SIO_IRQ_PROC1 16u

#define STACK0 0x20040000u /* top of striped SRAM */
#define STACK1 0x20041000u /* top of SRAM4, core 1's own bank */

/* what the cores share: words in SRAM (no .data here) */
struct shared {
    volatile uint32_t flag, woke, cpuid1, div1, roe1, held1, freed1, woke_wfi, irq_word;
    volatile uint32_t tie[2];
};
#define SH ((struct shared *)0x20000000u)
/* a counter both cores add to under spinlock 3: the data the image
 * guards (__spinlocked_start.. in pico_core1.ld, for run.mjs) */
#define COUNT REG(0x20000100u)
#define COUNT_LOCK 3u
#define COUNT_ADDS 100u

static inline void sev(void) { __asm__ volatile("sev" ::: "memory"); }
static inline void wfe(void) { __asm__ volatile("wfe" ::: "memory"); }
static inline void wfi(void) { __asm__ volatile("wfi" ::: "memory"); }

/* ---- the report: a 1x1 rgb888 stream frame, then 'T' lines ---------------- */
static void put(uint32_t c)
{
    while (UART0_FR & (1u << 5)) /* TXFF */
        ;
    UART0_DR = c;
}
static void put_bytes(const char *p, uint32_t n)
{
    while (n--)
        put((uint8_t)*p++);
}
static void report(const char *key, uint32_t v)
{
    char line[48];
    uint32_t n = 0;
    while (key[n]) {
        line[n] = key[n];
        n++;
    }
    line[n++] = ' ';
    char digits[10];
    uint32_t d = 0;
    do {
        digits[d++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (d)
        line[n++] = digits[--d];
    put('T');
    put(n & 0xffu);
    put(n >> 8);
    put_bytes(line, n);
}
static void uart_up(void)
{
    /* clk_ref (and clk_sys, which runs from it) from the 12 MHz crystal,
     * for the TIMER's tick at 1 MHz: 12 cycles of clk_ref */
    XOSC_CTRL = XOSC_CTRL_1_15MHZ;
    XOSC_STARTUP = 47u; /* 1 ms */
    XOSC_CTRL = XOSC_CTRL_1_15MHZ | XOSC_CTRL_ENABLE;
    while (!(XOSC_STATUS & XOSC_STATUS_STABLE))
        ;
    CLK_REF_CTRL = CLK_REF_SRC_XOSC;
    while (!(CLK_REF_SELECTED & (1u << CLK_REF_SRC_XOSC)))
        ;
    WATCHDOG_TICK = WATCHDOG_TICK_ENABLE | 12u;
    CLK_PERI_CTRL = CLK_PERI_ENABLE; /* from clk_sys (the crystal) */
    CLR(RESETS_RESET) = RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_UART0 | RESET_TIMER;
    while ((RESETS_DONE & (RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_UART0 | RESET_TIMER)) !=
           (RESET_IO_BANK0 | RESET_PADS_BANK0 | RESET_UART0 | RESET_TIMER))
        ;
    GPIO_CTRL(0) = 2u; /* UART0 TX */
    UART0_IBRD = 6u; /* 115200 from 12 MHz */
    UART0_FBRD = 33u;
    UART0_LCR_H = 0x70u;
    UART0_CR = 0x301u;
    /* the frame: header, one band of one black pixel, its end */
    static const char frame[] = {'R', 'T', 'F', '1', 0, 1, 0, 1, 0,
                                 'B', 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 0,
                                 'E', 1, 0, 3, 0};
    put_bytes(frame, sizeof frame);
}
static void __attribute__((noreturn)) finish(uint32_t status)
{
    report("exit_status", status);
    while (UART0_FR & (1u << 3)) /* BUSY */
        ;
    __asm__ volatile("cpsid i" ::: "memory");
    for (;;)
        wfi();
}

/* ---- the launch, as the datasheet's sender does it ------------------------ */
static void drain(void)
{
    while (SIO_FIFO_ST & FIFO_VLD)
        (void)SIO_FIFO_RD;
}
static void push(uint32_t v)
{
    while (!(SIO_FIFO_ST & FIFO_RDY))
        ;
    SIO_FIFO_WR = v;
    sev();
}
static uint32_t pop(void)
{
    while (!(SIO_FIFO_ST & FIFO_VLD))
        wfe();
    return SIO_FIFO_RD;
}
/* 1 when every word came back as sent */
static int launch(const uint32_t *seq, uint32_t n, int drains)
{
    for (uint32_t i = 0; i < n; i++) {
        if (seq[i] == 0 && drains) {
            drain();
            sev();
        }
        push(seq[i]);
        if (pop() != seq[i])
            return 0;
    }
    return 1;
}

extern const uint32_t vectors[];
static void __attribute__((unused)) core1_main(void);
static void __attribute__((unused)) core1_busy(void);
static void __attribute__((unused)) core1_div_early(void);

static void __attribute__((unused)) core1_reset(void)
{
    SET(PSM_FRCE_OFF) = PSM_PROC1;
    while (!(REG(PSM_FRCE_OFF) & PSM_PROC1))
        ;
    CLR(PSM_FRCE_OFF) = PSM_PROC1;
}

/* ---- core 1 ------------------------------------------------------------- */
/* the runner's mark (run.mjs watches this function's address on each
 * core): both cores bracket their additions with it */
__attribute__((noinline, used)) uint32_t port_cycles_read(void) { return SIO_CPUID; }

static void add_counts(void)
{
    (void)port_cycles_read();
    for (uint32_t i = 0; i < COUNT_ADDS; i++) {
        while (!SIO_SPINLOCK(COUNT_LOCK))
            ;
        COUNT = COUNT + 1u;
        SIO_SPINLOCK(COUNT_LOCK) = 0;
    }
    (void)port_cycles_read();
}

static void __attribute__((unused)) core1_unguarded(void)
{
    COUNT = COUNT + 1u;
}

static void core1_main(void)
{
    SH->roe1 = SIO_FIFO_ST;
    SIO_FIFO_ST = 0;
    SH->cpuid1 = SIO_CPUID;
    /* wait for core 0's divider operands, divide on our own */
    while (!SH->flag)
        wfe();
    SIO_DIV_UDIVIDEND = 1000000u;
    SIO_DIV_UDIVISOR = 7u;
    while (!(SIO_DIV_CSR & 1u))
        ;
    SH->div1 = SIO_DIV_QUOTIENT;
    add_counts();
    push(1);
    /* woken by core 0's SEV */
    while (SH->flag != 2)
        wfe();
    SH->woke = 1;
    /* spinlock 5: held by core 0, then freed */
    SH->held1 = SIO_SPINLOCK(5);
    push(2);
    while (SH->flag != 3)
        wfe();
    SH->freed1 = SIO_SPINLOCK(5);
    SIO_SPINLOCK(5) = 0;
    /* WFI: core 0's SEV leaves it asleep, a FIFO word (SIO_IRQ_PROC1) wakes it */
    NVIC_ISER = 1u << SIO_IRQ_PROC1;
    push(3);
    wfi();
    SH->woke_wfi = 1;
    NVIC_ICER = 1u << SIO_IRQ_PROC1;
    /* returns: the ROM parks core 1 in WFI */
}

/* core 1's FIFO interrupt: the word, and the flags cleared */
void sio_irq_proc1(void)
{
    while (SIO_FIFO_ST & FIFO_VLD)
        SH->irq_word = SIO_FIFO_RD;
    SIO_FIFO_ST = 0;
}

static void __attribute__((unused)) core1_tie(void)
{
    TIMER_INTE = 1u;
    NVIC_ISER = 1u << TIMER_IRQ_0;
    push(4);
    for (;;)
        wfi();
}

/* both cores: the same handler; its first load claims spinlock 7 */
void timer_irq(void)
{
    uint32_t got = SIO_SPINLOCK(7);
    SH->tie[SIO_CPUID] = got;
    TIMER_INTR = 1u;
    NVIC_ICER = 1u << TIMER_IRQ_0;
}

static void __attribute__((unused)) core1_busy(void)
{
    for (volatile uint32_t n = 0;; n++)
        ;
}

static void __attribute__((unused)) core1_div_early(void)
{
    SIO_DIV_UDIVIDEND = 100u;
    SIO_DIV_UDIVISOR = 7u;
    SH->div1 = SIO_DIV_QUOTIENT;
}

/* ---- core 0 ------------------------------------------------------------- */
void reset(void)
{
    uart_up();
    uint32_t vt = (uint32_t)vectors;
#if defined(CASE_ONE_ZERO)
    const uint32_t bad[] = {0, 1, vt, STACK1, (uint32_t)core1_main};
    finish(launch(bad, 5, 1) ? 0 : 3);
#elif defined(CASE_NO_DRAIN)
    const uint32_t seq[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_main};
    for (int tries = 0; tries < 4 && !launch(seq, 6, 0);)
        tries++;
    finish(3);
#elif defined(CASE_NO_THUMB)
    const uint32_t seq[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_main & ~1u};
    finish(launch(seq, 6, 1) ? 0 : 3);
#elif defined(CASE_VTOR)
    const uint32_t seq[] = {0, 0, 1, vt + 4u, STACK1, (uint32_t)core1_main};
    finish(launch(seq, 6, 1) ? 0 : 3);
#elif defined(CASE_DIV_EARLY)
    const uint32_t seq[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_div_early};
    launch(seq, 6, 1);
    for (int n = 0; n < 1000; n++)
        __asm__ volatile("nop");
    finish(0);
#elif defined(CASE_UNGUARDED)
    const uint32_t seq[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_unguarded};
    launch(seq, 6, 1);
    finish(0);
#elif defined(CASE_BUSY)
    const uint32_t seq[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_busy};
    launch(seq, 6, 1);
    finish(0);
#else
    /* core 1's stale 0, there before any launch */
    report("stale_vld", SIO_FIFO_ST & FIFO_VLD);
    report("stale_word", SIO_FIFO_RD);
    SH->flag = 0;
    COUNT = 0; /* (core 1 not launched yet: no lock needed) */
    const uint32_t seq[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_main};
    report("launched", (uint32_t)launch(seq, 6, 1));
    report("cpuid0", SIO_CPUID);
    /* our division in flight while core 1 does its own */
    SIO_DIV_UDIVIDEND = 1000u;
    SIO_DIV_UDIVISOR = 3u;
    SH->flag = 1;
    sev();
    add_counts(); /* while core 1 adds too */
    uint32_t a = pop();
    report("locked_count", COUNT);
    while (!(SIO_DIV_CSR & 1u))
        ;
    report("div0", SIO_DIV_QUOTIENT);
    report("div1", SH->div1);
    report("core1_ack", a);
    /* spinlock 5, ours while core 1 tries it once */
    uint32_t first = SIO_SPINLOCK(5), again = SIO_SPINLOCK(5), st = SIO_SPINLOCK_ST;
    /* SEV wakes core 1's WFE */
    SH->flag = 2;
    sev();
    a = pop();
    report("sev_woke", SH->woke);
    /* our own event: sev, then wfe does not sleep */
    sev();
    wfe();
    report("own_event", 1);
    report("lock_first", first);
    report("lock_again", again);
    report("lock_st", st);
    SIO_SPINLOCK(5) = 0; /* freed, then core 1 may take it */
    SH->woke_wfi = 0;
    SH->flag = 3;
    sev();
    a = pop();
    /* core 1 goes to WFI: an event does not wake it, its FIFO interrupt does */
    sev();
    for (volatile int n = 0; n < 100; n++)
        ;
    report("wfi_after_sev", SH->woke_wfi);
    SIO_FIFO_WR = 77u;
    while (!SH->woke_wfi)
        ;
    report("wfi_irq_word", SH->irq_word);
    report("lock_core1_held", SH->held1);
    report("lock_core1_freed", SH->freed1);
    report("cpuid1", SH->cpuid1);
    report("roe_at_entry", SH->roe1);
    /* core 1 has returned (parked in the ROM's WFI): the FIFO to it fills */
    for (int i = 0; i < 9; i++)
        SIO_FIFO_WR = 100u + (uint32_t)i;
    report("fifo_full_st", SIO_FIFO_ST);
    SIO_FIFO_ST = 0;
    report("fifo_cleared_st", SIO_FIFO_ST);
    report("fifo_empty_read", SIO_FIFO_RD);
    report("fifo_roe_st", SIO_FIFO_ST);
    report("irq15_roe", (NVIC_ISPR >> 15) & 1u);
    SIO_FIFO_ST = 0;
    report("irq15_clear", (NVIC_ISPR >> 15) & 1u);
    /* core 1 reset: it drains the 8 words, pushes its stale 0 */
    core1_reset();
    a = pop();
    report("reset_stale", a);
    report("reset_more", SIO_FIFO_ST & FIFO_VLD);
    /* launched again, to the tie */
    const uint32_t seq2[] = {0, 0, 1, vt, STACK1, (uint32_t)core1_tie};
    report("relaunched", (uint32_t)launch(seq2, 6, 1));
    a = pop(); /* core 1 waits in WFI, its alarm interrupt enabled */
    TIMER_INTE = 1u;
    NVIC_ISER = 1u << TIMER_IRQ_0;
    TIMER_ALARM0 = TIMER_TIMERAWL + 100u;
    SH->tie[0] = SH->tie[1] = 99u;
    while (SH->tie[0] == 99u)
        wfi();
    while (SH->tie[1] == 99u)
        ;
    report("tie_core0", SH->tie[0]);
    report("tie_core1", SH->tie[1]);
    finish(0);
#endif
}

/* the vector table: shared by both cores (core 1 is sent its address) */
__attribute__((section(".vectors"), used, aligned(256))) const uint32_t vectors[] = {
    [0] = STACK0,
    [1] = (uint32_t)reset,
    [16 + TIMER_IRQ_0] = (uint32_t)timer_irq,
    [16 + SIO_IRQ_PROC1] = (uint32_t)sio_irq_proc1,
    [47] = 0,
};
