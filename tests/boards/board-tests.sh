#!/bin/sh
# Board tests. On the first port (QEMU mps2-an385):
#  - the board's image is byte-identical to the hosted fixed build's, for
#    every SPD size-1 scene and the size-2 scenes, at 64x64, depth 5;
#  - the fixed firmware links no heap and no soft-float helper;
#  - the demo scenes of scenes/ (solids, transforms, CSG, textures) and
#    the benchmark scenes of scenes/bench likewise;
#  - plane, texture and sky code is pruned from firmware that lacks them
#    (the generic firmware, SPECIALISE=0: the default inlines them);
#  - the footprint budgets of tests/boards/budgets.sh on the default scene
#    (showpiece, 128x128, depth 5), built for its scene (the default) and
#    generic, and the code budget on balls-2;
#  - a scene over a capacity fails to build with a clear message;
#  - on the host, every byte the stream sink writes counts as output, not
#    as the render's time (tests/boards/sink_stream_test.c);
#  - the frame size a board build takes from the scene (scene-size.awk)
#    is the frame rt renders, for every scene of scenes/ and for tokens
#    split over lines, comments, CRLF and 3.2e1;
#  - make run and make image with the same variables name the same
#    firmware; distinct choices get distinct out/ names, each word of
#    them one docs/boards.md gives; make run at two sizes leaves two
#    references of each kind, and what make run and make host-run write
#    is named as docs/boards.md lists; a missing SCENE stops make run
#    with its name; a malformed SIZE stops every board with one message
#    before anything is compiled.
# One sample a pixel (AA=0) unless a case says otherwise: every goal
# defaults to the board's BOARD_RUN_AA, 3 levels here.
RT=${1:-build/host/rt}
OUT=build/test-board
. tests/boards/board-case.sh
. tests/boards/budgets.sh
fwdir() { make -s print-fwdir SCENE="$(scene_file $1)" SIZE=$2 DEPTH=5 AA=0; }
# fw NAME [make variables]: build the firmware and run it, one sample a
# pixel unless the variables say otherwise (board_fw: the caller counts)
fw() {
    n=$1
    shift
    board_fw $n AA=0 "$@"
}

echo "board tests: QEMU mps2-an385 against the hosted fixed build"
scene_file() { for d in scenes/spd scenes/bench scenes; do [ -f $d/$1.nff ] && echo $d/$1.nff && return; done; }
for s in balls-1 gears-1 rings-1 teapot-1 tetra-1 balls-2 rings-2 teapot-2 tetra-2 \
         quadrics torus boxes transforms csg showpiece textures card picolib whitted; do
    vars="SCENE=$(scene_file $s) SIZE=64x64 DEPTH=5 AA=0"
    board_build $s $vars && board_run $s $vars || continue
    ipp=$(report_val instructions_per_pixel "$OUT/$s.report")
    # the core's counters (include/rt_stats.h): the same keys and values on both
    board_vs_host $s fixed "$ipp instructions/pixel" $(scene_file $s) --fixed --size 64x64 --depth 5
done

# Compile-time pruning changes code size, never pixels: unpruned firmware
# (every primitive kind and feature compiled in) must give the same image.
for s in balls-1 rings-1 teapot-1 gears-1 tetra-1; do
    p=$(fwdir $s 64x64) u="$(fwdir $s 64x64)-noprune"
    if fw $s-noprune SCENE=scenes/spd/$s.nff SIZE=64x64 DEPTH=5 PRUNE=0 &&
       [ -f "$OUT/$s-board.png" ] && "$RT" compare "$OUT/$s-noprune-board.png" "$OUT/$s-board.png" --max-error 0 >/dev/null; then
        ok "$s: pruned == unpruned image; code $(code_of "$p/fixed.elf") vs $(code_of "$u/fixed.elf") bytes"
    else
        bad "$s: pruned and unpruned firmware differ or failed"
    fi
done

