/*
 * multicore.c - the architecture's half of port.h's "more than one core"
 * contract, for any Cortex-M: waiting on and signalling events, and, on a
 * core with exclusives (v7-M, v8-M), an atomic add. Only a multi-core
 * port's firmware references them; a single-core one links none
 * (--gc-sections). ARMv6-M (the RP2040's M0+) has no LDREX/STREX: its
 * port brings its own port_atomic_add (the pico's, on an SIO spinlock).
 */
#include "port.h"

/* WFE returns at once if an event came since the last one (the event
 * register), so a signal between the caller's test and this call is not
 * lost. The clobber makes the caller re-read its condition. */
void port_wait_event(void)
{
    __asm__ volatile("wfe" : : : "memory");
}

/* DSB, not DMB: the stores must have completed, not only be ordered,
 * before the other core can wake and look (v6-M has DSB too). */
void port_signal_event(void)
{
    __asm__ volatile("dsb\n\tsev" : : : "memory");
}

#if defined(__ARM_FEATURE_LDREX) && (__ARM_FEATURE_LDREX & 4)
/* An LDREX/STREX loop between two DMBs. The seq_cst add alone compiles
 * to LDAEX/STLEX, which would still let a plain store before it pass a
 * plain load after it. 32 bits only: a 64-bit atomic would call
 * libatomic, which this firmware does not link. */
uint32_t port_atomic_add(volatile uint32_t *p, uint32_t v)
{
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    uint32_t old = __atomic_fetch_add(p, v, __ATOMIC_RELAXED);
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    return old;
}
#endif
