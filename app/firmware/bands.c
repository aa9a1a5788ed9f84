/*
 * bands.c - one frame on several cores (bands.h).
 *
 * A band is a viewport of whole lines, rendered by rt_render on one core
 * with that core's own worker (rt_render_opts_t.worker), into one of that
 * core's own band buffers. When a core finishes a band it hands every
 * band that is ready, in frame order, to the display sink, whichever core
 * rendered it; a ticket lock keeps one core at a time in the sink. Besides
 * the read-only scene, the cores share only the band counter, the
 * buffers' states and the hand-over.
 * Progressive display (opts.progressive) takes pieces of each pass
 * instead and sends their areas as they come (below, BOARD_PROGRESSIVE).
 *
 * Which core renders which band (BOARD_BAND_SPLIT):
 *   0  interleave: core c takes bands c, c + N, c + 2N, ...
 *   1  counter (the default): each core takes the next band from a shared
 *      atomic counter. On mps2-an521 with one-line bands its critical path
 *      was 0.5045 / 0.5066 / 0.5018 of one core's instructions on balls-2,
 *      rings-1 and the showpiece at 64x64, against 0.5045 / 0.5109 /
 *      0.5093 interleaved (docs/boards.md, "Two cores").
 *
 * Counting: in instructions where the board counts them
 * (port_icount_read), else in each core's own cycles
 * (port_core_cycles_read: the pico's SysTick, one per core); the report
 * names the unit (BANDS_UNIT). With per-core counters each core's count
 * is its own whatever the other does, and the cores run in parallel (the
 * chip, or rp2040js stepping both): cores_one_at_a_time() is false.
 *
 * Under QEMU's -icount the cores run one at a time on one host
 * thread, and the instruction counter is one clock for all of them. Each
 * core therefore counts its own instructions per segment of work (a band,
 * a hand-over) as the clock's advance minus the instructions the others
 * counted in the meantime (they finish their segment before they let this
 * core run again: see take_turn). From these counts each core keeps the
 * clock it would have on the parallel board, where it waits only for a
 * free band buffer (its band leaves when all bands above it have): the
 * critical path is the latest core's clock at the end. Output costs no
 * time on that timeline, as the single-core count leaves the sink out.
 *
 * Taking turns. With a shared counter, which core takes a band depends on
 * when it asks; so when the cores run one at a time, a core asks only
 * when its parallel clock is not ahead of the others' (the order parallel
 * cores would ask in). When the cores truly run in parallel (QEMU's
 * -accel tcg,thread=multi, a real chip) they never wait for a turn, and
 * the counts are the clock's readings, not exact.
 */
#include "bands.h"

#include "port.h"

#ifndef BOARD_BAND_SPLIT
#define BOARD_BAND_SPLIT 1
#endif
#define SLOTS 2 /* band buffers per core: one renders while the last waits its turn */
#define BAND_BYTES (BOARD_BAND_LINES * RT_FB_CONST_LINE_BYTES(BOARD_FORMAT, BOARD_WIDTH))

_Static_assert(BOARD_CORES == 2, "the port starts one more core (port_start_core1)");
_Static_assert(BOARD_CORES <= RT_MAX_WORKERS, "one worker per core (RT_MAX_WORKERS)");
_Static_assert(BOARD_BAND_SPLIT == 0 || BOARD_BAND_SPLIT == 1, "BOARD_BAND_SPLIT: 0 interleave, 1 counter");

enum { SLOT_FREE, SLOT_READY };

typedef struct {
    volatile uint32_t state;
    volatile uint32_t band;
    volatile uint64_t ready_at;   /* parallel clock of its core when rendered */
    volatile uint64_t emitted_at; /* ... when it went to the sink */
} slot_t;

static slot_t slots[BOARD_CORES][SLOTS];
static uint8_t slot_px[BOARD_CORES][SLOTS][BAND_BYTES] __attribute__((aligned(4))); /* (word copies: progressive rows) */
static rt_fb_sink_t core_sink[BOARD_CORES];
static rt_error_t core_err[BOARD_CORES];

