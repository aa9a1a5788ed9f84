// st7789.mjs - the ST7789 panel as run.mjs decodes it: the controller's
// commands and data, as SPI0 sent them, into its frame memory, and the
// picture a viewer sees on the module, as rt's stream.
//
// The controller (ST7789V datasheet): frame memory of 240 columns x 320
// rows. CASET and RASET set the window, RAMWR fills it left to right, top
// to bottom, in window addresses; MADCTL maps window addresses onto the
// memory: MV exchanges columns and rows (the window is then up to 320
// columns wide), then MX mirrors memory columns and MY memory rows; RGB
// (0x08) swaps red and blue; ML and MH only change the refresh order.
//
// The module: which part of the memory its glass shows, and which way up,
// as the module's maker's own driver sets it (Pimoroni's):
//   320x240 (Display Pack 2.0): all of it, upright as MADCTL 0x70 writes it
//   240x240 (1.3" square): memory rows 0..239, upright as MADCTL 0 writes it
// flipped (the module turned by 180 degrees): upright as 0xb0, or as 0xc0
// with the rows from 80, write it. Both are IPS glass, which shows every
// colour inverted unless INVON is in force. So a picture written with a
// MADCTL that mirrors or turns it, a window without the module's row
// offset, or no INVON decodes to a different image, and the comparison
// with the host fails.
//
// The SPI log: a pair of bytes per event. A byte the SPI sent: flags
// (bit 0 the data/command line, 1 data; bit 1 chip select, 1 high) and the
// byte. Chip select going high between bytes: 0x80, 0. The decoder is
// strict: a byte sent with chip select high, a command it does not know, a
// parameter count the datasheet does not give, a window outside the
// memory, RAMWR data that does not fill its window exactly, pixels before
// sleep out, 16-bit colour and MADCTL, or a frame pixel never written: each
// fails with the byte offset in the log. What it accepts but does not
// model: the panel's voltage, gamma and timing settings (porch, gate,
// VCOM, power, frame rate), and tearing-effect output.
import { Buffer } from 'node:buffer';

const MEM_COLS = 240, MEM_ROWS = 320;
const EVENT_CS_HIGH = 0x80;

export const PANELS = {
  '320x240': { width: 320, height: 240, madctl: [0x70, 0xb0], rowOffset: [0, 0] },
  '240x240': { width: 240, height: 240, madctl: [0x00, 0xc0], rowOffset: [0, 80] },
};

// name, and the parameter bytes it takes: [fewest, most]
const CMD = {
  0x01: ['SWRESET', 0, 0], 0x10: ['SLPIN', 0, 0], 0x11: ['SLPOUT', 0, 0], 0x12: ['PTLON', 0, 0],
  0x13: ['NORON', 0, 0], 0x20: ['INVOFF', 0, 0], 0x21: ['INVON', 0, 0], 0x26: ['GAMSET', 1, 1],
  0x28: ['DISPOFF', 0, 0], 0x29: ['DISPON', 0, 0], 0x2a: ['CASET', 4, 4], 0x2b: ['RASET', 4, 4],
  0x2c: ['RAMWR', 0, Infinity], 0x34: ['TEOFF', 0, 0], 0x35: ['TEON', 0, 1], 0x36: ['MADCTL', 1, 1],
  0x3a: ['COLMOD', 1, 1], 0xb2: ['PORCTRL', 5, 5], 0xb7: ['GCTRL', 1, 1], 0xbb: ['VCOMS', 1, 1],
  0xc0: ['LCMCTRL', 1, 1], 0xc2: ['VDVVRHEN', 1, 2], 0xc3: ['VRHS', 1, 1], 0xc4: ['VDVS', 1, 1],
  0xc6: ['FRCTRL2', 1, 1], 0xd0: ['PWCTRL1', 2, 2], 0xd6: ['D6h', 1, 1], 0xe0: ['PVGAMCTRL', 14, 14],
  0xe1: ['NVGAMCTRL', 14, 14],
};

// The memory index where MADCTL m puts window address (x, y), or -1.
function place(m, x, y) {
  let c = x, r = y;
  if (m & 0x20) { c = y; r = x; }
  if (m & 0x40) c = MEM_COLS - 1 - c;
  if (m & 0x80) r = MEM_ROWS - 1 - r;
  return c >= 0 && c < MEM_COLS && r >= 0 && r < MEM_ROWS ? r * MEM_COLS + c : -1;
}

