// st7789.mjs - the ST7789 panel as run.mjs decodes it: the controller's
// commands and data (as SPI0 sent them, each byte with the data/command
// line) into its frame memory, and the frame as rt's stream.
import { Buffer } from 'node:buffer';

const PANEL_W = 320, PANEL_H = 240;

const CMD = { 0x01: 'SWRESET', 0x11: 'SLPOUT', 0x13: 'NORON', 0x21: 'INVON', 0x29: 'DISPON',
              0x2a: 'CASET', 0x2b: 'RASET', 0x2c: 'RAMWR', 0x36: 'MADCTL', 0x3a: 'COLMOD' };
const PARAMS = { SWRESET: 0, SLPOUT: 0, NORON: 0, INVON: 0, DISPON: 0, CASET: 4, RASET: 4, MADCTL: 1, COLMOD: 1 };

// log: pairs of bytes (data/command line, value). Returns the panel's
// pixels (row-major rgb565be, PANEL_W x PANEL_H) and which were written.
export function decodePanel(log) {
  if (log.length % 2) throw new Error(`SPI log of ${log.length} bytes is not pairs`);
  const mem = new Uint8Array(PANEL_W * PANEL_H * 2), written = new Uint8Array(PANEL_W * PANEL_H);
  let cmd = null, at = 0, params = [], data = 0, hi = -1;
  let cols = null, rows = null, madctl = null, colmod = null, awake = false, on = false, x = 0, y = 0;
  const where = () => `SPI byte ${at / 2}`;
  const finish = () => {
    if (cmd === 'RAMWR') {
      const want = (cols[1] - cols[0] + 1) * (rows[1] - rows[0] + 1) * 2;
      if (data !== want)
        throw new Error(`${where()}: RAMWR sent ${data} bytes for a ${cols[1] - cols[0] + 1}x${rows[1] - rows[0] + 1} window of ${want} (short or long data)`);
    } else if (cmd !== null && params.length !== PARAMS[cmd]) {
      throw new Error(`${where()}: ${cmd} takes ${PARAMS[cmd]} parameter bytes, got ${params.length}`);
    }
    if (cmd === 'CASET' || cmd === 'RASET') {
      const lo = params[0] << 8 | params[1], top = params[2] << 8 | params[3];
      const size = cmd === 'CASET' ? PANEL_W : PANEL_H;
      if (lo > top || top >= size) throw new Error(`${where()}: ${cmd} ${lo}..${top} is not a window of the ${PANEL_W}x${PANEL_H} panel (wrong window)`);
      if (cmd === 'CASET') cols = [lo, top]; else rows = [lo, top];
    } else if (cmd === 'MADCTL') {
      if (params[0] !== 0x20) throw new Error(`${where()}: MADCTL 0x${params[0].toString(16)}: only 0x20 (landscape, 320 columns) is modelled`);
      madctl = params[0];
    } else if (cmd === 'COLMOD') {
      colmod = params[0];
    } else if (cmd === 'SWRESET') {
      awake = on = false; madctl = colmod = null;
    } else if (cmd === 'SLPOUT') {
      awake = true;
    } else if (cmd === 'DISPON') {
      on = true;
    }
  };
  for (at = 0; at < log.length; at += 2) {
    const dc = log[at], v = log[at + 1];
    if (!dc) {
      finish();
      cmd = CMD[v];
      if (!cmd) throw new Error(`${where()}: command 0x${v.toString(16)} is not one the decoder knows`);
      params = []; data = 0; hi = -1;
      if (cmd === 'RAMWR') {
        if (!cols || !rows) throw new Error(`${where()}: RAMWR before CASET and RASET`);
        if (!awake || !on || colmod !== 0x55 || madctl === null)
          throw new Error(`${where()}: RAMWR before sleep out, display on, COLMOD 0x55 (16-bit colour) and MADCTL`);
        x = cols[0]; y = rows[0];
      }
    } else if (cmd === 'RAMWR') {
      data++;
      if (hi < 0) { hi = v; continue; }
      if (y > rows[1]) continue; // more than the window: finish() reports it
      const i = y * PANEL_W + x;
      mem[2 * i] = hi; mem[2 * i + 1] = v; written[i] = 1; hi = -1;
      if (++x > cols[1]) { x = cols[0]; y++; }
    } else if (cmd !== null && params.length < PARAMS[cmd]) {
      params.push(v);
    } else {
      throw new Error(`${where()}: data byte 0x${v.toString(16)} after ${cmd ?? 'no command'} takes no more`);
    }
  }
  finish();
  return { mem, written };
}

// The top left w x h of the panel as rt's stream: header, one band, end.
export function panelStream(panel, w, h) {
  if (!(w >= 1 && w <= PANEL_W && h >= 1 && h <= PANEL_H)) throw new Error(`a ${w}x${h} frame is not on the ${PANEL_W}x${PANEL_H} panel`);
  const px = new Uint8Array(w * h * 2);
  for (let y = 0; y < h; y++)
    for (let x = 0; x < w; x++) {
      const i = y * PANEL_W + x;
      if (!panel.written[i]) throw new Error(`panel pixel ${x},${y} of the frame was never written`);
      px[2 * (y * w + x)] = panel.mem[2 * i];
      px[2 * (y * w + x) + 1] = panel.mem[2 * i + 1];
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

