#!/bin/sh
# run.sh FIRMWARE.elf OUT.png RT [CLOCK_HZ]: the LM3S6965 board's
# BOARD_RUN. Starts the firmware under QEMU ($QEMU, from board.mk) with the
# monitor on a unix socket and UART0 into a file, waits until its report
# says "drawn", dumps the OLED through the monitor (screendump) and quits
# QEMU. Then it prints the report lines (rt receive --report-only on the
# UART file), turns the dump into OUT.png and prints how long QEMU took.
#
# The dump is 512x256 RGB: QEMU draws each of the panel's 128x64 pixels
# as a 4x4 block of grey 17*v (v = 0..15). Every block must be uniform
# with R = G = B = 17*v, or the run fails; the v of the frame's part of
# the panel (frame_width x frame_height of the report) become an L4 frame
# in rt's own stream format, which `rt receive` writes as OUT.png, with
# the same expansion (rt_fb_expand) as `rt --format l4` on the host.
# Exits non-zero when QEMU, the firmware, the capture or a decoder fails.

# panel_stream DUMP.ppm W H OUT.stream: the top left WxH panel pixels of
# the dump as an L4 frame in rt's stream format (sink.h): header, one band
# of all H lines, frame end. The dump's bytes go through awk as decimal
# numbers and come back as octal escapes for printf.
panel_stream() {
    bytes=$(od -An -v -tu1 "$1" | awk -v w="$2" -v h="$3" '
        function fail(msg) { print "lm3s6965evb run: screendump: " msg > "/dev/stderr"; bad = 1; exit 1 }
        function put(b) { s = s sprintf("\\%03o", b) }
        function put16(v) { put(v % 256); put(int(v / 256) % 256) }
        function put32(v) { put16(v % 65536); put16(int(v / 65536)) }
        BEGIN {
            split("80 54 10 53 49 50 32 50 53 54 10 50 53 53 10", want, " "); n = 0
            if (w !~ /^[0-9]+$/ || h !~ /^[0-9]+$/ || w < 1 || w > 128 || h < 1 || h > 64)
                fail("a frame of " w "x" h " is not on the 128x64 panel")
        }
        {
            for (f = 1; f <= NF; f++) {
                if (n < 15) {
                    if ($f != want[n + 1]) fail("not a 512x256 P6 PPM with maxval 255")
                } else {
                    p = n - 15; c = p % 3; px = int(p / 3); x = px % 512; y = int(px / 512)
                    if (c == 0) r = $f
                    else if ($f != r) fail(sprintf("pixel %d,%d is not grey", x, y))
                    else if (c == 2) {
                        if (r % 17) fail(sprintf("pixel %d,%d: %d is not a 4-bit grey (17 v)", x, y, r))
                        k = int(y / 4) * 128 + int(x / 4)
                        if (x % 4 == 0 && y % 4 == 0) v[k] = r / 17
                        else if (v[k] != r / 17) fail(sprintf("the 4x4 block of panel pixel %d,%d is not uniform", int(x / 4), int(y / 4)))
                    }
                }
                n++
            }
        }
        END {
            if (bad) exit 1
            if (n != 15 + 512 * 256 * 3) fail("truncated")
            lb = int((w + 1) / 2); a = 1; b = 0
            put(82); put(84); put(70); put(49); put(5); put16(w); put16(h)
            put(66); put16(0); put16(h)
            for (y = 0; y < h; y++)
                for (j = 0; j < lb; j++) {
                    hi = v[y * 128 + 2 * j]; lo = 2 * j + 1 < w ? v[y * 128 + 2 * j + 1] : 0
                    byte = hi * 16 + lo; put(byte)
                    a = (a + byte) % 65521; b = (b + a) % 65521
                }
            put32(b * 65536 + a); put(69); put32(b * 65536 + a)
            print s
        }') || return 1
    printf "$bytes" >"$4"
}

# run.sh --panel DUMP.ppm W H OUT.stream: that conversion alone (the tests)
if [ "$1" = --panel ]; then
    shift
    panel_stream "$@"
    exit $?
fi

elf=$1 out=$2 rt=$3
base=${elf%.elf}
serial=$base.serial ppm=$base.oled.ppm panel=$base.oled.stream
case $ppm in /*) ;; *) ppm=$PWD/$ppm ;; esac
tmp=$(mktemp -d) || exit 1
sock=$tmp/monitor.sock
pid=
trap '[ -n "$pid" ] && kill $pid 2>/dev/null; rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
rm -f "$serial" "$ppm" "$panel"

bytes_of() { if [ -f "$1" ]; then wc -c <"$1"; else echo 0; fi; }
monitor() { printf '%s\n' "$1" | socat - "UNIX-CONNECT:$sock" >/dev/null; }
# QEMU's stderr, without the line every lm3s6965evb start prints
qemu_errors() { grep -v '^Timer with period zero, disabling$' "$tmp/qemu.err" >&2; }
report() { "$rt" receive --report-only "$serial"; }

t0=$(date +%s.%N)
$QEMU -display none -serial "file:$serial" -monitor "unix:$sock,server,nowait" \
    -semihosting-config enable=on,target=native -icount shift=0 \
    -kernel "$elf" </dev/null >/dev/null 2>"$tmp/qemu.err" &
pid=$!
# The firmware idles after its last report line, "drawn 1"; it exits
# (and QEMU with it) only on a failure. 900 s at most, as run.sh.
i=0
until grep -aq 'drawn 1' "$serial" 2>/dev/null; do
    if ! kill -0 $pid 2>/dev/null; then
        wait $pid
        status=$?
        pid=
        qemu_errors
        report
        [ $status -eq 0 ] && status=1
        echo "lm3s6965evb run: the firmware ended with status $status before drawing the frame" >&2
        exit $status
    fi
    i=$((i + 1))
    if [ $i -gt 9000 ]; then
        report
        echo "lm3s6965evb run: no frame drawn after 900 s" >&2
        exit 1
    fi
    sleep 0.1
done
t1=$(date +%s.%N)

# The dump (15-byte header, 512x256x3 bytes), then quit.
size=$((15 + 512 * 256 * 3))
monitor "screendump $ppm"
i=0
while [ "$(bytes_of "$ppm")" -ne $size ] && [ $i -lt 100 ]; do
    sleep 0.1
    i=$((i + 1))
done
monitor quit
wait $pid
pid=
qemu_errors

rep=$(report)
rx=$?
[ -n "$rep" ] && printf '%s\n' "$rep"
[ $rx -ne 0 ] && exit $rx
if [ "$(bytes_of "$ppm")" -ne $size ]; then
    echo "lm3s6965evb run: screendump gave no 512x256 picture ($ppm)" >&2
    exit 1
fi
w=$(printf '%s\n' "$rep" | awk '$1 == "frame_width" { print $2 }')
h=$(printf '%s\n' "$rep" | awk '$1 == "frame_height" { print $2 }')
if [ -z "$w" ] || [ -z "$h" ]; then
    echo "lm3s6965evb run: the report names no frame_width and frame_height" >&2
    exit 1
fi

panel_stream "$ppm" "$w" "$h" "$panel" || exit 1
"$rt" receive "$panel" -o "$out" || exit $?

# (the time on the board: make run's summary.sh prices the instructions)
awk -v t0="$t0" -v t1="$t1" 'BEGIN { printf "QEMU wall time on the host (boot, render, OLED output): %.1f s\n", t1 - t0 }'
exit 0