// log: the SPI log (above); panelName: a key of PANELS; flip: 0 or 1.
// Returns the module's picture: width, height, pixels (row-major
// rgb565be) and which were written.
export function decodePanel(log, panelName = '320x240', flip = 0) {
  const panel = PANELS[panelName];
  if (!panel) throw new Error(`panel ${panelName} is not one of ${Object.keys(PANELS).join(', ')}`);
  if (log.length % 2) throw new Error(`SPI log of ${log.length} bytes is not pairs`);
  const mem = new Uint16Array(MEM_COLS * MEM_ROWS), memWritten = new Uint8Array(MEM_COLS * MEM_ROWS);
  let cmd = null, name = null, at = 0, params = [], data = 0, hi = -1;
  let cols = null, rows = null, madctl = 0, madctlSet = false, colmod = null, awake = false, invert = false;
  let x = 0, y = 0;
  const where = () => `SPI byte ${at / 2}`;
  const finish = () => {
    if (cmd === null) return;
    const [, fewest, most] = CMD[cmd];
    if (name === 'RAMWR') {
      const want = (cols[1] - cols[0] + 1) * (rows[1] - rows[0] + 1) * 2;
      if (data !== want)
        throw new Error(`${where()}: RAMWR sent ${data} bytes for a ${cols[1] - cols[0] + 1}x${rows[1] - rows[0] + 1} window of ${want} (short or long data)`);
    } else if (params.length < fewest || params.length > most) {
      throw new Error(`${where()}: ${name} takes ${fewest === most ? fewest : `${fewest} to ${most}`} parameter bytes, got ${params.length}`);
    }
    if (name === 'CASET' || name === 'RASET') {
      const lo = params[0] << 8 | params[1], top = params[2] << 8 | params[3];
      if (lo > top) throw new Error(`${where()}: ${name} ${lo}..${top} is not a window (wrong window)`);
      if (name === 'CASET') cols = [lo, top]; else rows = [lo, top];
    } else if (name === 'MADCTL') {
      madctl = params[0]; madctlSet = true;
    } else if (name === 'COLMOD') {
      colmod = params[0];
    } else if (name === 'SWRESET') {
      awake = invert = madctlSet = false; madctl = 0; colmod = null;
    } else if (name === 'SLPOUT') {
      awake = true;
    } else if (name === 'SLPIN') {
      awake = false;
    } else if (name === 'INVON' || name === 'INVOFF') {
      invert = name === 'INVON';
    }
    cmd = name = null;
  };
  for (at = 0; at < log.length; at += 2) {
    const flags = log[at], v = log[at + 1];
    if (flags & EVENT_CS_HIGH) { finish(); continue; } // chip select ends a command
    if (flags & 2) throw new Error(`${where()}: 0x${v.toString(16)} sent while chip select was high: the panel ignores it`);
    if (!(flags & 1)) {
      finish();
      if (!CMD[v]) throw new Error(`${where()}: command 0x${v.toString(16)} is not one the decoder knows`);
      cmd = v; name = CMD[v][0]; params = []; data = 0; hi = -1;
      if (name === 'RAMWR') {
        if (!cols || !rows) throw new Error(`${where()}: RAMWR before CASET and RASET`);
        if (!awake || colmod === null || (colmod & 7) !== 5 || !madctlSet)
          throw new Error(`${where()}: RAMWR before sleep out, COLMOD 0x55 (16-bit colour) and MADCTL`);
        const [w, h] = madctl & 0x20 ? [MEM_ROWS, MEM_COLS] : [MEM_COLS, MEM_ROWS];
        if (cols[1] >= w || rows[1] >= h)
          throw new Error(`${where()}: window ${cols[0]}..${cols[1]} x ${rows[0]}..${rows[1]} is outside the ${w}x${h} memory as MADCTL 0x${madctl.toString(16)} addresses it (wrong window)`);
        x = cols[0]; y = rows[0];
      }
    } else if (name === 'RAMWR') {
      data++;
      if (hi < 0) { hi = v; continue; }
      if (y > rows[1]) continue; // more than the window: finish() reports it
      const i = place(madctl, x, y);
      let px = hi << 8 | v;
      if (madctl & 0x08) px = (px & 0x1f) << 11 | (px & 0x07e0) | px >> 11; // BGR
      mem[i] = px; memWritten[i] = 1; hi = -1;
      if (++x > cols[1]) { x = cols[0]; y++; }
    } else if (name !== null && params.length < CMD[cmd][2]) {
      params.push(v);
    } else {
      throw new Error(`${where()}: data byte 0x${v.toString(16)} after ${name ?? 'no command'} takes no more`);
    }
  }
  finish();
  // what the glass shows
  const { width, height } = panel, view = panel.madctl[flip ? 1 : 0], offset = panel.rowOffset[flip ? 1 : 0];
  const pixels = new Uint8Array(width * height * 2), written = new Uint8Array(width * height);
  for (let v = 0; v < height; v++)
    for (let u = 0; u < width; u++) {
      const i = place(view, u, v + offset), o = v * width + u;
      const px = mem[i] ^ (invert ? 0 : 0xffff); // IPS glass: inverted without INVON
      pixels[2 * o] = px >> 8; pixels[2 * o + 1] = px & 0xff; written[o] = memWritten[i];
    }
  return { width, height, pixels, written, madctl, module: view, offset };
}

