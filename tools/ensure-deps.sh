#!/bin/sh
# ensure-deps.sh run [PACKAGE...] | host | test: installs what one command needs
# and is missing, and nothing else. The Makefile runs it first thing for
# make run (and host-run, image, profile) and for make test (and bench,
# stress, fuzz), so those two commands are all the set-up a user types.
#   run    the host build (gcc, make, binutils, the zlib and libpng
#          headers: build/host/rt, whose `rt receive` takes the board's
#          frame) plus the packages named: the board's BOARD_PACKAGES
#          (cross compiler, QEMU); none named: mps2-an385's
#   host   the host build alone (make host-run)
#   test   everything: every board's packages, the tests' and the
#          benchmarks' tools (clang, valgrind, cppcheck, cmake, python3)
#   (board and all: the same as run and test)
# A board whose emulator is an npm package (the Pico's, rp2040js, run by
# Node.js) has its runner in tools/emu/<board>/, which pins the package
# in its package.json and package-lock.json;
# `npm ci` installs it into that folder's node_modules/ (ignored by git)
# when nodejs is among the packages (BOARD=pico, and test). When npm does
# not trust the registry's certificate (a proxy that intercepts TLS), it
# tries once more with the system's certificates (ENSURE_DEPS_CA_BUNDLE,
# /etc/ssl/certs/ca-certificates.crt) before it gives up.
# Environment:
#   ENSURE_DEPS_FOR      the command, as the messages name it (the Makefile
#                        sets it: "make run (BOARD=pico)"); default "make
#                        run" or "make test" after the mode
#   ENSURE_DEPS_DRY_RUN  1: print what would be installed, install nothing,
#                        exit 0 (tests/static/deps-tests.sh)
#   ENSURE_DEPS_EMULATOR 0: the board's image only (make image): no npm ci
#                        of an emulator package, even with nodejs named
# A failure names the package, the command that needed it and apt's or
# npm's last error line, says what to do and exits 1.
set -e
cd "$(dirname "$0")/.."
mode=${1:-}
case $mode in
board) mode=run ;;
all) mode=test ;;
esac
case $mode in
run | host | test) ;;
*)
    echo "usage: sh tools/ensure-deps.sh run [PACKAGE...] | host | test" >&2
    echo "  (make run and make test run it themselves: they are the set-up)" >&2
    exit 2
    ;;
esac
shift
for_cmd=${ENSURE_DEPS_FOR:-make $mode}
say() { echo "ensure-deps: $*"; }
# BOARD_PACKAGES of the board.mk files named (the one list of them)
board_packages() {
    list=""
    for p in $(sed -n 's/^BOARD_PACKAGES *:= *//p' "$@"); do
        case " $list " in *" $p "*) ;; *) list="$list $p" ;; esac
    done
    echo $list
}
boards="$*"
[ -n "$boards" ] || boards=$(board_packages platform/mps2-an385/board.mk) # the default board's
[ "$mode" = host ] && boards=""
[ "$mode" = test ] && boards=$(board_packages platform/*/board.mk) # every board's
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'ok installed'; }
need=""
# the host build: build/host/rt (and rt-scenec, which compiles the scene
# into the firmware's tables)
command -v cc >/dev/null 2>&1 || need="$need gcc"
command -v make >/dev/null 2>&1 || need="$need make"
command -v ld >/dev/null 2>&1 || need="$need binutils"
[ -f /usr/include/zlib.h ] || installed zlib1g-dev || need="$need zlib1g-dev"
[ -f /usr/include/png.h ] || installed libpng-dev || need="$need libpng-dev"
# the boards: cross compilers, newlib (libm for the soft-float comparison), QEMU
npm_dirs=""
for p in $boards; do
    if [ "$p" = nodejs ]; then
        # any Node.js 18 or later with its npm will do (Debian's packages
        # are nodejs and npm; NodeSource's nodejs brings npm itself)
        command -v node >/dev/null 2>&1 || need="$need nodejs"
        [ "${ENSURE_DEPS_EMULATOR:-1}" = 0 ] && continue
        npm_dirs=$(ls tools/emu/*/package-lock.json 2>/dev/null | xargs -r -n1 dirname)
        command -v npm >/dev/null 2>&1 || need="$need npm"
        continue
    fi
    installed "$p" || need="$need $p"
