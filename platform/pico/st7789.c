/*
 * st7789.c - the Pico's display (sink.h): an ST7789 colour panel on SPI0,
 * RGB565 big-endian (the core's rgb565be bytes go out as rendered), each
 * band sent by DMA while the core renders the next.
 *
 * Panels (PANEL, PANEL_FLIP in board.mk), set as their makers' own
 * drivers set them (Pimoroni's, for the Display Pack 2.0 and the 1.3"
 * 240x240 modules). The controller's memory is 240 columns x 320 rows;
 * MADCTL says how the window addresses map onto it:
 *   320x240, upright    MX|MV|ML (0x70): rows and columns exchanged,
 *                       columns mirrored, a rotation (MV alone would be
 *                       a transpose: the picture mirrored)
 *   320x240, flipped    MY|MV|ML (0xb0): the same turned by 180 degrees
 *   240x240, upright    0: the glass shows memory rows 0..239
 *   240x240, flipped    MX|MY (0xc0), rows addressed from 80: mirrored
 *                       rows 80..319 land on memory rows 239..0
 *
 * Pins, as on Pimoroni's Pico Display Pack 2.0 (another module: wire it
 * the same, or change them here): SPI0 SCK GP18, TX GP19, chip select
 * GP17, data/command GP16 (low: command), backlight GP20 (high: on). The
 * Display Pack ties the controller's reset to the Pico's RUN line; a
 * module with a reset pin of its own: set PIN_RESET to its GPIO.
 *
 * The SPI: mode 0 (clock idle low, data sampled on the rising edge), 8-bit
 * frames, 62.5 MHz (clk_peri / 2: the ST7789's 16 ns write cycle). It is
 * configured and enabled before chip select is first driven low, so the
 * clock line never moves while the panel listens; chip select then goes
 * low for each command with its parameters, or each band's pixels, and
 * high again after, which also resynchronises the panel's serial
 * interface if a bit was ever lost.
 *
 * Start-up, with the datasheet's waits: hardware reset (when wired) or
 * software reset, 120 ms; sleep out, 120 ms; 16-bit colour, MADCTL,
 * inversion on (IPS glass, which both modules are, shows inverted colours
 * without it), normal mode, display on, then the backlight. The panel's
 * voltage and gamma registers keep their reset values (what Adafruit's
 * and others' minimal drivers rely on; tuned values are the module
 * maker's, for contrast, not for geometry). The delays count cycles at
 * 125 MHz (board.h).
 *
 * Per band: wait for the last transfer, then CASET and RASET (the band's
 * window, with the panel's offset), RAMWR and the band's bytes by DMA
 * channel 0 paced by SPI0's transmit request; chip select rises when the
 * transfer is done. With two cores (app/firmware/bands.c) either core
 * sends a band, one at a time under the hand-over's lock, and waits for
 * its transfer (transfer_wait) before letting go of the lock: the other
 * core always finds the DMA channel idle and the panel released. What
 * this file keeps (the frame's place, the progress count) is written by
 * core 0 before core 1 starts, or under that lock. Before the first band the whole panel is cleared to
 * black (one window, the same zero byte sent by DMA for every pixel), and
 * a frame smaller than the panel is centred on it (board.mk refuses a
 * larger one at build time); the sink then reports frame_width,
 * frame_height and a line naming the frame and the panel (PANEL_INFO,
 * which uf2.mjs check also finds in the image), which tell run.mjs where
 * the frame is. A progress line goes to the UART at each tenth of the
 * frame, and the LED toggles at each band. With progressive display
 * (PROGRESSIVE=1, the default: docs/hal.md) the areas are a pass's rows
 * of blocks or single blocks, each its own window; at each pass's end
 * (its last transfer done) a report line "progress_pass N" and a call of
 * board_pass_shown, where run.mjs takes the panel's picture; the report
 * adds first_picture_us, render start to pass 1 on the panel.
 *
 * The frame's times (frame_ms, first_picture_us) are the TIMER's
 * microseconds (board_us): the frame starts on core 0, but with two cores
 * either may end pass 1, and each core's SysTick is its own count. They
 * start where sink_init returns, which main.c follows with the render's
 * start (panel_begin would start late: the core sets up the camera and
 * the eye rays before it calls it: 27,000 cycles on the whitted scene).
 *
 * Checked against the runner's model of the controller
 * (tools/emu/pico/st7789.mjs), not on hardware: docs/boards.md, "On a
 * real Pico", says what only a real module can confirm.
 */