/* The frame, shared by the cores. */
static struct {
    const rt_scene_t *sc;
    const rt_render_opts_t *opts;
    rt_fb_sink_t *out;
    bands_report_t *rep;
    uint32_t n_bands;
    volatile uint32_t next_emit;          /* the band the sink wants next */
    volatile uint32_t serving;            /* the hand-over's lock: the ticket served */
    volatile uint64_t last_emitted_at;
    volatile uint64_t clock[BOARD_CORES]; /* parallel clocks, published */
    volatile uint64_t busy[BOARD_CORES];  /* instructions counted so far */
    volatile uint32_t done[BOARD_CORES];  /* no more bands to take */
    volatile uint32_t blocked[BOARD_CORES]; /* waiting for a free buffer */
    volatile uint32_t alive, go, spin;    /* start-up hand-shake */
    volatile int status;                  /* first failure, any core */
#if BOARD_PROGRESSIVE
    volatile uint32_t passes_shown;       /* progressive display: passes on the panel */
    volatile int sending;                 /* ... whose area the sink sends (-1: none; under the lock) */
#endif
} fr;

/* What the cores change only through port_atomic_add (a spinlock's on
 * the pico), in a section of its own: sections.ld names its bounds
 * (__spinlocked_start, __spinlocked_end), and the pico's runner fails a
 * write there by a core that holds no spinlock. */
__attribute__((section(".bss.spinlocked"))) static struct {
    volatile uint32_t next_band; /* BOARD_BAND_SPLIT 1 */
    volatile uint32_t ticket;    /* the hand-over's lock: tickets taken */
#if BOARD_PROGRESSIVE
    volatile uint32_t bands_done; /* progressive display: pieces rendered, all passes */
#endif
} taken;

static uint64_t others_busy(unsigned c)
{
    uint64_t n = 0;
    for (unsigned o = 0; o < BOARD_CORES; o++)
        if (o != c)
            n += fr.busy[o];
    return n;
}

/* A segment of this core's work: started at clock reading t0 when the
 * others had counted other0. */
typedef struct {
    uint64_t t0, other0;
} segment_t;

/* The count this file keeps (bands.h's units) */
#if BOARD_INSTR_COUNTER
static inline uint64_t count_read(void) { return port_icount_read(); }
#else
_Static_assert(BOARD_CYCLES, "bands.c counts instructions or, without an instruction counter, each core's cycles");
static inline uint64_t count_read(void) { return port_core_cycles_read(); }
#endif

static segment_t segment_start(unsigned c) { return (segment_t){ count_read(), others_busy(c) }; }

/* This core's count in the segment, now counted as its own. */
static uint64_t segment_end(unsigned c, segment_t s)
{
    uint64_t elapsed = count_read() - s.t0, others = others_busy(c) - s.other0;
    uint64_t own = fr.rep->one_at_a_time && others < elapsed ? elapsed - others : elapsed;
    fr.busy[c] += own;
    return own;
}

static void publish_clock(unsigned c, uint64_t clock)
{
    fr.clock[c] = clock;
    port_signal_event();
}

/* When the cores run one at a time: returns once no other core still
 * taking bands is behind this one on the parallel timeline (ties: the
 * lower core first). A core waiting for a buffer is not waited for: its
 * clock will move past the band this one is about to take. */
static void take_turn(unsigned c, uint64_t clock)
{
    publish_clock(c, clock);
    for (;;) {
        bool mine = true;
        for (unsigned o = 0; o < BOARD_CORES; o++) {
            if (o == c || fr.done[o] || fr.blocked[o])
                continue;
            uint64_t theirs = fr.clock[o];
            if (theirs < clock || (theirs == clock && o < c))
                mine = false;
        }
        if (mine || fr.status != 0)
            return;
        port_wait_event();
    }
}

static slot_t *ready_slot(uint32_t band, unsigned *core, unsigned *k)
{
    for (unsigned c = 0; c < BOARD_CORES; c++)
        for (unsigned i = 0; i < SLOTS; i++)
            if (slots[c][i].state == SLOT_READY && slots[c][i].band == band) {
                *core = c;
                *k = i;
                return &slots[c][i];
            }
    return 0;
}

/* The sink, one core at a time: a ticket lock (first come, first served). */
static void sink_lock(void)
{
    uint32_t me = port_atomic_add(&taken.ticket, 1);
    while (fr.serving != me)
        port_wait_event();
    __atomic_thread_fence(__ATOMIC_SEQ_CST); /* what the last holder wrote, seen */
}