# Textures, planes and the sky are pruned from firmware for a scene
# without them (balls-2), and linked for one with them (textures).
# The generic firmware (SPECIALISE=0): the whole-program build inlines
# them where it links them. (texture_colour is inline, a checker's point
# sample in it; the rest is texture_colour_at.)
syms() {
    make -s -j2 firmware SCENE="$(scene_file $1)" SIZE=64x64 DEPTH=5 AA=0 SPECIALISE=0 >"$OUT/$1-generic.build" 2>&1
    d=$(make -s print-fwdir SCENE="$(scene_file $1)" SIZE=64x64 DEPTH=5 AA=0 SPECIALISE=0)
    arm-none-eabi-nm "$d/fixed.elf" | awk '{ print $NF }' | grep -E '^rt_(texture_colour_at|ray_hit_plane|sky_colour)$' | sort | tr '\n' ' '
}
none=$(syms balls-2) all=$(syms textures)
if [ -z "$none" ] && [ "$all" = "rt_ray_hit_plane rt_sky_colour rt_texture_colour_at " ]; then
    ok "pruning: balls-2 links no plane, texture or sky code; textures links $all"
else
    bad "pruning: balls-2 links '$none'; textures links '$all'"
fi

# The code budget on a firmware with the SPD features only (balls-2:
# spheres, one polygon, shadows, reflection, specular), scene tables excluded.
c=$(code_of "$(fwdir balls-2 64x64)/fixed.elf")
[ "${c:-0}" -gt 0 ] && [ "$c" -le $FW_CODE_MAX ] && ok "balls-2 firmware code $c bytes <= $FW_CODE_MAX" ||
    bad "balls-2 firmware code ${c:-?} bytes > $FW_CODE_MAX"

