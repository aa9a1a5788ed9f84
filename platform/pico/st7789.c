/*
 * st7789.c - the Pico's display (sink.h): an ST7789 320x240 colour panel
 * on SPI0, RGB565 big-endian (the core's rgb565be bytes go out as
 * rendered), each band sent by DMA while the core renders the next.
 *
 * Pins as on Pimoroni's Pico Display Pack 2.0 (ST7789, 320x240): SPI0
 * SCK GP18, TX GP19, chip select GP17, data/command GP16 (low: command),
 * backlight GP20. Per band: wait for the last transfer, then CASET and
 * RASET (the band's window), RAMWR, and the band's bytes by DMA channel 0
 * paced by SPI0's transmit request. A frame smaller than the panel is
 * drawn at its top left; the sink then reports frame_width and
 * frame_height, which tell run.mjs what part of the panel to take.
 *
 * The init sequence and timings are the controller's datasheet's
 * (software reset, sleep out, 16-bit colour, landscape, inversion on for
 * IPS glass, display on). Written for a real module and checked only
 * against run.mjs's decoder: untested on hardware. A real Pico also needs
 * what the emulator does without: a boot2 stage before the vector table,
 * and clk_sys raised to 125 MHz from the PLL (the delays below count
 * cycles at 125 MHz, so at a slower clock they only grow).
 */
#include "../arch/cortex-m/pl022.h"
#include "port.h"
#include "sink.h"

#define PANEL_WIDTH 320
#define PANEL_HEIGHT 240

#if defined(BOARD_WIDTH) && defined(BOARD_HEIGHT)
_Static_assert(BOARD_WIDTH <= PANEL_WIDTH && BOARD_HEIGHT <= PANEL_HEIGHT, "the frame is larger than the 320x240 panel (SIZE)");
#endif
#ifdef RT_FB_ONLY_FORMAT
_Static_assert(RT_FB_ONLY_FORMAT == RT_FB_RGB565BE, "the ST7789 takes rgb565be pixels (FW_FORMAT in board.mk)");
#endif

#define REG(addr) (*(volatile uint32_t *)(addr))

#define SPI0 0x4003c000u /* a PL022 */
#define RESETS_RESET_CLR REG(0x4000f000u)
#define RESETS_DONE REG(0x4000c008u)
#define RESET_DMA (1u << 2)
#define RESET_SPI0 (1u << 16)
#define CLK_PERI_CTRL REG(0x40008048u)
#define CLK_PERI_ENABLE (1u << 11) /* auxiliary source 0: clk_sys */
#define GPIO_CTRL(n) REG(0x40014004u + 8u * (n))
#define FUNC_SPI 1u
#define FUNC_SIO 5u
#define SIO_GPIO_OUT_SET REG(0xd0000014u)
#define SIO_GPIO_OUT_CLR REG(0xd0000018u)
#define SIO_GPIO_OE_SET REG(0xd0000024u)
#define PIN_DC 16u
#define PIN_CS 17u
#define PIN_SCK 18u
#define PIN_TX 19u
#define PIN_BACKLIGHT 20u

/* DMA channel 0 */
#define DMA_READ_ADDR REG(0x50000000u)
#define DMA_WRITE_ADDR REG(0x50000004u)
#define DMA_TRANS_COUNT REG(0x50000008u)
#define DMA_CTRL_TRIG REG(0x5000000cu)
#define DMA_EN (1u << 0)
#define DMA_INCR_READ (1u << 4)
#define DMA_CHAIN_TO_SELF (0u << 11) /* chaining to itself: none */
#define DMA_TREQ_SPI0_TX (16u << 15)
#define DMA_BUSY (1u << 24)

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
#define MADCTL_LANDSCAPE 0x20u /* MV: rows and columns exchanged, 320 columns */
#define COLMOD_RGB565 0x55u

static uint16_t frame_width, frame_height;

/* At least `cycles` processor cycles (3 a turn on the M0+). */
static void delay_cycles(uint32_t cycles)
{
    for (uint32_t n = cycles / 3u + 1u; n != 0; n--)
        __asm__ volatile("");
}

static void send(uint8_t cmd, const uint8_t *params, unsigned n)
{
    SIO_GPIO_OUT_CLR = 1u << PIN_DC;
    pl022_send(SPI0, cmd);
    SIO_GPIO_OUT_SET = 1u << PIN_DC;
    for (unsigned i = 0; i < n; i++)
        pl022_send(SPI0, params[i]);
}

