#!/bin/sh
# The Pico (platform/pico/, RP2040 under rp2040js): beyond what
# tests/ports-tests.sh checks on every board,
#  - the ST7789 panel as run.mjs decodes it equals the host's fixed render
#    in rgb565be byte for byte, at depth 6 and for a frame smaller than the
#    panel (odd size, taken from its top left), and the report's counters
#    equal rt --stats;
#  - the UART stream (PICO_DISPLAY=uart) equals the host's in rgb888;
#  - the SIO divider (PICO_DIVIDER=1, the default) and libgcc's division
#    (0) give the same image and counters, the divider in fewer cycles on
#    a scene that divides (rings-1: cylinders);
#  - the report's cycles are at least its instructions (the M0+ takes one
#    cycle or more each);
#  - a damaged panel transfer (data short of its window, a window off the
#    panel, no display-on) gives no image and says why; a frame larger
#    than the panel does not build.
RT=${1:-build/host/rt}
OUT=build/test-pico
mkdir -p "$OUT"
pass=0 fail=0
ok() { pass=$((pass + 1)); printf '  ok    %s\n' "$1"; }
bad() { fail=$((fail + 1)); printf '  FAIL  %s\n' "$1"; }
val() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }

echo "pico: rp2040js RP2040 against the hosted fixed build"
pico_case() { # NAME SCENE SIZE DEPTH FORMAT [MAKE-VARS]
    n=$1 scene=$2 size=$3 depth=$4 format=$5 vars=$6
    set -- BOARD=pico SCENE="$scene" SIZE="$size" DEPTH="$depth" $vars
    if ! make -s -j2 firmware "$@" >"$OUT/$n.build" 2>&1; then
        bad "$n: firmware build failed: $(tail -3 "$OUT/$n.build")"
        return 1
    fi
    rm -f "$OUT/$n-board.png"
    if ! make -s board-run "$@" RUN_OUT="$OUT/$n-board.png" RUN_RT="$RT" >"$OUT/$n.report" 2>&1; then
        bad "$n: board run failed: $(tail -3 "$OUT/$n.report")"
        return 1
    fi
    "$RT" "$scene" -o "$OUT/$n-host.png" --size "$size" --depth "$depth" --format "$format" --threads 1 --quiet --stats \
        2>"$OUT/$n-host.stats"
    ipp=$(val instructions_per_pixel "$OUT/$n.report") cpp=$(val cycles_per_pixel "$OUT/$n.report")
    if cmp=$("$RT" compare "$OUT/$n-board.png" "$OUT/$n-host.png" --max-error 0); then
        ok "$n $size depth $depth: board == host fixed $format ($cmp), $ipp instructions and $cpp cycles a pixel"
    else
        bad "$n $size depth $depth: board and host fixed $format differ: $cmp"
    fi
    if same=$(sh tests/same-counters.sh "$OUT/$n-host.stats" "$OUT/$n.report"); then
        ok "$n: report and rt --stats: $same"
    else
        bad "$n: report and rt --stats: $same"
    fi
    if [ -n "$cpp" ] && [ -n "$ipp" ] && [ "$(val render_cycles "$OUT/$n.report")" -ge "$(val render_instructions "$OUT/$n.report")" ]; then
        ok "$n: render_cycles $(val render_cycles "$OUT/$n.report") >= render_instructions $(val render_instructions "$OUT/$n.report")"
    else
        bad "$n: report lacks cycles, or gives fewer cycles than instructions"
    fi
}
pico_case picolib-d6 scenes/bench/picolib.nff 40x30 6 rgb565be
pico_case showpiece-odd scenes/showpiece.nff 47x31 5 rgb565be
pico_case showpiece-uart scenes/showpiece.nff 32x24 5 rgb888 PICO_DISPLAY=uart
pico_case rings-div scenes/spd/rings-1.nff 24x24 5 rgb565be
pico_case rings-nodiv scenes/spd/rings-1.nff 24x24 5 rgb565be PICO_DIVIDER=0