static void sink_unlock(void)
{
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    fr.serving = fr.serving + 1; /* (only the holder writes it) */
    port_signal_event();
}

/* An area to the display sink, the lock held; returns once it is out
 * (the other core then finds the sink idle): 0 or the sink's failure. */
static int send(const rt_fb_area_t *area, const uint8_t *px)
{
    fr.out->flushing = true;
    int st = fr.out->flush(fr.out, area, px);
    while (st == 0 && fr.out->flushing)
        if (fr.out->wait)
            fr.out->wait(fr.out);
    return st;
}

/* Hands every ready band, in frame order, to the sink. */
static void hand_over(unsigned c)
{
    segment_t seg = segment_start(c);
    sink_lock();
    unsigned oc, k;
    slot_t *s;
    while (fr.status == 0 && (s = ready_slot(fr.next_emit, &oc, &k)) != 0) {
        uint16_t y = (uint16_t)(fr.next_emit * BOARD_BAND_LINES);
        uint16_t y2 = (uint16_t)(y + BOARD_BAND_LINES - 1 < BOARD_HEIGHT ? y + BOARD_BAND_LINES - 1 : BOARD_HEIGHT - 1);
        rt_fb_area_t area = { 0, y, BOARD_WIDTH - 1, y2 };
        int st = send(&area, slot_px[oc][k]);
        if (st != 0)
            fr.status = st;
        uint64_t at = s->ready_at > fr.last_emitted_at ? s->ready_at : fr.last_emitted_at;
        fr.last_emitted_at = s->emitted_at = at;
        fr.next_emit++;
        __atomic_thread_fence(__ATOMIC_SEQ_CST); /* the pixels are out before the buffer is free */
        s->state = SLOT_FREE;
    }
    sink_unlock();
    (void)segment_end(c, seg); /* counted as busy (so the others' counts stay exact), not as render */
}

static int slot_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    (void)a, (void)px;
    rt_fb_flush_ready(s); /* the pixels stay in the buffer until hand_over */
    return 0;
}

/* Core c's share of the frame. */
static void render_bands(unsigned c)
{
    bands_core_t *me = &fr.rep->core[c];
    uint64_t clock = 0;
    uint32_t nth = 0; /* bands this core has taken */
    for (unsigned k = 0;; k = (k + 1) % SLOTS) {
        slot_t *s = &slots[c][k];
        if (s->state != SLOT_FREE) {
            fr.blocked[c] = 1;
            port_signal_event();
            while (s->state != SLOT_FREE && fr.status == 0)
                port_wait_event();
            fr.blocked[c] = 0;
        }
        if (s->emitted_at > clock) { /* on the parallel board it waited for that */
            me->wait += s->emitted_at - clock;
            clock = s->emitted_at;
        }
        if (fr.rep->one_at_a_time)
            take_turn(c, clock);
        uint32_t band = BOARD_BAND_SPLIT ? port_atomic_add(&taken.next_band, 1) : c + nth * BOARD_CORES;
        if (band >= fr.n_bands || fr.status != 0)
            break;
        nth++;

        rt_render_opts_t o = *fr.opts;
        uint16_t y = (uint16_t)(band * BOARD_BAND_LINES);
        o.viewport = (rt_viewport_t){ 0, y, BOARD_WIDTH,
                                      (uint16_t)(BOARD_HEIGHT - y < BOARD_BAND_LINES ? BOARD_HEIGHT - y
                                                                                     : BOARD_BAND_LINES) };
        o.worker = (uint8_t)c;
        if (o.scratch) /* each core its own (bands.h) */
            o.scratch = (uint8_t *)o.scratch + c * o.scratch_bytes;
        rt_fb_sink_t *sink = &core_sink[c];
        sink->band[0] = slot_px[c][k];
        segment_t seg = segment_start(c);
        int st = rt_render(fr.sc, &o, sink, &me->stats, &core_err[c]);
        uint64_t cost = segment_end(c, seg);
        if (st != 0) {
            fr.status = st;
            break;
        }
        me->render += cost;
        me->bands++;
        clock += cost;
        s->band = band;
        s->ready_at = clock;
        __atomic_thread_fence(__ATOMIC_SEQ_CST); /* the band is whole before it is ready */
        s->state = SLOT_READY;
        publish_clock(c, clock);
        hand_over(c);
    }
    fr.clock[c] = clock;
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    fr.done[c] = 1;
    port_signal_event();
}

