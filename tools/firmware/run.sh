#!/bin/sh
# run.sh FIRMWARE.elf OUT.png RT [CLOCK_HZ]: run the firmware on the
# emulated board ($QEMU: the QEMU binary and machine, from board.mk),
# decode its UART stream into OUT.png and print its report lines, then
# how long QEMU took on the host. (CLOCK_HZ: unused, the runners' common
# arguments.)
# Exits non-zero when QEMU, the firmware or the stream fails.
# $QEMU_ICOUNT is the board's -icount option (BOARD_ICOUNT, default
# shift=0); $QEMU_ACCEL, when set (e.g. "-accel tcg,thread=multi": the
# cores of a multi-core board really in parallel), replaces -icount, and
# the instruction counts are then host time, not instructions.
# With RUN_END=report (a board built for silicon, with no semihosting:
# BOARD_ARCH_SKIP) the firmware ends with an "exit_status N" report line
# and sleeps, and QEMU, which does not exit on WFI, is stopped there.
elf=$1 out=$2 rt=$3
stream="${elf%.elf}.stream"
clock="${QEMU_ACCEL:--icount ${QEMU_ICOUNT:-shift=0}}"
t0=$(date +%s.%N)
if [ "$RUN_END" = report ]; then
    # emptied first: the loop below may read it before the background
    # QEMU's redirection does, and must not find the last run's exit_status
    : >"$stream"
    $QEMU -nographic -monitor none $clock -kernel "$elf" </dev/null >"$stream" 2>"$stream.err" &
    pid=$!
    end=$(($(date +%s) + 900))
    status=124
    while kill -0 $pid 2>/dev/null; do
        if grep -aq 'exit_status [0-9]' "$stream"; then
            sleep 0.2 # (the rest of the line, a few bytes)
            status=$(grep -ao 'exit_status [0-9]*' "$stream" | tail -1 | cut -d' ' -f2)
            break
        fi
        [ "$(date +%s)" -ge $end ] && break
        sleep 0.1
    done
    kill $pid 2>/dev/null
    wait $pid 2>/dev/null
    # QEMU that ended by itself, before any exit_status line: its failure
    [ $status = 124 ] && [ "$(date +%s)" -lt $end ] && status=1 && cat "$stream.err" >&2
    [ $status = 124 ] && echo "qemu-run: no exit_status line in 900 s" >&2
else
    timeout 900 $QEMU -nographic -monitor none \
        -semihosting-config enable=on,target=native $clock \
        -kernel "$elf" </dev/null >"$stream"
    status=$?
fi
t1=$(date +%s.%N)
report=$("$rt" receive "$stream" -o "$out")
rx=$?
[ -n "$report" ] && printf '%s\n' "$report"
if [ $status -ne 0 ]; then
    echo "qemu-run: firmware exited with status $status" >&2
    exit $status
fi
[ $rx -ne 0 ] && exit $rx
# (the time on the board: make run's summary.sh, from the cycles an
# instruction make bench measured; -icount shift=0 counts instructions,
# one per virtual ns, not cycles)
if [ -n "$QEMU_ACCEL" ]; then
    echo "($QEMU_ACCEL instead of -icount: the instruction counts above are host time)"
fi
awk -v t0="$t0" -v t1="$t1" 'BEGIN { printf "QEMU wall time on the host (boot, render, UART stream): %.1f s\n", t1 - t0 }'
exit 0
