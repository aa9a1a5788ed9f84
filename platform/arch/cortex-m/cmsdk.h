/*
 * cmsdk.h - Arm's CMSDK APB UART and timer, as the MPS2 boards have them
 * (mps2-an385 and -an386 at 0x40004000 / 0x40000000, mps2-an521 at
 * 0x50200000 / 0x50000000): each board passes its base addresses.
 */
#ifndef CMSDK_H
#define CMSDK_H

#include <stddef.h>
#include <stdint.h>

#include "../../mmio.h"

#define CMSDK_REG(base, off) REG((base) + (off))

/* UART: DATA +0, STATE +4 (bit 0: TX full), CTRL +8 (bit 0: TX enable),
 * BAUDDIV +0x10 (at least 16 before enabling; QEMU ignores the rate). */
static inline void cmsdk_uart_init(uintptr_t base)
{
    CMSDK_REG(base, 0x10) = 16;
    CMSDK_REG(base, 0x08) = 1;
}

static inline void cmsdk_uart_write(uintptr_t base, const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (CMSDK_REG(base, 0x04) & 1u)
            ;
        CMSDK_REG(base, 0x00) = p[i];
    }
}

/* Timer: CTRL +0 (bit 0: enable), VALUE +4 (counts down), RELOAD +8.
 * Started from 2^32 - 1, the ticks since are its distance from there:
 * no state, so any core may read it; it wraps after 2^32 ticks. */
static inline void cmsdk_timer_start(uintptr_t base)
{
    CMSDK_REG(base, 0x00) = 0;
    CMSDK_REG(base, 0x08) = 0xFFFFFFFFu;
    CMSDK_REG(base, 0x04) = 0xFFFFFFFFu;
    CMSDK_REG(base, 0x00) = 1;
}

static inline uint32_t cmsdk_timer_ticks(uintptr_t base) { return 0xFFFFFFFFu - CMSDK_REG(base, 0x04); }

#endif
