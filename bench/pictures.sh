#!/bin/sh
# The pictures of README.md and docs/scenes.md, from the fixed-point
# build of build/host/rt (make build/host/rt first; make pictures does).
set -e
RT=${RT:-build/host/rt}
"$RT" scenes/bench/card.nff -o docs/card.png --size 320x240 --quiet              # one sample a pixel
"$RT" scenes/bench/whitted.nff -o docs/whitted.png --size 320x240 --aa 3 --quiet # adaptive anti-aliasing
"$RT" scenes/showpiece.nff -o docs/showpiece.png --size 400x400 --aa 3 --quiet
echo "pictures: docs/card.png docs/whitted.png docs/showpiece.png"
