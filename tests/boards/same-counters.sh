#!/bin/sh
# same-counters.sh HOST_STATS BOARD_REPORT [rays]: compares the core's
# counters (include/rt_stats.h keys) of `rt --stats` with a board's report.
# Prints "N counters equal" and exits 0 when at least 10 keys are shared
# (5 with `rays`) and all agree; otherwise prints each difference (or the
# count) and exits 1. `rays`: only the ray counts (eye_rays, eye_hits,
# *_rays), for a frame split between cores, whose per-core caches (the
# last blocker per light) change how many tests and nodes a ray costs.
awk -v rays="$3" 'NR == FNR { host[$1] = $2; next }
     rays != "" && $1 != "eye_hits" && $1 !~ /_rays$/ { next }
     ($1 in host) { n++; if (host[$1] != $2) { print "differ: " $1 " board " $2 " host " host[$1]; bad = 1 } }
     END { if (bad) exit 1; print n + 0 (rays != "" ? " ray counters equal" : " counters equal"); exit !(n >= (rays != "" ? 5 : 10)) }' "$1" "$2"