done
if [ "$mode" = test ]; then
    command -v python3 >/dev/null 2>&1 || need="$need python3"   # stress suite, benchmarks, make size
    command -v valgrind >/dev/null 2>&1 || need="$need valgrind"   # make bench: callgrind
    command -v cppcheck >/dev/null 2>&1 || need="$need cppcheck"
    command -v cmake >/dev/null 2>&1 || need="$need cmake"   # tests/host/consumer-tests.sh
    # libFuzzer: clang and its runtime
    command -v clang >/dev/null 2>&1 || need="$need clang"
    ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1 ||
        ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a >/dev/null 2>&1 || need="$need libclang-rt-dev"
    # The sanitiser runtimes come with gcc's libasan/libubsan on Debian.
    if ! echo 'int main(void){return 0;}' | cc -x c -fsanitize=address,undefined -o /dev/null - >/dev/null 2>&1; then
        need="$need libasan8 libubsan1"
    fi
    # ThreadSanitizer (build/tsan/rt, tests/host/threads-tests.sh): gcc's libtsan
    if ! echo 'int main(void){return 0;}' | cc -x c -fsanitize=thread -o /dev/null - >/dev/null 2>&1; then
        need="$need libtsan2"
    fi
fi
# the npm packages a folder's package.json pins ("rp2040js@1.4.1")
npm_names() {
    sed -n '/"dependencies"/,/}/p' "$1/package.json" | grep -o '"[^"]*": *"[^"]*"' |
        sed 's/"\([^"]*\)": *"\([^"]*\)"/\1@\2/' | tr '\n' ' ' | sed 's/ $//'
}
npm_todo=""
for d in $npm_dirs; do
    command -v npm >/dev/null 2>&1 && (cd "$d" && npm ls --depth=0 >/dev/null 2>&1) && continue
    npm_todo="$npm_todo $d"
done

if [ "${ENSURE_DEPS_DRY_RUN:-0}" = 1 ]; then
    say "would install for $for_cmd:${need:- (no Debian package missing)}"
    for d in $npm_todo; do
        say "would install for $for_cmd: $(npm_names "$d") (npm ci in $d)"
    done
    exit 0
fi

log=$(mktemp "${TMPDIR:-/tmp}/ensure-deps.XXXXXX")
trap 'rm -f "$log"' EXIT
# last_error FILE: the last error line of apt's or npm's output
last_error() {
    line=$(grep -E '^(E:|Err:|npm ERR!|npm error)' "$1" | grep -vE 'A complete log of this run|_logs/' | tail -1)
    [ -n "$line" ] || line=$(grep -v '^[[:space:]]*$' "$1" | tail -1)
    printf '%s\n' "${line:-(no output)}"
}

if [ -n "$need" ]; then
    say "installing for $for_cmd:$need (apt-get; minutes on a fresh machine)"
    SUDO=""
    if [ "$(id -u)" != 0 ]; then
        if ! command -v sudo >/dev/null 2>&1; then
            say "could not install$need, needed by $for_cmd: installing needs root, and there is no sudo"
            say "what to do: run the command as root, or install sudo and allow this user to use it"
            exit 1
        fi
        SUDO="sudo"
    fi
    # wait for another install to finish rather than fail on its lock
    LOCK="-o DPkg::Lock::Timeout=600"
    # (apt-get update exits 0 when a mirror cannot be reached: its
    # warnings say so)
    $SUDO apt-get $LOCK update -qq >"$log" 2>&1 || echo "E: apt-get update failed" >>"$log"
    update_err=$(grep -E '^(E:|W:|Err:)' "$log" | grep -E 'fetch|resolv|connect|E:' | head -1)
    # without the packages' recommendations (QEMU's GUI and firmware, the
    # ARM toolchain's C++ library...): on a fresh Debian 12, make run's
    # download 175 MB instead of 721 MB, make test's 398 MB instead of 1080
    # shellcheck disable=SC2086
    if ! DEBIAN_FRONTEND=noninteractive $SUDO apt-get $LOCK install -y -qq --no-install-recommends $need >"$log" 2>&1; then
        err=$(last_error "$log")
        # the packages apt's errors name; none named (a download, the
        # network, a lock): all of them
        failed=""
        words=$(grep -E '^(E:|Err:| )' "$log" | tr -c 'a-z0-9.+-' '\n')
        for p in $need; do
            printf '%s\n' "$words" | grep -qxF "$p" && failed="$failed $p"
        done
        [ -n "$failed" ] || failed=$need
        say "could not install$failed, needed by $for_cmd: $err"
        [ -z "$update_err" ] || say "apt-get update had failed before: $update_err"
        say "what to do: run \`${SUDO:+sudo }apt-get update\` and the command again; check that this machine"
        say "  reaches its Debian mirror (/etc/apt/sources.list, /etc/apt/sources.list.d/) and that no other"
        say "  apt-get holds the lock; without root, run it as a user sudo allows. apt-get's last lines:"
        tail -5 "$log" | sed 's/^/    /'
        exit 1
    fi
