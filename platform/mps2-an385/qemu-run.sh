#!/bin/sh
# qemu-run.sh FIRMWARE.elf OUT.png RT: run the firmware on the emulated
# board, decode its UART stream into OUT.png and print its report lines.
# Exits non-zero when QEMU, the firmware or the stream fails.
elf=$1 out=$2 rt=$3
stream="${elf%.elf}.stream"
timeout 900 qemu-system-arm -M mps2-an385 -nographic -monitor none \
    -semihosting-config enable=on,target=native -icount shift=0 \
    -kernel "$elf" </dev/null >"$stream"
status=$?
"$rt" receive "$stream" -o "$out"
rx=$?
if [ $status -ne 0 ]; then
    echo "qemu-run: firmware exited with status $status" >&2
    exit $status
fi
exit $rx