#include "../arch/cortex-m/pl022.h"
#include "board.h"
#include "port.h"
#include "rp2040.h"
#include "sink.h"

#ifndef PANEL_WIDTH /* board.mk passes PANEL's */
#define PANEL_WIDTH 320
#define PANEL_HEIGHT 240
#endif
#ifndef PANEL_FLIP
#define PANEL_FLIP 0
#endif
_Static_assert((PANEL_WIDTH == 320 || PANEL_WIDTH == 240) && PANEL_HEIGHT == 240, "PANEL: 320x240 or 240x240");

/* MADCTL bits */
#define MADCTL_MY 0x80u /* row addresses bottom to top */
#define MADCTL_MX 0x40u /* column addresses right to left */
#define MADCTL_MV 0x20u /* rows and columns exchanged */
#define MADCTL_ML 0x10u /* refresh bottom to top (no effect on memory) */
#if PANEL_WIDTH == 320
#define PANEL_MADCTL (PANEL_FLIP ? MADCTL_MY | MADCTL_MV | MADCTL_ML : MADCTL_MX | MADCTL_MV | MADCTL_ML)
#define PANEL_ROW_OFFSET 0u
#else
#define PANEL_MADCTL (PANEL_FLIP ? MADCTL_MX | MADCTL_MY : 0u)
#define PANEL_ROW_OFFSET (PANEL_FLIP ? 80u : 0u) /* 320 memory rows, 240 of glass */
#endif

#if defined(BOARD_WIDTH) && defined(BOARD_HEIGHT)
_Static_assert(BOARD_WIDTH <= PANEL_WIDTH && BOARD_HEIGHT <= PANEL_HEIGHT, "the frame is larger than the panel (SIZE, PANEL)");
#define STR_(x) #x
#define STR(x) STR_(x)
/* the frame and the panel, as the report's line and as bytes of the
 * flash image that uf2.mjs check prints ("panel: " starts it) */
#define PANEL_INFO                                                                                                   \
    "panel: frame " STR(BOARD_WIDTH) "x" STR(BOARD_HEIGHT) " centred on the " STR(PANEL_WIDTH) "x" STR(PANEL_HEIGHT) \
    " ST7789 panel" PANEL_INFO_FLIP ", the rest black"
#if PANEL_FLIP
#define PANEL_INFO_FLIP " (flipped)"
#else
#define PANEL_INFO_FLIP ""
#endif
static const char panel_info[] = PANEL_INFO;
#endif
#ifdef RT_FB_ONLY_FORMAT
_Static_assert(RT_FB_ONLY_FORMAT == RT_FB_RGB565BE, "the ST7789 takes rgb565be pixels (FW_FORMAT in board.mk)");
#endif

/* the panel's pins */
#define PIN_DC 16u
#define PIN_CS 17u
#define PIN_SCK 18u
#define PIN_TX 19u
#define PIN_BACKLIGHT 20u
/* #define PIN_RESET n   -- a module whose reset pin is wired to GPIO n */

/* ST7789 commands */
#define ST_SWRESET 0x01u
#define ST_SLPOUT 0x11u
#define ST_NORON 0x13u
#define ST_INVON 0x21u
#define ST_DISPON 0x29u
#define ST_CASET 0x2Au
#define ST_RASET 0x2Bu
#define ST_RAMWR 0x2Cu
#define ST_MADCTL 0x36u
#define ST_COLMOD 0x3Au
#define COLMOD_RGB565 0x55u

#define CYCLES_PER_MS (CLK_SYS_HZ / 1000u)

static uint16_t frame_width, frame_height, frame_x, frame_y;
static uint32_t frame_start_us, first_picture_us; /* (progressive: to pass 1 on the panel) */

static void delay_ms(uint32_t ms)
{
    uint64_t end = board_cycles() + (uint64_t)ms * CYCLES_PER_MS;
    while (board_cycles() < end)
        ;
}

static void select_panel(void) { SIO_GPIO_OUT_CLR = 1u << PIN_CS; }
static void release_panel(void) { SIO_GPIO_OUT_SET = 1u << PIN_CS; }

/* The panel selected, a command sent, the data/command line set for
 * what follows it. */
