#!/bin/sh
# footprint.sh FIRMWARE.elf OBJDIR [REPORT]: flash and RAM by section, the
# worst-case stack from the call graph, and (when a run report exists)
# the measured stack high-water mark. A section whose run address differs
# from its load address is in flash and, once reset has copied it, in RAM
# too (the code and scene tables of a board that runs them from SRAM).
elf=$1 objdir=$2 report=$3
here=$(dirname "$0")
${CROSS:-arm-none-eabi-}objdump -h "$elf" | awk -f "$here/sections.awk" | awk '
    {
        n = $1; size = $2
        printf "  %-12s %8d bytes  %s\n", n, size, $5 == "ram" ? "RAM" : n == ".data" ? "flash, copied to RAM" : $5 == "copied" ? "flash, run from RAM" : "flash"
        if (n == ".scene") { scene = size; if ($5 == "copied") ram_scene = size }
        else if (n == ".data") data = size
        else if (n == ".bss") bss = size
        else if ($5 != "ram") { code += size; if ($5 == "copied") ram_code += size }
    }
    END {
        printf "flash: code %d bytes, scene tables %d bytes, data image %d bytes\n", code, scene, data
        if (ram_code + ram_scene > 0)
            printf "ram:   code %d bytes and scene tables %d bytes copied from flash at reset\n", ram_code, ram_scene
        printf "ram:   data+bss %d bytes\n", data + bss
    }'
# the stack region itself (its section also holds alignment padding)
lim=$(${CROSS:-arm-none-eabi-}nm "$elf" | awk '$3 == "__stack_limit" { print $1 }')
top=$(${CROSS:-arm-none-eabi-}nm "$elf" | awk '$3 == "__stack_top" { print $1 }')
echo "ram:   stack region $((0x${top:-0} - 0x${lim:-0})) bytes (separate)"
# band buffers: main.c's one, or bands.c's two per core on a multi-core board
hex=$(${CROSS:-arm-none-eabi-}nm -S "$elf" | awk '$4 == "band" || $4 == "slot_px" { print $2 }')
echo "ram:   of which band buffers $((0x${hex:-0})) bytes"
python3 "$here/stack_usage.py" "$objdir" --root main --below reset_c --depth "${DEPTH:-5}" \
    --indirect "${SINK_CALLBACKS:-stream_begin,stream_flush,stream_end}"
if [ -n "$report" ] && [ -f "$report" ]; then
    grep -E '^(core1_)?stack_(high_water|size|guard_intact)' "$report" | sed 's/^/measured: /'
fi
