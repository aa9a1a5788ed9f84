/*
 * oled.c - the LM3S6965 evaluation board's display (sink.h): the SSD0323
 * controller of its 128x64 OLED, 4-bit grey, on SSI0 (a PL022), with the
 * data/command line on GPIO C7 and the chip select on GPIO D0.
 *
 * Each band goes to the panel as it is flushed, so there is no frame
 * buffer: a column window (0x15, first, last column; one column is a
 * byte, two pixels), a row window (0x75, first, last row), then the
 * band's bytes as data, which the controller stores along the row and
 * wraps within the window. The core's L4 packing (rt_fb.h: two pixels
 * per byte, the left one in the high nibble) is the controller's own, so
 * the bytes go out as rendered. A frame smaller than the panel is drawn
 * at its top left; after it the sink reports frame_width and
 * frame_height, which tell the host what part of the panel to take.
 *
 * The frame stays on the panel (SINK_HOLDS_FRAME, board.mk): the firmware
 * reports "drawn 1" and idles while the host captures the panel
 * (tools/emu/lm3s6965evb/run.sh).
 * Only what QEMU's SSD0323 model acts on is sent; a real panel also needs
 * its power-up sequence (supply, contrast, multiplex, remap).
 */
#include "../arch/cortex-m/pl022.h"
#include "../mmio.h"
#include "port.h"
#include "sink.h"

#define PANEL_WIDTH 128
#define PANEL_HEIGHT 64

#if defined(BOARD_WIDTH) && defined(BOARD_HEIGHT)
_Static_assert(BOARD_WIDTH <= PANEL_WIDTH && BOARD_HEIGHT <= PANEL_HEIGHT, "the frame is larger than the 128x64 OLED (SIZE)");
#endif
#ifdef RT_FB_ONLY_FORMAT
_Static_assert(RT_FB_ONLY_FORMAT == RT_FB_L4, "the OLED takes l4 pixels (FW_FORMAT in board.mk)");
#endif

#define SSI0 0x40008000u /* a PL022 */

/* GPIO C and D: direction, digital enable, and the data register masked
 * to one pin (address bits 9..2 select the pins a write changes) */
#define GPIOC_DIR REG(0x40006400u)
#define GPIOC_DEN REG(0x4000651Cu)
#define OLED_DC REG(0x40006000u + (0x80u << 2)) /* C7: low command, high data */
#define OLED_DC_DATA 0x80u
#define GPIOD_DIR REG(0x40007400u)
#define GPIOD_DEN REG(0x4000751Cu)
#define OLED_CS REG(0x40007000u + (0x01u << 2)) /* D0 */

/* SSD0323 commands */
#define SSD_COLUMNS 0x15u
#define SSD_ROWS 0x75u
#define SSD_DISPLAY_ON 0xAFu

static size_t line_bytes;
static uint16_t frame_width, frame_height;

static void oled_send(uint32_t dc, const uint8_t *p, size_t n)
{
    OLED_DC = dc;
    for (size_t i = 0; i < n; i++)
        pl022_send(SSI0, p[i]);
}

static int oled_begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    if (s->format != RT_FB_L4 || w > PANEL_WIDTH || h > PANEL_HEIGHT)
        return 1;
    sink_io_begin();
    line_bytes = RT_FB_LINE_BYTES(RT_FB_L4, w);
    frame_width = w;
    frame_height = h;
    static const uint8_t on[] = { SSD_DISPLAY_ON };
    oled_send(0, on, sizeof on);
    sink_io_end();
    return 0;
}

static int oled_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    sink_io_begin();
    const uint8_t window[] = { SSD_COLUMNS, 0, (uint8_t)(line_bytes - 1), SSD_ROWS, (uint8_t)a->y1, (uint8_t)a->y2 };
    oled_send(0, window, sizeof window);
    oled_send(OLED_DC_DATA, px, (size_t)(a->y2 - a->y1 + 1) * line_bytes);
    rt_fb_flush_ready(s); /* the bytes are out */
    sink_io_end();
    return 0;
}

static int oled_end(rt_fb_sink_t *s)
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
    GPIOC_DIR |= 0x80u;
    GPIOC_DEN |= 0x80u;
    GPIOD_DIR |= 0x01u;
    GPIOD_DEN |= 0x01u;
    OLED_CS = 0x01u;
    PL022_CR1(SSI0) = 0;    /* disabled while it is set up */
    PL022_CPSR(SSI0) = 2;   /* 50 MHz / 2 / (1 + 6) = 3.6 MHz, under the SSD0323's 4 MHz */
    PL022_CR0(SSI0) = 6u << 8 | 3u << 6 | 7u; /* serial clock rate 6, SPI mode 3, 8-bit frames */
    PL022_CR1(SSI0) = 0x02u; /* enabled, master */
    sink->format = format;
    sink->band[0] = band;
    sink->band[1] = 0;
    sink->band_bytes = bytes;
    sink->pitch = 0;
    sink->begin = oled_begin;
    sink->flush = oled_flush;
    sink->wait = 0;
    sink->end = oled_end;
    sink->user = 0;
    sink->flushing = false;
}
