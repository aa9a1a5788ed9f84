/* sink_io.c - the time a display sink spends on output (sink.h), kept
 * apart so the render's counts are the renderer's alone. With two cores
 * (bands.c) either core may output, one at a time; the cycles are each
 * core's own (its SysTick), so each core keeps its own total. The cycle
 * reads are port_cycles_read's, which a runner may count as the output's
 * marks on the core that calls it (port.h). */
#include "port.h"
#include "sink.h"

#ifndef BOARD_CORES
#define BOARD_CORES 1
#endif

static uint64_t instr_total, instr_mark;
#if BOARD_CYCLES
static uint64_t cycles_total[BOARD_CORES], cycles_mark;

#if BOARD_CORES > 1
static unsigned io_core(void) { return port_core_id(); }
#else
static unsigned io_core(void) { return 0; }
#endif
#endif

void sink_io_begin(void)
{
    instr_mark = port_icount_read();
#if BOARD_CYCLES
    cycles_mark = port_cycles_read();
#endif
}

void sink_io_end(void)
{
#if BOARD_CYCLES
    cycles_total[io_core()] += port_cycles_read() - cycles_mark;
#endif
    instr_total += port_icount_read() - instr_mark;
}

uint64_t sink_io_instructions(void) { return instr_total; }

/* Rows drawn of this frame, and where the next progress line is due */
static uint32_t progress_rows, progress_next;

void sink_progress(uint32_t lines, uint32_t height)
{
    port_heartbeat();
    progress_rows += lines;
    if (progress_rows >= progress_next || progress_rows >= height) {
        report_value("progress_rows", progress_rows);
        progress_next = progress_rows + (height + 9u) / 10u;
    }
    if (progress_rows >= height) /* the frame is done: the next starts at 0 */
        progress_rows = progress_next = 0;
}

#if BOARD_CYCLES
uint64_t sink_io_cycles(void) { return cycles_total[io_core()]; }
#else
uint64_t sink_io_cycles(void) { return 0; }
#endif
