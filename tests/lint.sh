#!/bin/sh
# Static checks: cppcheck on the core (src/) must report nothing.
out=$(cppcheck --enable=warning,style,performance,portability --std=c11 --quiet --error-exitcode=1 \
    -Isrc --suppress=missingIncludeSystem --max-configs=32 src/ 2>&1)
if [ $? -eq 0 ] && [ -z "$out" ]; then
    echo "  ok    cppcheck src/: no findings"
    echo "lint: 1 passed, 0 failed"
else
    echo "  FAIL  cppcheck src/:"
    echo "$out"
    echo "lint: 0 passed, 1 failed"
    exit 1
fi
