"""The progressive display's picture after pass N, from the finished
image alone: the passes of an interlaced 8x8 lattice (Adam7's) leave
cells of 8x8, 4x8, 4x4, 2x4, 2x2, 1x2 and 1x1 pixels after passes 1..7,
and each pixel shows the pixel at its cell's top left corner (frame
coordinates; the viewport lies on the 8-pixel grid).

    python3 tests/host/progressive_rule.py FINAL.ppm N X0 Y0 OUT.ppm
        writes the picture after pass N of a viewport whose top left
        frame pixel is (X0, Y0), and prints the samples traced so far
        (the lattice's points in the viewport)."""
import os
import sys

# the shared PPM reader of tests/lib/
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import ppm  # noqa: E402

CELLS = [(8, 8), (4, 8), (4, 4), (2, 4), (2, 2), (1, 2), (1, 1)]


def after_pass(w, h, px, n, x0=0, y0=0):
    cw, ch = CELLS[n - 1]
    out = bytearray(len(px))
    for y in range(h):
        sy = (y0 + y) // ch * ch - y0
        for x in range(w):
            sx = (x0 + x) // cw * cw - x0
            s = (sy * w + sx) * 3
            out[(y * w + x) * 3:(y * w + x) * 3 + 3] = px[s:s + 3]
    samples = sum(1 for y in range(h) for x in range(w) if (x0 + x) % cw == 0 and (y0 + y) % ch == 0)
    return bytes(out), samples


if __name__ == '__main__':
    src, n, x0, y0, dst = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
    w, h, px = ppm.read(src)
    out, samples = after_pass(w, h, px, n, x0, y0)
    open(dst, 'wb').write(b'P6\n%d %d\n255\n' % (w, h) + out)
    print(samples)