#if BOARD_PROGRESSIVE
/*
 * Progressive display (rt_render.h) on every core. The panel keeps its
 * own frame, so areas need not reach it in frame order: each pass is cut
 * into pieces that no block crosses, bands of PASS_CUT lines where its
 * blocks touch along rows, strips of PASS_CUT columns where they stack
 * down columns (RT_PROGRESSIVE_BY_COLUMNS: each column one area, as on one
 * core). The cores take the pieces from the shared counter, and each core
 * sends its piece's areas straight to the sink, under the lock, from a
 * band buffer of its own. A pass's pieces start only once the pass before
 * is on the panel (the core that finishes a pass's last piece tells the
 * sink: pass_end), so the panel after each pass is the one a single core
 * shows. The cost: each core waits for its own transfers, and at the end
 * of each pass for the other's last piece.
 */
#define PASS_CUT 8 /* the lattice's tile */

/* Pieces of pass p. */
static uint32_t pass_pieces(uint32_t p)
{
    return RT_PROGRESSIVE_BY_COLUMNS(p) ? (BOARD_WIDTH + PASS_CUT - 1) / PASS_CUT
                                        : (BOARD_HEIGHT + PASS_CUT - 1) / PASS_CUT;
}

/* Under the lock: the sink idle, and the core whose transfer it was told
 * (its band buffer free again). */
static void sink_idle(void)
{
    while (fr.out->flushing)
        if (fr.out->wait)
            fr.out->wait(fr.out);
    if (fr.sending >= 0) {
        rt_fb_flush_ready(&core_sink[fr.sending]);
        fr.sending = -1;
    }
}

/* The core's sink: each area started at once, under the lock, once the
 * sink is idle; the transfer runs on while the core renders into its other
 * band buffer (the core's wait, or the next core to send, sees it end). */
static int pass_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    sink_lock();
    sink_idle();
    fr.out->flushing = true;
    int st = fr.out->flush(fr.out, a, px);
    if (st == 0)
        fr.sending = (int)(s - core_sink);
    sink_unlock();
    return st; /* (on a failure the core stops: its buffer's state no longer matters) */
}

/* The core's wait for its transfer: under the lock, the sink idle. */
static void pass_wait(rt_fb_sink_t *s)
{
    (void)s;
    sink_lock();
    sink_idle();
    sink_unlock();
}

static void render_passes(unsigned c)
{
    bands_core_t *me = &fr.rep->core[c];
    for (;;) {
        segment_t seg = segment_start(c);
        uint32_t piece = port_atomic_add(&taken.next_band, 1), pass = 1, before = 0; /* pieces of earlier passes */
        while (pass <= RT_PROGRESSIVE_PASSES && piece - before >= pass_pieces(pass))
            before += pass_pieces(pass++);
        while (pass <= RT_PROGRESSIVE_PASSES && fr.passes_shown + 1 < pass && fr.status == 0)
            port_wait_event();
        me->wait += segment_end(c, seg);
        if (pass > RT_PROGRESSIVE_PASSES || fr.status != 0)
            break;
        rt_render_opts_t o = *fr.opts;
        uint16_t at = (uint16_t)((piece - before) * PASS_CUT);
        if (RT_PROGRESSIVE_BY_COLUMNS(pass))
            o.viewport = (rt_viewport_t){ at, 0, (uint16_t)(BOARD_WIDTH - at < PASS_CUT ? BOARD_WIDTH - at : PASS_CUT),
                                          BOARD_HEIGHT };
        else
            o.viewport = (rt_viewport_t){ 0, at, BOARD_WIDTH,
                                          (uint16_t)(BOARD_HEIGHT - at < PASS_CUT ? BOARD_HEIGHT - at : PASS_CUT) };
        o.progressive = (uint8_t)pass;
        o.worker = (uint8_t)c;
        seg = segment_start(c);
        int st = rt_render(fr.sc, &o, &core_sink[c], &me->stats, &core_err[c]);
        me->render += segment_end(c, seg); /* (its transfers included) */
        if (st != 0) {
            fr.status = st;
            break;
        }
        me->bands++;
        if (port_atomic_add(&taken.bands_done, 1) + 1 == before + pass_pieces(pass)) { /* the pass's last piece */
            seg = segment_start(c);
            if (fr.out->pass_end) {
                sink_lock();
                sink_idle(); /* (every piece's render waited for its own last transfer) */
                fr.out->pass_end(fr.out, pass);
                sink_unlock();
            }
            fr.passes_shown = pass;
            me->wait += segment_end(c, seg);
        }
    }
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    fr.done[c] = 1;
    port_signal_event(); /* (also wakes a core waiting for a pass after a failure) */
}
#endif