/* The last band's transfer done and the bus idle: the buffer is free. */
static void transfer_wait(rt_fb_sink_t *s)
{
    sink_io_begin();
    while (DMA_CTRL_TRIG & DMA_BUSY)
        ;
    pl022_idle(SPI0);
    PL022_ICR(SPI0) = 1u; /* what came back overran the receive FIFO */
    rt_fb_flush_ready(s);
    sink_io_end();
}

static int panel_begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    if (s->format != RT_FB_RGB565BE || w > PANEL_WIDTH || h > PANEL_HEIGHT)
        return 1;
    frame_width = w;
    frame_height = h;
    return 0;
}

static int panel_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    (void)s;
    sink_io_begin();
    /* the other buffer's transfer is done: the core waited for it */
    const uint8_t cols[] = { (uint8_t)(a->x1 >> 8), (uint8_t)a->x1, (uint8_t)(a->x2 >> 8), (uint8_t)a->x2 };
    const uint8_t rows[] = { (uint8_t)(a->y1 >> 8), (uint8_t)a->y1, (uint8_t)(a->y2 >> 8), (uint8_t)a->y2 };
    send(ST_CASET, cols, sizeof cols);
    send(ST_RASET, rows, sizeof rows);
    send(ST_RAMWR, 0, 0);
    DMA_READ_ADDR = (uint32_t)(uintptr_t)px;
    DMA_WRITE_ADDR = (uint32_t)(uintptr_t)&PL022_DR(SPI0);
    DMA_TRANS_COUNT = (uint32_t)(a->y2 - a->y1 + 1) * (uint32_t)(a->x2 - a->x1 + 1) * 2u;
    DMA_CTRL_TRIG = DMA_EN | DMA_INCR_READ | DMA_CHAIN_TO_SELF | DMA_TREQ_SPI0_TX;
    sink_io_end();
    return 0; /* rt_fb_flush_ready() comes from transfer_wait() */
}

static int panel_end(rt_fb_sink_t *s)
{
    (void)s;
    sink_io_begin();
    report_value("frame_width", frame_width);
    report_value("frame_height", frame_height);
    sink_io_end();
    return 0;
}

void sink_init(rt_fb_sink_t *sink, rt_fb_format_t format, uint8_t *band, size_t bytes)
{
    RESETS_RESET_CLR = RESET_DMA | RESET_SPI0;
    while ((RESETS_DONE & (RESET_DMA | RESET_SPI0)) != (RESET_DMA | RESET_SPI0))
        ;
    CLK_PERI_CTRL = CLK_PERI_ENABLE;
    GPIO_CTRL(PIN_SCK) = FUNC_SPI;
    GPIO_CTRL(PIN_TX) = FUNC_SPI;
    GPIO_CTRL(PIN_DC) = FUNC_SIO;
    GPIO_CTRL(PIN_CS) = FUNC_SIO;
    GPIO_CTRL(PIN_BACKLIGHT) = FUNC_SIO;
    SIO_GPIO_OUT_SET = 1u << PIN_DC | 1u << PIN_BACKLIGHT;
    SIO_GPIO_OUT_CLR = 1u << PIN_CS; /* the panel is the bus's only device */
    SIO_GPIO_OE_SET = 1u << PIN_DC | 1u << PIN_CS | 1u << PIN_BACKLIGHT;
    PL022_CR1(SPI0) = 0;          /* disabled while it is set up */
    PL022_CPSR(SPI0) = 2;         /* 125 MHz / 2 = 62.5 MHz, the ST7789's fastest write clock */
    PL022_CR0(SPI0) = 3u << 6 | 7u; /* SPI mode 3, 8-bit frames */
    PL022_DMACR(SPI0) = 2u;       /* transmit requests to the DMA */
    PL022_CR1(SPI0) = 2u;         /* enabled, master */

    static const uint8_t colmod[] = { COLMOD_RGB565 }, madctl[] = { MADCTL_LANDSCAPE };
    send(ST_SWRESET, 0, 0);
    delay_cycles(125000u * 120u); /* 120 ms before sleep out */
    send(ST_SLPOUT, 0, 0);
    delay_cycles(125000u * 5u);   /* 5 ms before the next command */
    send(ST_COLMOD, colmod, 1);
    send(ST_MADCTL, madctl, 1);
    send(ST_INVON, 0, 0);
    send(ST_NORON, 0, 0);
    send(ST_DISPON, 0, 0);

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
    sink->user = 0;
    sink->flushing = false;
}
