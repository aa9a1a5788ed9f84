#!/bin/sh
# ensure-deps.sh [board [PACKAGE...] | all]: installs the Debian packages
# that are missing.
#   board  what rendering needs: the host CLI (make host-run, and `rt
#          receive` for make run), plus the packages named (a board's
#          BOARD_PACKAGES: cross compiler, QEMU); none named: mps2-an385's
#   all    (default) every board's packages and the tests' and
#          benchmarks' tools
# A board whose emulator is an npm package (platform/pico: rp2040js, run
# by Node.js) pins it in its folder's package.json and package-lock.json;
# `npm ci` installs it into that folder's node_modules/ (ignored by git),
# for `all` and whenever nodejs is among the packages named.
set -e
cd "$(dirname "$0")/.."
mode=${1:-all}
case $mode in
board | all) ;;
*) echo "usage: sh platform/ensure-deps.sh [board [PACKAGE...] | all]" >&2; exit 2 ;;
esac
[ $# -gt 0 ] && shift
boards="$*"
[ -n "$boards" ] || boards="gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm"
# every board's (platform/*/board.mk, BOARD_PACKAGES)
[ "$mode" = all ] && boards="gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm gcc-riscv64-unknown-elf qemu-system-misc socat nodejs"
need=""
command -v cc >/dev/null 2>&1 || need="$need gcc"
command -v make >/dev/null 2>&1 || need="$need make"
command -v ld >/dev/null 2>&1 || need="$need binutils"
[ -f /usr/include/zlib.h ] || need="$need zlib1g-dev"
[ -f /usr/include/png.h ] || need="$need libpng-dev"
# the boards: cross compilers, newlib (libm for the soft-float comparison), QEMU
npm_boards=""
for p in $boards; do
    if [ "$p" = nodejs ]; then
        # any Node.js 18 or later with its npm will do (Debian's packages
        # are nodejs and npm; NodeSource's nodejs brings npm itself)
        npm_boards=$(ls platform/*/package-lock.json 2>/dev/null | xargs -r -n1 dirname)
        command -v node >/dev/null 2>&1 || need="$need nodejs"
        command -v npm >/dev/null 2>&1 || need="$need npm"
        continue
    fi
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || need="$need $p"
done
if [ "$mode" = all ]; then
    command -v python3 >/dev/null 2>&1 || need="$need python3"   # stress suite, benchmarks, make size
    command -v valgrind >/dev/null 2>&1 || need="$need valgrind"   # make bench: callgrind
    command -v cppcheck >/dev/null 2>&1 || need="$need cppcheck"
    command -v cmake >/dev/null 2>&1 || need="$need cmake"   # tests/consumer-tests.sh
    # libFuzzer: clang and its runtime
    command -v clang >/dev/null 2>&1 || need="$need clang"
    ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1 ||
        ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a >/dev/null 2>&1 || need="$need libclang-rt-dev"
    # The sanitiser runtimes come with gcc's libasan/libubsan on Debian.
    if ! echo 'int main(void){return 0;}' | cc -x c -fsanitize=address,undefined -o /dev/null - >/dev/null 2>&1; then
        need="$need libasan8 libubsan1"
    fi
    # ThreadSanitizer (build/tsan/rt, tests/threads-tests.sh): gcc's libtsan
    if ! echo 'int main(void){return 0;}' | cc -x c -fsanitize=thread -o /dev/null - >/dev/null 2>&1; then
        need="$need libtsan2"
    fi
fi
if [ -n "$need" ]; then
    echo "installing ($mode):$need"
    SUDO=""
    [ "$(id -u)" = 0 ] || SUDO="sudo"
    # wait for another install to finish rather than fail on its lock
    LOCK="-o DPkg::Lock::Timeout=600"
    $SUDO apt-get $LOCK update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get $LOCK install -y -qq $need >/dev/null
fi
# the npm packages of those boards, as their lock files pin them
for d in $npm_boards; do
    if ! (cd "$d" && npm ls --depth=0 >/dev/null 2>&1); then
        echo "installing ($mode): npm ci in $d"
        (cd "$d" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
    fi
done