// Why a frame pixel shows nothing: the window's pixels went elsewhere.
function unwritten(picture, x, y) {
  const { madctl, module, offset } = picture;
  const hint = madctl !== undefined && (madctl & 0xe0) !== (module & 0xe0)
    ? `: MADCTL 0x${madctl.toString(16)} put the frame elsewhere in the memory than the module's 0x${module.toString(16)}${offset ? ` (rows from ${offset})` : ''} shows upright (mirrored, turned or off the glass)`
    : offset ? `: is the window offset by the module's ${offset} rows?` : '';
  return new Error(`panel pixel ${x},${y} of the frame was never written${hint}`);
}

// Where a w x h frame sits on the module's picture: centred (st7789.c),
// rounded towards the top left.
export function frameOrigin(picture, w, h) {
  const { width, height } = picture;
  if (!(w >= 1 && w <= width && h >= 1 && h <= height)) throw new Error(`a ${w}x${h} frame is not on the ${width}x${height} panel`);
  return [(width - w) >> 1, (height - h) >> 1];
}

// Every pixel of the picture outside the centred w x h frame was written
// and is black (the firmware clears the panel first): else what the glass
// shows around the frame is whatever the memory held at power-up.
export function checkBorder(picture, w, h) {
  const { width, height } = picture, [x0, y0] = frameOrigin(picture, w, h);
  for (let y = 0; y < height; y++)
    for (let x = 0; x < width; x++) {
      if (x >= x0 && x < x0 + w && y >= y0 && y < y0 + h) continue;
      const i = y * width + x;
      if (!picture.written[i]) throw new Error(`panel pixel ${x},${y}, outside the ${w}x${h} frame at ${x0},${y0}, was never written: the panel was not cleared`);
      if (picture.pixels[2 * i] | picture.pixels[2 * i + 1])
        throw new Error(`panel pixel ${x},${y}, outside the ${w}x${h} frame at ${x0},${y0}, is 0x${(picture.pixels[2 * i] << 8 | picture.pixels[2 * i + 1]).toString(16).padStart(4, '0')}, not black`);
    }
  return [x0, y0];
}

// The w x h of the module's picture at x0, y0 (the whole panel by
// default) as rt's stream: header, one band, end (the stream format of
// app/firmware/sink.h).
export function panelStream(picture, w = picture.width, h = picture.height, x0 = 0, y0 = 0) {
  const { width, height } = picture;
  if (!(w >= 1 && x0 >= 0 && x0 + w <= width && h >= 1 && y0 >= 0 && y0 + h <= height)) throw new Error(`a ${w}x${h} frame at ${x0},${y0} is not on the ${width}x${height} panel`);
  const px = new Uint8Array(w * h * 2);
  for (let y = 0; y < h; y++)
    for (let x = 0; x < w; x++) {
      const i = (y0 + y) * width + x0 + x;
      if (!picture.written[i]) throw unwritten(picture, x0 + x, y0 + y);
      px[2 * (y * w + x)] = picture.pixels[2 * i];
      px[2 * (y * w + x) + 1] = picture.pixels[2 * i + 1];
    }
  let a = 1, b = 0;
  for (const v of px) { a = (a + v) % 65521; b = (b + a) % 65521; }
  const adler = ((b << 16) | a) >>> 0;
  const out = Buffer.alloc(9 + 5 + px.length + 4 + 5);
  out.write('RTF1', 0, 'latin1');
  out[4] = 2; // RT_FB_RGB565BE
  out.writeUInt16LE(w, 5); out.writeUInt16LE(h, 7);
  out[9] = 0x42; out.writeUInt16LE(0, 10); out.writeUInt16LE(h, 12);
  out.set(px, 14);
  out.writeUInt32LE(adler, 14 + px.length);
  out[18 + px.length] = 0x45; out.writeUInt32LE(adler, 19 + px.length);
  return out;
}
