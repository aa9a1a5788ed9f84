#!/bin/sh
# The core's global symbols all carry the library's prefix (rt_ or RT_),
# so the core links into anyone's firmware without a clash: nm over each
# backend's objects of the core (src/*.c, src/*/*.c) (default: the hosted builds).
B=${1:-build/host}
. tests/lib/check.sh
for backend in fixed double float double_ftol; do
    bad="" n=0
    for c in src/*.c src/*/*.c; do
        o="$B/$backend/${c#src/}"
        o="${o%.c}.o"
        [ -f "$o" ] || { bad="$bad (missing $o)"; continue; }
        n=$((n + $(nm -g --defined-only "$o" | awk 'NF == 3' | wc -l)))
        bad="$bad$(nm -g --defined-only "$o" | awk -v f="$(basename "$c")" 'NF == 3 && $3 !~ /^(rt_|RT_)/ { printf " %s:%s", f, $3 }')"
    done
    if [ -z "$bad" ] && [ $n -gt 0 ]; then
        ok "$backend: $n global symbols, all rt_/RT_"
    else
        bad "$backend: unprefixed (add to src/rt_prefix.h):$bad"
    fi
done
summary symbols