static void start_command(uint8_t cmd)
{
    select_panel();
    SIO_GPIO_OUT_CLR = 1u << PIN_DC;
    pl022_send(SPI0, cmd);
    SIO_GPIO_OUT_SET = 1u << PIN_DC;
}

/* A command and its parameters, the panel selected for just these. */
static void command(uint8_t cmd, const uint8_t *params, unsigned n)
{
    start_command(cmd);
    for (unsigned i = 0; i < n; i++)
        pl022_send(SPI0, params[i]);
    release_panel();
}

static void command16x2(uint8_t cmd, unsigned lo, unsigned hi)
{
    const uint8_t p[] = { (uint8_t)(lo >> 8), (uint8_t)lo, (uint8_t)(hi >> 8), (uint8_t)hi };
    command(cmd, p, sizeof p);
}

/* The last band's transfer done, the bus idle and the panel released:
 * the buffer is free. */
static void transfer_wait(rt_fb_sink_t *s)
{
    sink_io_begin();
    while (DMA_CTRL_TRIG & DMA_BUSY)
        ;
    pl022_idle(SPI0);
    PL022_ICR(SPI0) = 1u; /* what came back overran the receive FIFO */
    release_panel();
    rt_fb_flush_ready(s);
    sink_io_end();
}

/* The whole panel black, so that nothing but black surrounds a smaller
 * frame: one window, the same zero byte (black, with INVON) sent by DMA
 * without read increment for every byte. */
static void panel_clear(void)
{
    static const uint8_t black = 0;
    command16x2(ST_CASET, 0, PANEL_WIDTH - 1);
    command16x2(ST_RASET, PANEL_ROW_OFFSET, PANEL_ROW_OFFSET + PANEL_HEIGHT - 1);
    start_command(ST_RAMWR);
    DMA_READ_ADDR = (uint32_t)(uintptr_t)&black;
    DMA_WRITE_ADDR = (uint32_t)(uintptr_t)&PL022_DR(SPI0);
    DMA_TRANS_COUNT = (uint32_t)PANEL_WIDTH * PANEL_HEIGHT * 2u;
    DMA_CTRL_TRIG = DMA_EN | DMA_CHAIN_TO_SELF | DMA_TREQ_SPI0_TX;
    while (DMA_CTRL_TRIG & DMA_BUSY)
        ;
    pl022_idle(SPI0);
    PL022_ICR(SPI0) = 1u;
    release_panel();
}

static int panel_begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    if (s->format != RT_FB_RGB565BE || w > PANEL_WIDTH || h > PANEL_HEIGHT)
        return 1;
    frame_width = w;
    frame_height = h;
    frame_x = (uint16_t)((PANEL_WIDTH - w) / 2u);
    frame_y = (uint16_t)((PANEL_HEIGHT - h) / 2u);
    first_picture_us = 0;
    return 0;
}

static int panel_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    (void)s;
    sink_io_begin();
    /* the other buffer's transfer is done: the core waited for it */
    command16x2(ST_CASET, frame_x + a->x1, frame_x + a->x2);
    command16x2(ST_RASET, PANEL_ROW_OFFSET + frame_y + a->y1, PANEL_ROW_OFFSET + frame_y + a->y2);
    start_command(ST_RAMWR); /* the panel stays selected: transfer_wait() releases it */
    DMA_READ_ADDR = (uint32_t)(uintptr_t)px;
    DMA_WRITE_ADDR = (uint32_t)(uintptr_t)&PL022_DR(SPI0);
    DMA_TRANS_COUNT = (uint32_t)(a->y2 - a->y1 + 1) * (uint32_t)(a->x2 - a->x1 + 1) * 2u;
    DMA_CTRL_TRIG = DMA_EN | DMA_INCR_READ | DMA_CHAIN_TO_SELF | DMA_TREQ_SPI0_TX;
#if BOARD_PROGRESSIVE
    port_heartbeat(); /* (the passes cover the frame again and again: progress by pass) */
#else
    sink_progress((uint32_t)(a->y2 - a->y1 + 1), frame_height);
#endif
    sink_io_end();
    return 0; /* rt_fb_flush_ready() comes from transfer_wait() */
}

#if BOARD_PROGRESSIVE
/* A pass is on the panel (the core waited for its last transfer): the
 * board's time to the first whole picture, and the runner's mark. */