/* Core c's share of the frame. */
static void render_share(unsigned c)
{
#if BOARD_PROGRESSIVE
    if (fr.opts->progressive) {
        render_passes(c);
        return;
    }
#endif
    render_bands(c);
}

/* Core 1 starts here, on its own stack. */
static void core1_entry(void)
{
    stack_paint(); /* core 1's stack, as main does core 0's */
    fr.alive = 1;
    port_signal_event();
    while (!fr.go) { /* counted by core 0 to tell how the cores run */
        fr.spin++;
        port_wait_event();
    }
    render_share(1);
    /* returns: the port parks core 1 (port.h) */
}

/* Whether the cores run one at a time: core 1 counts while it waits to
 * start, so while core 0 spins here without waiting, a core 1 that runs
 * alongside shows. Under QEMU's -icount a core 1 waiting for an event
 * does not run until core 0 waits (even across QEMU's time slices), so a
 * long look cannot be fooled; with the cores in parallel the first
 * change ends it. */
static bool cores_one_at_a_time(void)
{
    if (!BOARD_INSTR_COUNTER) /* each core counts its own cycles: see Counting */
        return false;
    uint32_t before = fr.spin;
    for (uint32_t n = 0; n < 1000000; n++)
        /* cppcheck-suppress knownConditionTrueFalse ; volatile: core 1 counts it */
        if (fr.spin != before)
            return false;
    return true;
}

int bands_render(const rt_scene_t *sc, const rt_render_opts_t *opts, rt_fb_sink_t *sink, bands_report_t *rep,
                 rt_error_t *err)
{
    uint16_t h = opts->height;
    fr.sc = sc;
    fr.opts = opts;
    fr.out = sink;
    fr.rep = rep;
    fr.n_bands = (uint32_t)(h + BOARD_BAND_LINES - 1) / BOARD_BAND_LINES;
    for (unsigned c = 0; c < BOARD_CORES; c++) {
        core_sink[c] = (rt_fb_sink_t){ .format = sink->format, .dither = sink->dither, .band_bytes = BAND_BYTES, .flush = slot_flush };
#if BOARD_PROGRESSIVE
        fr.sending = -1;
        if (opts->progressive) { /* each core's two band buffers, its areas sent at once */
            core_sink[c].flush = pass_flush;
            core_sink[c].wait = pass_wait;
            core_sink[c].band[0] = slot_px[c][0];
            core_sink[c].band[1] = slot_px[c][1];
        }
#endif
    }
    int st = sink->begin ? sink->begin(sink, opts->width, h) : 0;
    if (st != 0)
        return st;
    port_start_core1(core1_entry);
    while (!fr.alive)
        port_wait_event();
    rep->one_at_a_time = cores_one_at_a_time();
    __atomic_thread_fence(__ATOMIC_SEQ_CST);
    fr.go = 1;
    port_signal_event();
    render_share(0);
    for (unsigned c = 1; c < BOARD_CORES; c++)
        while (!fr.done[c])
            port_wait_event();
    for (unsigned c = 0; c < BOARD_CORES; c++) {
        uint64_t end = rep->core[c].render + rep->core[c].wait;
        if (end > rep->critical_path)
            rep->critical_path = end;
    }
    if (fr.status != 0) {
        for (unsigned c = 0; c < BOARD_CORES; c++)
            if (core_err[c].msg[0])
                *err = core_err[c];
        return fr.status;
    }
    return sink->end ? sink->end(sink) : 0;
}
