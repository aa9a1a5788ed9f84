/* sink_io.c - the time a display sink spends on output (sink.h), kept
 * apart so the render's counts are the renderer's alone. */
#include "port.h"
#include "sink.h"

static uint64_t instr_total, instr_mark;
#if BOARD_CYCLES
static uint64_t cycles_total, cycles_mark;
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
    cycles_total += port_cycles_read() - cycles_mark;
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
uint64_t sink_io_cycles(void) { return cycles_total; }
#else
uint64_t sink_io_cycles(void) { return 0; }
#endif
