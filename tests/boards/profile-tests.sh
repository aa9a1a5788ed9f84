#!/bin/sh
# make profile (bench/profile.py) on two boards and instruction sets:
# balls-2 at 32x32 on mps2-an385 (Cortex-M3; the firmware ports-tests.sh
# builds) and gears-1, which refracts, at 12x12 on sifive_e (RISC-V):
#  - the profile's total within 0.1% of the firmware's render_instructions;
#  - the groups, the ray kinds and the group x kind matrix each sum to it,
#    and every function executed is in a group;
#  - trace_ray entries per kind equal the firmware's eye_rays, reflect_rays,
#    refract_rays, scene_occluded entries its shadow_rays (no patches here),
#    and every kind the scene has got instructions;
#  - the attribution against extents measured on their own (bench/cycles.py
#    --from-symbol, on the RISC-V run): shadow instructions equal those
#    inside rt_scene_occluded, eye + reflection + refraction + shadow those
#    inside rt_trace_ray.
. tests/lib/check.sh
OUT=build/test-profile
mkdir -p "$OUT"

# field EXPR: evaluates a Python expression over the profile's JSON (d)
field() { python3 -c "import json, sys; d = json.load(open(sys.argv[1])); print($2)" "$1"; }

# sums JSON: groups, kinds and matrix each add up to the total
sums() {
    python3 - "$1" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
t = d["instructions"]
g = sum(v["instructions"] for v in d["groups"].values())
k = sum(v["instructions"] for v in d["kinds"].values())
m = sum(sum(r.values()) for r in d["matrix"].values())
f = sum(v["instructions"] for v in d["functions"].values())
print("total %d, groups %d, kinds %d, matrix %d, functions %d" % (t, g, k, m, f))
sys.exit(0 if t == g == k == m == f and t > 0 else 1)
EOF
}

# rays JSON KIND...: the kinds' ray counts equal the firmware's counters,
# each of the KINDs named has rays and instructions, and the profiler
# made checks of its own and every one passed
rays() {
    python3 - "$@" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
key = {"eye": "eye_rays", "reflection": "reflect_rays", "refraction": "refract_rays", "shadow": "shadow_rays"}
ok, out = True, []
for k, c in key.items():
    got, fw = d["kinds"].get(k, {}).get("rays", 0), d["firmware"].get(c)
    ok &= got == fw
    out.append("%s %s/%s" % (k, got, fw))
for k in sys.argv[2:]:
    ok &= d["kinds"][k]["rays"] > 0 and d["kinds"][k]["instructions"] > 0
# the profiler's own checks: none at all is a failure, not a pass
checks = d.get("checks") or []
ok &= bool(checks) and all(c["ok"] for c in checks)
out.append("%d profiler checks" % len(checks))
print("counted/firmware: " + ", ".join(out))
sys.exit(0 if ok else 1)
EOF
}

total() {
    python3 - "$1" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
ri = d["firmware"]["render_instructions"]
diff = 100.0 * (d["instructions"] - ri) / ri
print("%d counted, render_instructions %d: %+.4f%%, %.0f instr/px" % (d["instructions"], ri, diff,
                                                                      d["instructions"] / d["pixels"]))
sys.exit(0 if abs(diff) <= 0.1 else 1)
EOF
}

grouped() {
    o=$(field "$1" '" ".join(d["groups"]["other"]["functions"])')
    echo "other: ${o:-none}"
    [ -z "$o" ]
}

# same JSON KINDS CYCLES-JSON: the kinds' instructions sum to the extent cycles.py measured
same() {
    a=$(field "$1" "sum(d['kinds'][k]['instructions'] for k in '$2'.split(','))")
    b=$(field "$3" 'd["instructions"]')
    echo "$2: $a, cycles.py: $b"
    [ "$a" = "$b" ] && [ "$a" -gt 0 ]
}

echo "profile: make profile, its totals, ray counts and attribution"
for run in "mps2-an385 scenes/spd/balls-2.nff 32x32 eye,reflection,shadow" \
           "sifive_e scenes/spd/gears-1.nff 12x12 eye,reflection,refraction,shadow"; do
    set -- $run
    b=$1 s=$2 size=$3 kinds=$4
    n=$b-$(basename $s .nff)
    t0=$(date +%s)
    vars="BOARD=$b SCENE=$s SIZE=$size DEPTH=5"
    make -s -j2 firmware AA=0 $vars >"$OUT/$n.build" 2>&1
    if ! make -s profile AA=0 $vars PROFILE_JSON="$OUT/$n.json" >"$OUT/$n.txt" 2>&1; then
        check "$n: make profile" sh -c "tail -20 '$OUT/$n.txt'; false"
        continue
    fi
    check "$n: make profile" echo "$(($(date +%s) - t0)) s"
    check "$n: total" total "$OUT/$n.json"
    check "$n: sums" sums "$OUT/$n.json"
    check "$n: grouped" grouped "$OUT/$n.json"
    check "$n: ray counts" rays "$OUT/$n.json" $(echo $kinds | tr , ' ')
    if [ $b = sifive_e ]; then
        eval "$(make -s board-info AA=0 $vars KEEP_FRAMES=1)" # the ELF make profile built
        for f in rt_scene_occluded rt_trace_ray; do
            python3 bench/cycles.py "$elf" --machine $b --from-symbol $f --top 0 --json "$OUT/$n-$f.json" \
                >"$OUT/$n-$f.txt" 2>&1
        done
        check "$n: shadow extent" same "$OUT/$n.json" shadow "$OUT/$n-rt_scene_occluded.json"
        check "$n: trace_ray extent" same "$OUT/$n.json" eye,reflection,refraction,shadow \
            "$OUT/$n-rt_trace_ray.json"
    fi
done
summary profile
