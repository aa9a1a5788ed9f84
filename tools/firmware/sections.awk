# sections.awk - objdump -h's section table as one line per allocated
# section: name, size in bytes (decimal), run address, load address (hex),
# and where it lives: "flash" (loaded, runs where it is loaded), "copied"
# (loaded into flash, run from RAM after reset copies it: .data, and the
# code and scene tables of a board that runs them from SRAM) or "ram"
# (not loaded: .bss, the stack). For footprint.sh and the tests:
#   objdump -h FIRMWARE.elf | awk -f tools/firmware/sections.awk
function hex(s,   v, i) {
    v = 0
    for (i = 1; i <= length(s); i++)
        v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
    return v
}
$1 ~ /^[0-9]+$/ && $2 ~ /^\./ { name = $2; size = hex($3); vma = $4; lma = $5; next }
name != "" {
    if ($0 ~ /ALLOC/)
        print name, size, vma, lma, $0 !~ /LOAD/ ? "ram" : (vma != lma || name == ".data") ? "copied" : "flash"
    name = ""
}
