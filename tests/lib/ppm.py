"""Binary PPM (P6, 8-bit) for the shell tests: read, and crop from the
command line (python3 tests/lib/ppm.py crop IN X Y W H OUT)."""
import sys


def read(path):
    """(width, height, pixel bytes R, G, B) of a binary PPM."""
    d = open(path, 'rb').read()
    parts, i = [], 0
    while len(parts) < 4:
        while d[i:i + 1].isspace():
            i += 1
        j = i
        while not d[j:j + 1].isspace():
            j += 1
        parts.append(d[i:j])
        i = j
    assert parts[0] == b'P6' and parts[3] == b'255', path + ': not an 8-bit binary PPM'
    w, h = int(parts[1]), int(parts[2])
    px = d[i + 1:]
    assert len(px) == w * h * 3, path + ': truncated'
    return w, h, px


def crop(src, x, y, cw, ch, dst):
    w, _, px = read(src)
    rows = [px[((y + r) * w + x) * 3:((y + r) * w + x + cw) * 3] for r in range(ch)]
    open(dst, 'wb').write(b'P6\n%d %d\n255\n' % (cw, ch) + b''.join(rows))


if __name__ == '__main__' and len(sys.argv) == 8 and sys.argv[1] == 'crop':
    crop(sys.argv[2], *map(int, sys.argv[3:7]), sys.argv[7])