# The packed framebuffer formats on the board against the host's
# (rgb565be: 16-bit byte-swapped; l4: two pixels per byte, and at an odd
# width the last byte of every line keeps its low nibble 0).
for case in rgb565:48x32 rgb565be:48x32 l4:48x32 l4:47x31; do
    fmt=${case%%:*} size=${case#*:}
    if fw $fmt-$size SCENE=scenes/spd/rings-1.nff SIZE=$size DEPTH=3 FORMAT=$fmt &&
       "$RT" scenes/spd/rings-1.nff -o "$OUT/$fmt-$size-host.png" --size $size --depth 3 --format $fmt --quiet &&
       cmp=$("$RT" compare "$OUT/$fmt-$size-board.png" "$OUT/$fmt-$size-host.png" --max-error 0); then
        ok "rings-1 $fmt $size: board == host fixed ($cmp)"
    else
        bad "rings-1 $fmt $size: board and host differ or failed"
    fi
done
# the odd-width L4 stream: every line's last byte has a zero low nibble
if python3 -c '
import sys
d = open(sys.argv[1], "rb").read()
i = d.find(b"RTF1"); w = d[i+5] | d[i+6] << 8; h = d[i+7] | d[i+8] << 8
assert d[i+4] == 5 and w % 2 == 1
lb = (w + 1) // 2; j = i + 9; rows = 0
while d[j:j+1] in (b"B", b"T"):
    if d[j:j+1] == b"T":  # a report line between bands (progress_rows)
        j += 3 + (d[j+1] | d[j+2] << 8); continue
    n = d[j+3] | d[j+4] << 8
    for r in range(n):
        assert d[j + 5 + r * lb + lb - 1] & 15 == 0
    rows += n; j += 5 + n * lb + 4
assert rows == h
' "$(make -s print-fwdir SCENE=scenes/spd/rings-1.nff SIZE=47x31 DEPTH=3 FORMAT=l4 AA=0)/fixed.stream" 2>"$OUT/l4-pad.err"; then
    ok "l4 at width 47: the last nibble of every line in the stream is 0"
else
    bad "l4 at width 47: padding nibble not 0 or stream unreadable: $(tail -1 "$OUT/l4-pad.err")"
fi

# Linked-symbol checks on the default scene's firmware (and, as a control
# that the check can fail, the soft-float build must show its helpers).
make -s -j2 firmware SCENE=scenes/showpiece.nff SIZE=128x128 DEPTH=5 AA=0 >"$OUT/default.build" 2>&1
d=$(fwdir showpiece 128x128)
bad_syms=$(arm-none-eabi-nm "$d/fixed.elf" | awk '{ print $NF }' | grep -E '^(malloc|free|calloc|realloc|_sbrk|_malloc_r|__aeabi_f.*|__aeabi_d.*|__aeabi_[fd]2.*)$')
[ -z "$bad_syms" ] && ok "fixed firmware links no heap or soft-float symbol" || bad "fixed firmware links: $bad_syms"
make -s -j2 firmware BACKEND=double SCENE=scenes/showpiece.nff SIZE=128x128 DEPTH=5 AA=0 >>"$OUT/default.build" 2>&1
arm-none-eabi-nm "$d/double.elf" | grep -q ' __aeabi_dmul$' &&
    ok "control: the soft-float build does link __aeabi_dmul" ||
    bad "control: the soft-float build shows no __aeabi_dmul (the symbol check proves nothing)"

# The footprint budgets on the default scene at depth 5.
if make -s board-run SCENE=scenes/showpiece.nff SIZE=128x128 DEPTH=5 AA=0 RUN_OUT="$OUT/default.png" RUN_RT="$RT" >"$OUT/default.report" 2>&1; then
    eval "$(arm-none-eabi-size -A "$d/fixed.elf" | awk '
        $1 == ".vectors" || $1 == ".text" || $1 == ".ARM.exidx" { code += $2 }
        $1 == ".data" || $1 == ".bss" { ram += $2 }
        END { printf "code=%d ram=%d\n", code, ram }')"
    band=$((0x$(arm-none-eabi-nm -S "$d/fixed.elf" | awk '$4 == "band" { print $2 }')))
    hw=$(awk '$1 == "stack_high_water" { print $2 }' "$OUT/default.report")
    guard=$(awk '$1 == "stack_guard_intact" { print $2 }' "$OUT/default.report")
    # built for its scene (the default): the generic code and what the
    # scene's constants unroll; the generic firmware too within the budget
    make -s -j2 firmware SCENE=scenes/showpiece.nff SIZE=128x128 DEPTH=5 AA=0 SPECIALISE=0 >"$OUT/default-generic.build" 2>&1
    generic=$(code_of "$(make -s print-fwdir SCENE=scenes/showpiece.nff SIZE=128x128 DEPTH=5 AA=0 SPECIALISE=0)/fixed.elf")
    [ "$code" -gt 0 ] && [ "$code" -le $FW_CODE_MAX ] && [ "${generic:-99999}" -le $FW_CODE_MAX ] &&
        ok "code $code bytes, generic (SPECIALISE=0) $generic bytes, each <= $FW_CODE_MAX (scene tables excluded)" ||
        bad "code $code bytes, generic ${generic:-?} bytes (limit $FW_CODE_MAX each)"
    [ "$ram" -gt 0 ] && [ $((ram - band)) -le $FW_RAM_MAX ] && ok "RAM $((ram - band)) bytes + band $band bytes (<= $FW_RAM_MAX + band)" ||
        bad "RAM $((ram - band)) bytes (+ band $band) > $FW_RAM_MAX"
    [ "${hw:-99999}" -le $FW_STACK_MAX ] && ok "stack high-water $hw bytes <= $FW_STACK_MAX" ||
        bad "stack high-water ${hw:-?} bytes > $FW_STACK_MAX"
    [ "$guard" = 1 ] && ok "stack guard intact" || bad "stack guard overwritten"
else
    bad "default scene board run failed: $(tail -3 "$OUT/default.report")"
fi

# The host receiver rejects damaged streams instead of writing an image.
st="$d/fixed.stream"
if [ -f "$st" ]; then
    n=$(wc -c <"$st")
    head -c $((n / 2)) "$st" >"$OUT/half.stream"
    msg=$("$RT" receive "$OUT/half.stream" -o "$OUT/half.png" 2>&1 >/dev/null); status=$?
    [ $status -eq 2 ] && [ ! -e "$OUT/half.png" ] && echo "$msg" | grep -q "truncated" &&
        ok "truncated stream rejected: $msg" || bad "truncated stream: status $status, '$msg'"
    # flip one pixel byte inside the first band (after the 9-byte header and 5-byte band header)
    python3 -c "import sys; d=bytearray(open(sys.argv[1],'rb').read()); d[20]^=0x10; open(sys.argv[2],'wb').write(d)" "$st" "$OUT/flip.stream"
    msg=$("$RT" receive "$OUT/flip.stream" -o "$OUT/flip.png" 2>&1 >/dev/null); status=$?
    [ $status -eq 2 ] && [ ! -e "$OUT/flip.png" ] && echo "$msg" | grep -q "checksum mismatch" &&
        ok "corrupted stream rejected: $msg" || bad "corrupted stream: status $status, '$msg'"
fi

# Deep recursion on the board: two facing mirrors at the maximum depth keep
# the stack inside its budget and the image equal to the host's.
mir="$OUT/mirrors.nff"
printf 'b 0 0 0\nv\nfrom 0.5 -1.5 0.3\nat 0 3 0\nup 0 0 1\nangle 60\nhither 1\nresolution 32 32\nl 0 0 0.9\nf 1 1 1 0.05 1 50 0 1\np 4\n-3 -3 -1\n3 -3 -1\n3 3 -1\n-3 3 -1\np 4\n-3 -3 1\n-3 3 1\n3 3 1\n3 -3 1\nf 0.9 0.2 0.2 0.8 0.2 10 0.5 1.5\ns 0 2 0 0.4\n' >"$mir"
if fw mirrors SCENE="$mir" SIZE=32x32 DEPTH=5 &&
   "$RT" "$mir" -o "$OUT/mirrors-host.png" --size 32x32 --depth 5 --quiet &&
   "$RT" compare "$OUT/mirrors-board.png" "$OUT/mirrors-host.png" --max-error 0 >/dev/null; then
    hw=$(awk '$1 == "stack_high_water" { print $2 }' "$OUT/mirrors.report")
    [ "${hw:-99999}" -le $FW_STACK_MAX ] && ok "facing mirrors at depth 5: board == host, stack high-water $hw bytes <= $FW_STACK_MAX" ||
        bad "facing mirrors: stack high-water ${hw:-?} bytes > $FW_STACK_MAX"
else
    bad "facing mirrors at depth 5 failed on the board: $(tail -2 "$OUT/mirrors.report")"
fi

# Over capacity: 1025 spheres against RT_MAX_SPHERES = 1024 of the board build.
big="$OUT/too-many-spheres.nff"
{
    printf 'v\nfrom 0 -40 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 16 16\nl 0 -40 40\nf 1 1 1 1 0 1 0 1\n'
    i=0
    while [ $i -lt 1025 ]; do echo "s $((i % 32)) 0 $((i / 32)) 0.4"; i=$((i + 1)); done
} >"$big"
if make -s firmware SCENE="$big" SIZE=16x16 >"$OUT/big.build" 2>&1; then
    bad "a 1025-sphere scene built (capacity not enforced)"
elif grep -q "too-many-spheres.nff:1034: too many spheres: capacity RT_MAX_SPHERES = 1024 (raise it with -DRT_MAX_SPHERES=N)" "$OUT/big.build"; then
    ok "over capacity: $(grep 'too many' "$OUT/big.build")"
else
    bad "over-capacity build failed without the expected message: $(tail -2 "$OUT/big.build")"
fi
# The stream sink on the host against a console whose bytes take time (a
# real UART's; QEMU's is always ready): each call's output is all counted
# as output, the end record's included (tests/boards/sink_stream_test.c).
if cc -std=c11 -Wall -Wextra -Werror -DBOARD_CYCLES=1 -Iinclude -Iplatform -Iapp/firmware tests/boards/sink_stream_test.c \
       app/firmware/sink_stream.c app/firmware/sink_io.c app/firmware/report.c -o "$OUT/sink-stream-test" \
       2>"$OUT/sink-stream.build" && "$OUT/sink-stream-test" >"$OUT/sink-stream.txt"; then
    ok "stream sink: $(tail -1 "$OUT/sink-stream.txt" | cut -d' ' -f2-), every byte out counted as output"
else
    bad "stream sink: $(grep FAIL "$OUT/sink-stream.txt" | head -2) $(tail -2 "$OUT/sink-stream.build")"
fi

# The frame a board build takes from the scene (scene-size.awk) is the
# frame rt renders: a viewport at its last pixel renders, one a pixel
# further right or down is outside the frame. Every scene of scenes/, and
# the reader's own token rules: the numbers on other lines, after a
# comment, as 3.2e1 and 24.0, CRLF line ends.
printf 'v\nfrom 0 -4 0\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1 resolution # the size:\n  3.2e1\n\n# x\n24.0\nl 0 -4 4\nf 1 0 0 1 0 1 0 1\ns 0 0 0 1\n' >"$OUT/size-split.nff"
printf 'v\r\nfrom 0 -4 0\r\nat 0 0 0\r\nup 0 0 1\r\nangle 40\r\nhither 1\r\nresolution 20 12\r\nl 0 -4 4\r\nf 1 0 0 1 0 1 0 1\r\ns 0 0 0 1\r\n' >"$OUT/size-crlf.nff"
n=0 wrong=""
for f in $(find scenes -name '*.nff' | sort) "$OUT/size-split.nff" "$OUT/size-crlf.nff"; do
    s=$(make -s board-info SCENE="$f" | sed -n 's/.* size=\([^ ]*\).*/\1/p') w=${s%x*} h=${s#*x}
    if [ -n "$s" ] && "$RT" "$f" -o "$OUT/size.png" --viewport $((w - 1)),$((h - 1)),1,1 --threads 1 --quiet 2>/dev/null &&
       ! "$RT" "$f" -o "$OUT/size.png" --viewport $w,$((h - 1)),1,1 --threads 1 --quiet 2>/dev/null &&
       ! "$RT" "$f" -o "$OUT/size.png" --viewport $((w - 1)),$h,1,1 --threads 1 --quiet 2>/dev/null; then
        n=$((n + 1))
    else
        wrong="$wrong $f:${s:-none}"
    fi
done
[ -z "$wrong" ] && ok "the board's frame is rt's for all $n scenes (scenes/, numbers split over lines and comments, 3.2e1, CRLF): $(make -s board-info SCENE="$OUT/size-split.nff" | sed -n 's/.* size=\([^ ]*\).*/\1/p') for the split one" ||
    bad "the board's frame is not rt's for:$wrong"
sz=$(make -s board-info SCENE=scenes/bench/card.nff SIZE=100x50 | sed -n 's/.* size=\([^ ]*\).*/\1/p')
[ "$sz" = 100x50 ] && ok "SIZE=100x50 on the command line wins over the scene's 320x240" || bad "SIZE=100x50 gave $sz"

# Two scenes of one file name in different folders share a build folder:
# the second gets its own tables even when its file is the older one
mkdir -p "$OUT/same-a" "$OUT/same-b"
printf 'v from 0 0 -5 at 0 0 0 up 0 1 0 angle 40 hither 1 resolution 16 16\nl 5 5 -5\nf 1 0 0 0.8 0.2 20 0 1\ns 0 0 0 1\n' >"$OUT/same-a/same.nff"
printf 'v from 0 0 -5 at 0 0 0 up 0 1 0 angle 40 hither 1 resolution 16 16\nl 5 5 -5\nf 0 0 1 0.8 0.2 20 0 1\ns 0 0 0 1\n' >"$OUT/same-b/same.nff"
touch -d '2001-01-01' "$OUT/same-b/same.nff"
same_elf() { make -s -j2 firmware SCENE="$1" AA=0 >"$OUT/same.build" 2>&1 && cksum <"$(make -s print-fwdir SCENE="$1" AA=0)/fixed.elf"; }
ea=$(same_elf "$OUT/same-a/same.nff") eb=$(same_elf "$OUT/same-b/same.nff") ea2=$(same_elf "$OUT/same-a/same.nff")
[ -n "$ea" ] && [ -n "$eb" ] && [ "$ea" != "$eb" ] && [ "$ea" = "$ea2" ] &&
    ok "same.nff in two folders: each built from its own file (the older one too)" ||
    bad "same.nff in two folders: ELF a '$ea', b '$eb', a again '$ea2' ($(tail -2 "$OUT/same.build"))"

# Names in out/: the default run keeps the README's name; every choice
# that changes the firmware (size, sampling, dither, format, depth,
# texture filter, configuration, bands, cores, and the boards' own: panel,
# flip, STM32 variant, crystal, HSE mode, LED, its polarity, USART, baud
# rate) gives another name and ELF,
# and make run's ELF is the one beside make image's file
info() { make -s board-info "$@" | sed -n 's/.* elf=\([^ ]*\) out=\([^ ]*\).*/\2 \1/p'; }
d=$(info) && [ "${d%% *}" = out/showpiece-mps2-an385-fixed ] && ok "the default run: ${d%% *}.png" || bad "the default run's name: $d"
names="$OUT/names.txt"
: >"$names"
for v in "" "SIZE=64x64" "SIZE=64x48" "AA=0" "AA=2" "AA=3,20" "SPP=2" "DITHER=1" "FORMAT=rgb565" "DEPTH=3" \
         "TEXTURE_FILTER=0" "CONFIG=q16" "BAND_LINES=2" "STACK_SIZE=8192" "PRUNE=0" "BACKEND=float" \
         "BOARD=mps2-an521" "BOARD=mps2-an521 CORES=1" "BOARD=lm3s6965evb" "BOARD=lm3s6965evb DITHER=0" \
         "BOARD=pico" "BOARD=pico PANEL=240x240" "BOARD=pico PANEL_FLIP=1" "BOARD=pico PANEL=240x240 PANEL_FLIP=1" \
         "BOARD=pico SIZE=160x120" "BOARD=pico AA=3" "BOARD=pico PICO_DISPLAY=uart" "BOARD=pico PICO_DIVIDER=0" \
         "BOARD=stm32f4" "BOARD=stm32f4 STM32=nucleo64" "BOARD=stm32f4 HSE_MHZ=25" "BOARD=stm32f4 STM32_LED=PC1" \
         "BOARD=stm32f4 STM32_USART=2" "BOARD=stm32f4 AA=0" "BOARD=stm32f4 SIZE=160x120" \
         "BOARD=stm32f4 STM32=blackpill-f411" "BOARD=stm32f4 STM32=blackpill-f401" "BOARD=stm32f4 HSE=bypass" \
         "BOARD=stm32f4 STM32_LED_ON=low" "BOARD=stm32f4 BAUD=921600" \
         "SPECIALISE=0" "BOARD=pico PROGRESSIVE=0"; do
    echo "$(info $v) $v" >>"$names"
done
dup_out=$(awk '{ print $1 }' "$names" | sort | uniq -d) dup_dir=$(awk '{ print $2 }' "$names" | sort | uniq -d)
if [ -z "$dup_out$dup_dir" ] && [ "$(wc -l <"$names")" = 42 ] && ! awk '$1 == "" || $2 == ""' "$names" | grep -q .; then
    ok "42 builds, 42 out/ names and ELFs: $(awk 'NR > 1 { printf "%s%s", sep, $1; sep = ", " }' "$names" | sed 's,out/showpiece-,,g' | cut -c1-400)..."
else
    bad "out/ names or ELFs shared: $dup_out $dup_dir"
fi
# every word of those names is one docs/boards.md gives (`d<depth>` as d3)
undoc=$(python3 -c '
import re, sys
doc = open("docs/boards.md").read()
sec = doc[doc.index("**Names in `out/`.**"):doc.index("## Boards")]
# a placeholder is a number (`led<pin>`: a pin such as PC1)
forms = [re.compile(re.sub(r"<[^>]+>", lambda m: "[A-Z]+[0-9]+" if m.group(0) == "<pin>" else "[0-9]+",
                           re.escape(w).replace("\\<", "<").replace("\\>", ">")))
         for w in re.findall(r"`([^`\s]+)`", sec)]
words = set()
for line in open(sys.argv[1]):
    name = line.split()[0].split("/")[-1]
    board = next(b for b in sys.argv[2:] if name.startswith("showpiece-" + b + "-"))
    parts = name[len("showpiece-" + board + "-"):].split("-")[1:]
    while parts:  # a word of two parts where the list gives it so (blackpill-f411)
        two = "-".join(parts[:2])
        n = 2 if len(parts) > 1 and any(f.fullmatch(two) for f in forms) else 1
        words.add("-".join(parts[:n]))
        parts = parts[n:]
print(" ".join(sorted(w for w in words if not any(f.fullmatch(w) for f in forms))) or "none", len(words))
' "$names" $(ls platform/*/board.mk | cut -d/ -f2))
[ "${undoc%% *}" = none ] && ok "the ${undoc#* } words of those names are each in docs/boards.md's list" ||
    bad "out/ name words docs/boards.md does not give: $undoc"
run=$(make -n run BOARD=stm32f4 SIZE=40x30 2>/dev/null | sed -n 's/.* RUN "\([^ ]*\) on.*/\1/p')
img=$(make -n image BOARD=stm32f4 SIZE=40x30 2>/dev/null | grep -o '[^ ]*\.bin ' | head -1)
[ -n "$run" ] && [ "${img% }" = "${run%.elf}.bin" ] && ok "make run runs $run; make image copies ${img% } beside it" ||
    bad "make run's ELF '$run' and make image's file '$img'"

# make run's files: two runs at two sizes leave two references of each
# kind, nothing overwritten, and every file make run and make host-run
# write has a name of docs/boards.md's list of out/ names, each name of
# the list but the files to flash written (the runs reuse the l4
# firmware of the format cases above)
od=$OUT/out
rm -rf "$od"
for size in 48x32 47x31; do
    make -s run SCENE=scenes/spd/rings-1.nff SIZE=$size DEPTH=3 FORMAT=l4 AA=0 OUT_DIR="$od" >"$OUT/run-$size.log" 2>&1 ||
        bad "make run at $size failed: $(tail -3 "$OUT/run-$size.log")"
done
make -s host-run SCENE=scenes/spd/rings-1.nff SIZE=47x31 DEPTH=3 OUT_DIR="$od" >"$OUT/host-run.log" 2>&1 ||
    bad "make host-run failed: $(tail -3 "$OUT/host-run.log")"
if names=$(ls "$od" 2>/dev/null | python3 -c '
import re, sys
doc = open("docs/boards.md").read()
sec = doc[doc.index("**Names in `out/`.**"):doc.index("## Boards")]
templates = re.findall(r"^    (out/\S+)", sec, re.M)
part = {"scene": "rings-1", "board": "mps2-an385", "backend": "fixed|float|double", "ext": "uf2|bin|hex",
        "choices": r"[a-z0-9_]+(?:-[a-z0-9_]+)*", "sampling": r"aa\d+(?:_\d+)?|spp\d+", "format": "[a-z0-9]+"}
def regex(t):
    out = ""
    for tok in re.findall(r"<[^>]+>|\[|\]|[^<\[\]]+", t):
        if tok == "[": out += "(?:"
        elif tok == "]": out += ")?"
        elif tok.startswith("<"):
            out += "(?:%s)" % part.get(tok[1:-1], r"\d+" if tok[1:-1] in ("W", "H", "depth") else tok[1:-1])
        else: out += re.escape(tok)
    return re.compile(out)
files = sys.stdin.read().split()
used, wrong = set(), []
for f in files:
    hit = [t for t in templates if regex(t).fullmatch("out/" + f)]
    used.update(hit)
    if not hit: wrong.append(f)
unused = [t for t in templates if t not in used and not t.endswith(".<ext>")]
refs = [f for f in files if re.match(r"rings-1-(double|area)-4[78]x3[12]-", f)]
if len(templates) < 5 or wrong or unused or len(files) != 8 or len(refs) != 5:
    sys.exit("%d templates, %d files, %d references; undocumented: %s; no file: %s" % (
        len(templates), len(files), len(refs), " ".join(wrong), " ".join(unused)))
print(" ".join(files))
'); then
    ok "make run at 48x32 and 47x31, make host-run: 8 files, each named as docs/boards.md lists: $names"
else
    bad "make run's out/ names: $names (written: $(ls "$od" 2>/dev/null | tr '\n' ' '))"
fi

# A scene that is not there stops make run at once, with its name
msg=$(make run SCENE=nosuch.nff 2>&1); status=$?
if [ $status -ne 0 ] && echo "$msg" | grep -q 'SCENE=nosuch.nff: no such file' && ! echo "$msg" | grep -q 'No rule'; then
    ok "make run SCENE=nosuch.nff: $(echo "$msg" | grep -o 'SCENE=nosuch.nff: no such file')"
else
    bad "make run SCENE=nosuch.nff: status $status, $msg"
fi

# A malformed SIZE stops every board at once with the one message, before
# anything is compiled: CC and the cross compiler are stubs that leave a
# mark if they run.
printf '#!/bin/sh\ntouch "%s/compiled"\nexit 1\n' "$PWD/$OUT" >"$OUT/nocc-gcc" && chmod +x "$OUT/nocc-gcc"
for size in abc 64x 100000x10; do
    want="SIZE=$size: expected WxH in whole pixels from 1x1 to 4096x4096, such as SIZE=128x96"
    wrong=
    for b in $(ls platform/*/board.mk | cut -d/ -f2); do
        rm -f "$OUT/compiled"
        msg=$(make -s firmware BOARD=$b SIZE=$size CC="$PWD/$OUT/nocc-gcc" BOARD_CROSS="$PWD/$OUT/nocc-" 2>&1)
        status=$?
        got=$(printf '%s\n' "$msg" | sed 's/^[^ ]*firmware\.mk:[0-9]*: \*\*\* //; s/\.  Stop\.$//')
        [ $status -ne 0 ] && [ "$got" = "$want" ] && [ ! -e "$OUT/compiled" ] || wrong="$wrong $b (status $status: $msg)"
    done
    [ -z "$wrong" ] && ok "SIZE=$size on every board: \"$want\", nothing compiled" || bad "SIZE=$size:$wrong"
done
summary board-tests
