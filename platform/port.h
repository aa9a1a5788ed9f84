/*
 * port.h - the port contract: what a board folder (platform/<board>/)
 * gives the board-independent firmware in app/firmware/.
 *
 * A port provides, in its own files:
 *   - start-up: a reset entry that copies .data, zeroes .bss, enables
 *     what C needs (the FPU on a hard-float build), calls main() and
 *     passes its result to port_exit() (platform/arch/<arch>/ has one
 *     per architecture, so a board usually writes none);
 *   - port_init(), port_write(): console bytes out, binary-safe;
 *   - port_icount_start(), port_icount_read(): an instruction counter
 *     (unless the chip has none: BOARD_INSTR_COUNTER below);
 *   - port_exit(): end the run with a status (semihosting under QEMU,
 *     in platform/arch/<arch>/ as well; a board meant for silicon
 *     without a debugger brings its own and leaves the arch's out with
 *     BOARD_ARCH_SKIP in its board.mk);
 *   - a linker script that defines MEMORY, says where code, the scene's
 *     tables and the stack go (the region aliases CODE, SCENE and STACK)
 *     and includes
 *     app/firmware/sections.ld (which defines the symbols below);
 *   - board.mk: CPU flags, QEMU command, clock, backends (docs/boards.md,
 *     "Adding a board").
 * Only app/firmware/ and platform/ include this header; the core (src/)
 * never does.
 */
#ifndef PORT_H
#define PORT_H

#include <stddef.h>
#include <stdint.h>

/* Console ready for port_write (and whatever else the board must set up
 * before the firmware runs). */
void port_init(void);
/* len bytes to the console, blocking; every byte value passes unchanged. */
void port_write(const void *data, size_t len);

/* Guest instructions since port_icount_start(), exact under QEMU's
 * -icount shift=0 (each port says how it counts). A chip with no
 * instruction counter (the RP2040's Cortex-M0+) sets
 * BOARD_INSTR_COUNTER := 0 in its board.mk: it then provides neither,
 * its report gives no instruction counts, and the board's runner counts
 * them from outside the image (tools/emu/pico/run.mjs). */
#ifndef BOARD_INSTR_COUNTER /* firmware.mk passes the board's */
#define BOARD_INSTR_COUNTER 1
#endif
#if BOARD_INSTR_COUNTER
void port_icount_start(void);
uint64_t port_icount_read(void);
#else
static inline void port_icount_start(void) {}
static inline uint64_t port_icount_read(void) { return 0; }
#endif

/* Core cycles since reset, exact (each port says by what): only a board
 * whose board.mk sets BOARD_CYCLES := 1 provides it, and its report then
 * gives render_cycles and cycles_per_pixel beside the instructions. */
uint64_t port_cycles_read(void);
#ifndef BOARD_CYCLES /* firmware.mk passes the board's; 0: no cycle counter */
#define BOARD_CYCLES 0
#endif

/* Which of the two counters above run, for a port that finds out at run
 * time (BOARD_COUNTERS_PROBED=1 in its BOARD_CFLAGS: the STM32F4, whose
 * DWT cycle counter runs on the chip and reads 0 under QEMU, where TIM2
 * counts instructions instead); main.c reports only those. Every other
 * port has what its board.mk says. */
#ifndef BOARD_COUNTERS_PROBED
#define BOARD_COUNTERS_PROBED 0
#endif
#if BOARD_COUNTERS_PROBED
int port_counts_instructions(void);
int port_counts_cycles(void);
#else
static inline int port_counts_instructions(void) { return BOARD_INSTR_COUNTER; }
static inline int port_counts_cycles(void) { return BOARD_CYCLES; }
#endif

/* Toggles the board's user LED: a heartbeat at each band drawn
 * (sink_progress). Only a board with BOARD_LED=1 in its BOARD_CFLAGS
 * provides it; on the others it does nothing. */
#ifndef BOARD_LED
#define BOARD_LED 0
#endif
#if BOARD_LED
void port_heartbeat(void);
#else
static inline void port_heartbeat(void) {}
#endif

/* Ends the run with this exit status. */
void port_exit(int status) __attribute__((noreturn));

/* ---- provided by app/firmware/ for the port ------------------------ */

/* The stack region of sections.ld: painted at start, measured after. */
void stack_paint(void);
uint32_t stack_high_water(void);
uint32_t stack_size(void);
int stack_guard_intact(void);

/* A record of report text on the console ('T' record of sink.h's stream
 * format), for fault handlers and ports. */
void report_text(const char *text);

/* ---- a port with more than one core ------------------------------------- */
/*
 * Only a board with a second core provides these (mps2-an521: two
 * Cortex-M33; pico: the RP2040's two Cortex-M0+); its board.mk sets
 * BOARD_CORES := 2 (app/firmware/bands.c then splits the frame
 * between the cores), and a single-core port neither defines nor links
 * any of them. Both cores run the same image, so port_exit() stays core
 * 0's, and core 1 reports through shared memory; the console may be
 * written by either core, one at a time (bands.c's hand-over holds a
 * lock). port_icount_read() may be called from either core (under QEMU
 * the counter is one virtual clock, so it counts both cores' instructions,
 * not the caller's).
 */

/* Which core runs the caller: 0 (the one reset starts in main) or 1
 * (sink_io.c keeps each core's output cycles apart by it). */
unsigned port_core_id(void);

/* Core 1 starts running entry() on its own stack (the board's .stack1);
 * entry should call stack_paint() first, as main does. Call once. If
 * entry returns, core 1 parks in port_wait_event() for good. */
void port_start_core1(void (*entry)(void));

/* Sleeps until the other core signals (or any other event): it may also
 * return at once or spuriously, so callers loop on their own condition. */
void port_wait_event(void);

/* Wakes the other core out of port_wait_event(), after making the
 * caller's earlier stores visible to it (barrier first, then the event),
 * so a woken core re-reading its condition sees them. */
void port_signal_event(void);

/* *p += v as one indivisible step, returning the old value; a full
 * barrier either side, so plain stores before it are seen by whoever
 * reads the new value (hand-out of work, done counts). */
uint32_t port_atomic_add(volatile uint32_t *p, uint32_t v);

/* A board that counts cycles but not instructions (BOARD_CYCLES 1,
 * BOARD_INSTR_COUNTER 0: the pico, whose SysTick is each core's own):
 * the calling core's own cycles, which bands.c counts each core's work
 * with. Not port_cycles_read(): a runner may watch that one's calls as
 * each core's marks (tools/emu/pico/run.mjs), which must stay the start of
 * its share of the render, its output's pairs and the end. */
uint64_t port_core_cycles_read(void);

/* Provided by app/firmware/stack.c when BOARD_CORES > 1: the stack
 * functions above measure core 0's stack (sections.ld's .stack); these
 * measure either core's (1: the board's .stack1, same size and guard).
 * stack_paint() paints whichever of the two stacks it is called on. */
uint32_t stack_high_water_core(unsigned core);
int stack_guard_intact_core(unsigned core);

#endif
