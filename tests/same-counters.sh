#!/bin/sh
# same-counters.sh HOST_STATS BOARD_REPORT: compares the core's counters
# (src/rt_stats.h keys) of `rt --stats` with a board's report. Prints
# "N counters equal" and exits 0 when at least 10 keys are shared and all
# agree; otherwise prints each difference (or the count) and exits 1.
awk 'NR == FNR { host[$1] = $2; next }
     ($1 in host) { n++; if (host[$1] != $2) { print "differ: " $1 " board " $2 " host " host[$1]; bad = 1 } }
     END { if (bad) exit 1; print n + 0 " counters equal"; exit !(n >= 10) }' "$1" "$2"