static void panel_pass_end(rt_fb_sink_t *s, unsigned pass)
{
    (void)s;
    sink_io_begin();
    if (pass == 1)
        first_picture_us = board_us() - frame_start_us;
    board_pass_shown(pass);
    report_value("progress_pass", pass);
    sink_io_end();
}
#endif

static int panel_end(rt_fb_sink_t *s)
{
    (void)s;
    sink_io_begin();
    /* (the core waited for the last transfer) the board's own time for
     * the frame, display included */
    report_value("frame_ms", ((uint64_t)(board_us() - frame_start_us) + 500u) / 1000u);
#if BOARD_PROGRESSIVE
    /* to pass 1's last byte, sent: the whole picture on the panel */
    report_value("first_picture_us", first_picture_us);
#endif
    report_value("frame_width", frame_width);
    report_value("frame_height", frame_height);
#ifdef BOARD_WIDTH
    report_text(panel_info);
#endif
    sink_io_end();
    return 0;
}

void sink_init(rt_fb_sink_t *sink, rt_fb_format_t format, uint8_t *band, size_t bytes)
{
    board_unreset(RESET_DMA | RESET_SPI0, "bring-up: DMA or SPI0 did not leave reset");
    /* the panel released and the backlight off while the SPI is set up */
    SIO_GPIO_OUT_SET = 1u << PIN_CS | 1u << PIN_DC;
    SIO_GPIO_OUT_CLR = 1u << PIN_BACKLIGHT;
    SIO_GPIO_OE_SET = 1u << PIN_DC | 1u << PIN_CS | 1u << PIN_BACKLIGHT;
    GPIO_CTRL(PIN_DC) = FUNC_SIO;
    GPIO_CTRL(PIN_CS) = FUNC_SIO;
    GPIO_CTRL(PIN_BACKLIGHT) = FUNC_SIO;
    PL022_CR1(SPI0) = 0;  /* disabled while it is set up */
    PL022_CPSR(SPI0) = 2; /* clk_peri 125 MHz / 2 = 62.5 MHz */
    PL022_CR0(SPI0) = 7u; /* SPI mode 0 (SPO 0, SPH 0), 8-bit frames */
    PL022_DMACR(SPI0) = 2u; /* transmit requests to the DMA */
    PL022_CR1(SPI0) = 2u;   /* enabled, master */
    GPIO_CTRL(PIN_SCK) = FUNC_SPI; /* the clock idles low from here on */
    GPIO_CTRL(PIN_TX) = FUNC_SPI;

#ifdef PIN_RESET
    GPIO_CTRL(PIN_RESET) = FUNC_SIO;
    SIO_GPIO_OE_SET = 1u << PIN_RESET;
    SIO_GPIO_OUT_CLR = 1u << PIN_RESET; /* at least 10 us low */
    delay_ms(1);
    SIO_GPIO_OUT_SET = 1u << PIN_RESET;
#else
    command(ST_SWRESET, 0, 0);
#endif
    delay_ms(120); /* reset to sleep out */
    command(ST_SLPOUT, 0, 0);
    delay_ms(120); /* sleep out to the next command (5 ms), and to a later sleep in */
    static const uint8_t colmod[] = { COLMOD_RGB565 }, madctl[] = { PANEL_MADCTL };
    command(ST_COLMOD, colmod, 1);
    command(ST_MADCTL, madctl, 1);
    command(ST_INVON, 0, 0);
    command(ST_NORON, 0, 0);
    command(ST_DISPON, 0, 0);
    panel_clear(); /* before the backlight: what the memory held at power-up is never seen */
    SIO_GPIO_OUT_SET = 1u << PIN_BACKLIGHT;

    /* two band buffers: the core renders into one while DMA sends the other */
    sink->format = format;
    sink->band[0] = band;
    sink->band[1] = band + bytes / 2;
    sink->band_bytes = bytes / 2;
    sink->pitch = 0;
    sink->begin = panel_begin;
    sink->flush = panel_flush;
    sink->wait = transfer_wait;
    sink->end = panel_end;
#if BOARD_PROGRESSIVE
    sink->pass_end = panel_pass_end;
#endif
    sink->user = 0;
    sink->flushing = false;
    frame_start_us = board_us(); /* the render starts next (main.c) */
}
