/*
 * pico_clk_peri_off.c - for tests/boards/board-pico-tests.sh: the Pico's
 * firmware with clk_peri stopped once port_init() is done, as an image
 * that never enabled it would run on the chip (its UART sends nothing).
 * The runner must fail it. Linked into a test build only, with
 * -Wl,--wrap=port_init, so that main's call comes here; the port's own
 * source has no switch for it.
 */
#include "pico/rp2040.h"

void __real_port_init(void);
void __wrap_port_init(void);

void __wrap_port_init(void)
{
    __real_port_init();
    CLK_PERI_CTRL = 0; /* stopped: the next write to the UART reaches nothing */
}