fi

# the npm packages of those boards, as their lock files pin them
ca_bundle=${ENSURE_DEPS_CA_BUNDLE:-/etc/ssl/certs/ca-certificates.crt}
cert_errors='SELF_SIGNED_CERT_IN_CHAIN|UNABLE_TO_GET_ISSUER_CERT|UNABLE_TO_VERIFY_LEAF_SIGNATURE|DEPTH_ZERO_SELF_SIGNED_CERT|CERT_UNTRUSTED|unable to verify the first certificate|self.signed certificate'
for d in $npm_todo; do
    names=$(npm_names "$d")
    say "installing for $for_cmd: $names (npm ci in $d)"
    ok=1
    (cd "$d" && npm ci --no-audit --no-fund --loglevel=error) >"$log" 2>&1 || ok=0
    # npm does not trust the registry's certificate (a proxy that
    # intercepts TLS, whose CA the system trusts but Node does not): once
    # more with the system's certificates, unless npm has a cafile already
    if [ $ok = 0 ] && grep -qE "$cert_errors" "$log" && [ -f "$ca_bundle" ] &&
        [ "$(npm config get cafile 2>/dev/null)" != "$ca_bundle" ]; then
        say "npm does not trust the registry's certificate (a proxy that intercepts TLS?):"
        say "  once more with the system's, NODE_EXTRA_CA_CERTS=$ca_bundle npm ci --cafile=$ca_bundle"
        (cd "$d" && NODE_EXTRA_CA_CERTS=$ca_bundle npm ci --no-audit --no-fund --loglevel=error --cafile="$ca_bundle") \
            >"$log" 2>&1 && ok=1
        [ $ok = 0 ] || say "installed with the system's certificates (npm config set cafile $ca_bundle makes npm use them always)"
    fi
    if [ $ok = 0 ]; then
        code=$(grep -oE '(npm ERR!|npm error) code [A-Z_]+' "$log" | tail -1 | sed 's/.* code //')
        say "could not install $names (npm ci in $d), needed by $for_cmd: $(last_error "$log")"
        say "${code:+npm's error code is $code. }The other boards need no Node.js (make run renders on mps2-an385)."
        cat <<EOF
ensure-deps: what to do: if npm cannot reach https://registry.npmjs.org, check the network and npm's proxy
  (npm config get https-proxy; HTTPS_PROXY). Behind a proxy that intercepts TLS (errors such as
  SELF_SIGNED_CERT_IN_CHAIN, UNABLE_TO_GET_ISSUER_CERT_LOCALLY, unable to verify the first certificate),
  put the proxy's CA certificate in /usr/local/share/ca-certificates/, run update-ca-certificates, and
  give Node and npm the system's certificates, then run the command again:
    export NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt   # or: export NODE_OPTIONS=--use-openssl-ca
    npm config set cafile /etc/ssl/certs/ca-certificates.crt
  (npm's cafile, when set, is all npm trusts, NODE_EXTRA_CA_CERTS included: npm config get cafile)
  npm's last lines:
EOF
        tail -5 "$log" | sed 's/^/    /'
        exit 1
    fi
done
exit 0
