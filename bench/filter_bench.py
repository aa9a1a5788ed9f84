#!/usr/bin/env python3
"""What filtered textures cost and buy, on the boards' firmware.

Each scene is rendered one sample a pixel at 320x240 by the firmware
twice: with filtered textures (the default: ray cones, each texture
averaged over the pixel's footprint) and with TEXTURE_FILTER=0 (textures
sampled at the hit point, no ray cones linked), and this records
  - instructions per pixel inside the render (QEMU -icount shift=0) and
    their ratio, filtered over point-sampled;
  - code bytes (text, vectors, exidx; the scene tables are data);
  - the error against the pixel-area image (rt --double --spp 16
    --texture-filter off: what a viewer sees).
balls-2 has no texture: its two builds must be the same code.
It writes bench/filter.md.

  bench/filter_bench.py [--boards a,b] [--scenes a,b] [--size WxH]
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boards_bench import ROOT, code_ram, run  # noqa: E402
from boards_bench import measure as boards_measure  # noqa: E402
from scenes_bench import SCENES, error, scene_path  # noqa: E402

OUT = os.path.join(ROOT, "build", "bench-filter")
SCENE_DEPTH = dict(SCENES, **{"balls-2": 5})
BOARD_BACKENDS = {"mps2-an385": "fixed", "mps2-an386": "float"}


def path_of(scene):
    return scene_path(scene) if scene in SCENES else os.path.join("scenes", "spd", scene + ".nff")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--boards", default="mps2-an385,mps2-an386")
    ap.add_argument("--scenes", default="card,picolib,whitted,balls-2")
    ap.add_argument("--size", default="320x240")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    run(["make", "-s", "build/host/rt"])
    rows = []
    for b in a.boards.split(","):
        be = BOARD_BACKENDS.get(b, "fixed")
        for s in a.scenes.split(","):
            got = {}
            for filt in ("1", "0"):
                m = boards_measure(b, be, s, a.size, path=path_of(s), depth=SCENE_DEPTH[s], out=OUT,
                                   variant="TEXTURE_FILTER=" + filt)
                if not m:
                    sys.exit("filter_bench: %s %s %s TEXTURE_FILTER=%s: build or run failed" % (b, be, s, filt))
                code, _ = code_ram(m["info"]["cross"], m["info"]["elf"])
                ref = reference_of(s, a.size, m["info"]["format"])
                psnr, _, over8 = error(m["png"], ref)
                got[filt] = (m["ipp"], code, psnr, over8)
            f, p = got["1"], got["0"]
            rows.append((b, be, s, f, p))
            print("%-11s %-6s %-8s filtered %6d instr/px %6d B %6s dB; point %6d instr/px %6d B %6s dB; %.2fx"
                  % (b, be, s, f[0], f[1], f[2], p[0], p[1], p[2], f[0] / p[0]), flush=True)
    with open(os.path.join(ROOT, "bench", "filter.md"), "w") as out:
        out.write("# Filtered textures on the boards (bench/filter_bench.py)\n\n"
                  "One sample a pixel, %s, one core; instructions a pixel inside the render (QEMU\n"
                  "-icount shift=0), code bytes (text, vectors and exidx), and the error against the\n"
                  "pixel-area image (rt --double --spp 16 --texture-filter off). Filtered: the\n"
                  "firmware's default; point-sampled: built with TEXTURE_FILTER=0.\n\n" % a.size)
        out.write("| board | backend | scene | filtered instr/px | point-sampled instr/px | cost | "
                  "filtered code (B) | point-sampled code (B) | filtered PSNR | point-sampled PSNR | "
                  "filtered > 8/255 | point-sampled > 8/255 |\n")
        out.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for b, be, s, f, p in rows:
            out.write("| %s | %s | %s | %s | %s | %.2fx | %s | %s | %s dB | %s dB | %s%% | %s%% |\n"
                      % (b, be, s, "{:,}".format(f[0]), "{:,}".format(p[0]), f[0] / p[0], "{:,}".format(f[1]),
                         "{:,}".format(p[1]), f[2], p[2], f[3], p[3]))
    print("wrote bench/filter.md")


def reference_of(scene, size, fmt):
    # cached per build of rt: a reference from an older build would be stale
    ref = os.path.join(OUT, "ref-%s-%s-%s-%d.png" % (scene, size, fmt, int(os.path.getmtime("build/host/rt"))))
    if not os.path.exists(ref):
        run(["build/host/rt", path_of(scene), "-o", ref, "--double", "--size", size, "--depth",
             str(SCENE_DEPTH[scene]), "--format", fmt, "--spp", "16", "--texture-filter", "off", "--quiet"])
    return ref


if __name__ == "__main__":
    main()
