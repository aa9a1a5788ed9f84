#!/bin/sh
# The user configuration file (RT_CONFIG_FILE, as LVGL's lv_conf.h): its
# values replace rt_config.h's defaults in everything that includes rt.h,
# and an out-of-range value stops the build with the check's message.
OUT=${1:-build/test-config}
mkdir -p "$OUT"
. tests/lib/check.sh

cat >"$OUT/my_rt_config.h" <<'H'
#define RT_MAX_DEPTH 3
#define RT_MAX_SPHERES 7
H
cat >"$OUT/use.c" <<'C'
#include "rt.h"
_Static_assert(RT_MAX_DEPTH == 3 && RT_MAX_SPHERES == 7, "the user file's values");
_Static_assert(RT_MAX_CONES == 256, "a default the user file leaves alone");
int main(void) { return 0; }
C
if cc -std=c11 -Wall -Wextra -Werror -Iinclude -Isrc -I"$OUT" -DRT_CONFIG_FILE="\"my_rt_config.h\"" -c "$OUT/use.c" \
      -o "$OUT/use.o" 2>"$OUT/use.err"; then
    ok "RT_CONFIG_FILE replaces defaults (RT_MAX_DEPTH 3, RT_MAX_SPHERES 7), keeps the rest"
else
    bad "RT_CONFIG_FILE: $(head -3 "$OUT/use.err")"
fi
if ! cc -std=c11 -Iinclude -Isrc -c "$OUT/use.c" -o "$OUT/use.o" 2>/dev/null; then
    ok "without RT_CONFIG_FILE the defaults apply (the user file's asserts fail)"
else
    bad "without RT_CONFIG_FILE the user values still applied"
fi
for case in "RT_MAX_DEPTH 99:RT_MAX_DEPTH out of 1..16" "RT_MAX_LIGHTS 0:RT_MAX_LIGHTS out of 1..255" \
            "FX_FRAC_BITS 30:FX_FRAC_BITS out of 8..20"; do
    def=${case%%:*} want=${case#*:}
    echo "#define $def" >"$OUT/bad_config.h"
    if ! cc -std=c11 -Iinclude -Isrc -I"$OUT" -DRT_CONFIG_FILE="\"bad_config.h\"" -c "$OUT/use.c" -o "$OUT/bad.o" \
           2>"$OUT/bad.err" && grep -q "#error \"$want\"" "$OUT/bad.err"; then
        ok "$def: the build stops with '$want'"
    else
        bad "$def: $(grep -m1 error "$OUT/bad.err")"
    fi
done
# rt.h is all a user includes, and it includes only rt_*.h headers (none
# of the core's internal ones, which are not installed).
printf '#include "rt.h"\n' >"$OUT/only.c"
if cc -std=c11 -Iinclude -H -fsyntax-only "$OUT/only.c" 2>"$OUT/only.h.txt"; then
    own=$(sed -n 's/^\.* //p' "$OUT/only.h.txt" | grep -v '^/' | sort -u)
    other=$(echo "$own" | grep -v '^include/rt[_.a-z0-9]*\.h$' || true)
    if [ -z "$other" ] && echo "$own" | grep -q 'include/rt_fb.h'; then
        ok "rt.h needs include/ alone and includes only rt_*.h: $(echo $own | sed 's|include/||g')"
    else
        bad "rt.h pulls in internal headers: $other"
    fi
else
    bad "rt.h does not compile on its own: $(head -3 "$OUT/only.h.txt")"
fi
summary config-tests
