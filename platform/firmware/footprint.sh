#!/bin/sh
# footprint.sh FIRMWARE.elf OBJDIR [REPORT]: flash and RAM by section, the
# worst-case stack from the call graph, and (when a run report exists)
# the measured stack high-water mark.
elf=$1 objdir=$2 report=$3
here=$(dirname "$0")
${CROSS:-arm-none-eabi-}size -A "$elf" | awk '
    $1 ~ /^\./ && $2 ~ /^[0-9]+$/ && $1 !~ /^\.(debug|comment|ARM\.attributes)/ { printf "  %-12s %8d bytes\n", $1, $2; s[$1] = $2 }
    END {
        code = s[".vectors"] + s[".text"] + s[".ARM.exidx"]
        printf "flash: code %d bytes, scene tables %d bytes, data image %d bytes\n", code, s[".scene"], s[".data"]
        printf "ram:   data+bss %d bytes\n", s[".data"] + s[".bss"]
    }'
# the stack region itself (its section also holds alignment padding)
lim=$(${CROSS:-arm-none-eabi-}nm "$elf" | awk '$3 == "__stack_limit" { print $1 }')
top=$(${CROSS:-arm-none-eabi-}nm "$elf" | awk '$3 == "__stack_top" { print $1 }')
echo "ram:   stack region $((0x${top:-0} - 0x${lim:-0})) bytes (separate)"
# band buffers: main.c's one, or bands.c's two per core on a multi-core board
hex=$(${CROSS:-arm-none-eabi-}nm -S "$elf" | awk '$4 == "band" || $4 == "slot_px" { print $2 }')
echo "ram:   of which band buffers $((0x${hex:-0})) bytes"
python3 "$here/stack_usage.py" "$objdir" --root main --depth "${DEPTH:-5}" \
    --indirect "${SINK_CALLBACKS:-stream_begin,stream_flush,stream_end}"
if [ -n "$report" ] && [ -f "$report" ]; then
    grep -E '^(core1_)?stack_(high_water|size|guard_intact)' "$report" | sed 's/^/measured: /'
fi
