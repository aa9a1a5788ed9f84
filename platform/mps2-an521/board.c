/*
 * board.c - the MPS2 AN521's side of the port contract (port.h): the
 * SSE-200's two Cortex-M33, run Secure. The console is CMSDK APB UART0,
 * the instruction counter CMSDK APB timer 0 (both at their Secure
 * aliases; cmsdk.h), and the multi-core part: which core, starting core 1 (its
 * own vector table and stack), through the SSE-200's system control.
 * Waiting, signalling and the atomic add are the architecture's
 * (platform/arch/cortex-m/multicore.c).
 */
#include "../arch/cortex-m/cmsdk.h" /* the MPS2 boards' UART and timer */
#include "../mmio.h"
#include "port.h"

#if defined(__ARM_FP) || defined(__ARM_FEATURE_DSP)
#error "mps2-an521: core 0 has no FPU and no DSP extension; build with -mcpu=cortex-m33+nofp+nodsp (board.mk)"
#endif

#define UART0 0x50200000u
/* Timer 0 counts down at 20 MHz; under qemu -icount shift=0 one guest
 * instruction takes 1 ns, so it decrements exactly once per 50 -- of
 * either core: it runs on the one virtual clock the two share. */
#define TIMER0 0x50000000u
#define INSTRUCTIONS_PER_TICK 50u

/* SSE-200 system control and identity */
#define CPU_IDENTITY REG(0x5001F000u) /* 0 on core 0, 1 on core 1 */
#define INITSVTOR1 REG(0x50021114u)   /* core 1's vector table at its start */
#define CPUWAIT REG(0x50021118u)      /* bit 1 set at reset: core 1 held */
#define CPUWAIT_CPU1 2u

void port_init(void) { cmsdk_uart_init(UART0); }

/* One core at a time (bands.c hands bands to the sink under a lock). */
void port_write(const void *data, size_t len) { cmsdk_uart_write(UART0, data, len); }

void port_icount_start(void) { cmsdk_timer_start(TIMER0); }

/* No state, so either core may read it; 2^32 ticks are 214.7e9
 * instructions (three hours of a 20 MHz core). */
uint64_t port_icount_read(void) { return (uint64_t)cmsdk_timer_ticks(TIMER0) * INSTRUCTIONS_PER_TICK; }

/* ---- two cores ------------------------------------------------------------ */

unsigned port_core_id(void) { return CPU_IDENTITY; }

extern uint32_t __stack1_top[];
void Fault_Handler(void); /* platform/arch/cortex-m/startup.c */
static void core1_reset(void);

/* Core 1's vector table: INITSVTOR1 takes bits [31:7], and 1 KiB covers
 * any table this subsystem could need; sections.ld puts .vectors.* right
 * after reset's table (so at 0x10000400). This firmware uses no
 * interrupts, so the 16 system entries are all. */
__attribute__((section(".vectors.core1"), aligned(1024), used))
static void (*const core1_vectors[16])(void) = {
    (void (*)(void))(uintptr_t)__stack1_top, /* initial SP */
    core1_reset,
    Fault_Handler, /* NMI */
    Fault_Handler, /* HardFault */
    Fault_Handler, /* MemManage */
    Fault_Handler, /* BusFault */
    Fault_Handler, /* UsageFault */
    Fault_Handler, /* SecureFault */
    0, 0, 0,
    Fault_Handler, /* SVCall */
    Fault_Handler, /* DebugMon */
    0,
    Fault_Handler, /* PendSV */
    Fault_Handler, /* SysTick */
};

static void (*volatile core1_entry)(void);

/* Core 1 comes out of reset here with SP = __stack1_top; .data and .bss
 * were set up by core 0 before it let core 1 go. No FPU to enable: the
 * build is soft-float (core 0 has none). */
static void core1_reset(void)
{
    core1_entry();
    for (;;)
        port_wait_event();
}

void port_start_core1(void (*entry)(void))
{
    core1_entry = entry;
    INITSVTOR1 = (uint32_t)(uintptr_t)core1_vectors;
    /* the entry and the vector table's address in place before core 1 runs */
    __asm__ volatile("dsb" : : : "memory");
    CPUWAIT = CPUWAIT & ~CPUWAIT_CPU1;
}
