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

#if BOARD_CYCLES
uint64_t sink_io_cycles(void) { return cycles_total; }
#else
uint64_t sink_io_cycles(void) { return 0; }
#endif