# The divider: the same bits, fewer cycles
if cmp -s "$OUT/rings-div-board.png" "$OUT/rings-nodiv-board.png"; then
    c1=$(val render_cycles "$OUT/rings-div.report") c0=$(val render_cycles "$OUT/rings-nodiv.report")
    if [ -n "$c1" ] && [ -n "$c0" ] && [ "$c1" -lt "$c0" ]; then
        ok "SIO divider: the same image, $c1 cycles against libgcc's $c0"
    else
        bad "SIO divider: $c1 cycles against libgcc's $c0"
    fi
else
    bad "SIO divider and libgcc's division give different images"
fi
nm=$(make -s board-info BOARD=pico SCENE=scenes/spd/rings-1.nff SIZE=24x24 DEPTH=5 | sed -n 's/.*elf=\([^ ]*\).*/\1/p')
calls=$(arm-none-eabi-objdump -d "$nm" | awk '/^[0-9a-f]+ <.*>:$/ { fn = $2 } /bl.*<__(aeabi_uidiv|udivsi3)/ && fn ~ /wdiv/ { n++ } END { print n + 0 }')
[ "$calls" -eq 0 ] && ok "with the divider, fx_wdiv* call no libgcc division" || bad "fx_wdiv* still call libgcc's division ($calls calls)"

# Damaged transfers, from the odd frame's SPI log (pairs: D/C, byte)
log=$(make -s board-info BOARD=pico SCENE=scenes/showpiece.nff SIZE=47x31 DEPTH=5 | sed -n 's/.*elf=\([^ ]*\)\.elf.*/\1/p').spi
damage() { # WHAT PYTHON-EXPR-ON-d EXPECTED
    python3 -c "import sys
d = bytearray(open(sys.argv[1], 'rb').read())
cmds = [i for i in range(0, len(d), 2) if d[i] == 0]
$2
open(sys.argv[2], 'wb').write(d)" "$log" "$OUT/bad.spi"
    rm -f "$OUT/bad.stream"
    msg=$(node platform/pico/run.mjs --panel "$OUT/bad.spi" 47 31 "$OUT/bad.stream" 2>&1); status=$?
    if [ $status -ne 0 ] && [ ! -e "$OUT/bad.stream" ] && echo "$msg" | grep -q "$3"; then
        ok "$1: $msg"
    else
        bad "$1: status $status, '$msg'"
    fi
}
if [ -f "$log" ]; then
    damage "short data" "del d[-2:]" "short or long data"
    damage "wrong window" "i = [c for c in cmds if d[c + 1] == 0x2a][0]; d[i + 7] = 0x01; d[i + 9] = 0x40" "wrong window"
    damage "no display on" "i = [c for c in cmds if d[c + 1] == 0x29][0]; del d[i:i + 2]" "before sleep out, display on"
    damage "a frame pixel never written" "i = [c for c in cmds if d[c + 1] == 0x2c][-1]; del d[i - 20:]" "never written"
    # the intact log decodes to the image the run wrote
    if node platform/pico/run.mjs --panel "$log" 47 31 "$OUT/good.stream" && "$RT" receive "$OUT/good.stream" -o "$OUT/good.png" &&
       "$RT" compare "$OUT/good.png" "$OUT/showpiece-odd-host.png" --max-error 0 >/dev/null; then
        ok "the intact SPI log decodes to the host's image"
    else
        bad "the intact SPI log does not decode to the host's image"
    fi
else
    bad "no SPI log at $log"
fi

# Larger than the panel: a build error that says so
if make -s firmware BOARD=pico SCENE=scenes/spd/rings-1.nff SIZE=321x240 >"$OUT/big.build" 2>&1; then
    bad "a 321x240 frame built for the 320x240 panel"
elif grep -q "the frame is larger than the 320x240 panel" "$OUT/big.build"; then
    ok "a 321x240 frame does not build: the frame is larger than the 320x240 panel"
else
    bad "a 321x240 frame failed to build without the expected message: $(tail -2 "$OUT/big.build")"
fi
echo "board-pico-tests: $pass passed, $fail failed"
[ $fail -eq 0 ]
