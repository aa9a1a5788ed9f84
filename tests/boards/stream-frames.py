#!/usr/bin/env python3
"""stream-frames.py A.stream B.stream: whether two UART streams (format in
app/firmware/sink.h) carry the same frame: the same header, band
records (position, lines, pixels, checksum) and end record, in the same
order. Report ('T') records may differ. Prints what it compared; exit 1
on a difference or a malformed stream."""
import os
import re
import struct
import sys

# bits per pixel by format value, from the one list (RT_FB_FORMATS, include/rt_fb.h)
RT_FB_H = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "include", "rt_fb.h")
FORMAT_BITS = {int(v): int(b) for v, b in re.findall(r'X\(RT_FB_\w+, "\w+", (\d+), (\d+)\)', open(RT_FB_H).read())}


def frame_records(path):
    data = open(path, "rb").read()
    i, out, line_bytes = 0, [], None
    while i < len(data):
        tag = data[i:i + 1]
        if data[i:i + 4] == b"RTF1":
            fmt, w, h = struct.unpack_from("<BHH", data, i + 4)
            line_bytes = (w * FORMAT_BITS[fmt] + 7) // 8
            out.append(data[i:i + 9])
            i += 9
        elif tag == b"B" and line_bytes is not None:
            y, lines = struct.unpack_from("<HH", data, i + 1)
            n = 5 + lines * line_bytes + 4
            out.append(data[i:i + n])
            i += n
        elif tag == b"E":
            out.append(data[i:i + 5])
            i += 5
        elif tag == b"T":
            (n,) = struct.unpack_from("<H", data, i + 1)
            i += 3 + n
        else:
            raise ValueError("%s: unknown record %r at byte %d" % (path, tag, i))
    return out


def main():
    try:
        a, b = frame_records(sys.argv[1]), frame_records(sys.argv[2])
    except (OSError, ValueError, struct.error, KeyError) as e:
        print(e)
        return 1
    if a != b:
        print("frame records differ (%d vs %d records)" % (len(a), len(b)))
        return 1
    print("%d frame records byte-identical (%d bands)" % (len(a), len(a) - 2))
    return 0


sys.exit(main())
