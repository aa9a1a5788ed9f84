#!/bin/sh
# tools/ensure-deps.sh on a machine where nothing is installed: a PATH
# of the few tools the script runs plus stubs (dpkg-query knows no package,
# apt-get and npm succeed or fail as asked, id says root), so
#  - make run (the default board) asks for the host build and the ARM
#    toolchain and QEMU only: no clang, valgrind, cppcheck, RISC-V, Node.js;
#  - make run BOARD=pico asks for Node.js, npm and the pinned rp2040js;
#    make image BOARD=pico (deps-image) for Node.js (uf2.mjs) and the ARM
#    compiler only, no npm, no rp2040js; make image BOARD=stm32f4 no QEMU;
#  - make test asks for everything;
#  - a failing apt-get names the package and the command and exits 1;
#  - a failing npm names rp2040js and the command and gives the proxy
#    certificates' advice.
# No package is installed: the dry runs install nothing, the stubs nothing.
OUT=${1:-build/test-deps}
. tests/lib/check.sh
MAKE_BIN=$(command -v make)
rm -rf "$OUT" && mkdir -p "$OUT/bin" "$OUT/npm"
for t in sh dirname ls xargs grep sed tr tail head cat rm mktemp env awk; do
    p=$(command -v "$t") && ln -s "$p" "$OUT/bin/$t"
done
cat >"$OUT/bin/dpkg-query" <<'EOF'
#!/bin/sh
exit 1
EOF
cat >"$OUT/bin/id" <<'EOF'
#!/bin/sh
echo "${STUB_UID:-0}"
EOF
# apt-get: logs its arguments; APT_FAIL=PKG: install fails as apt does
# for a package it cannot find; APT_OFFLINE=1: as apt does without its
# mirror (update warns and exits 0, install finds no package)
cat >"$OUT/bin/apt-get" <<'EOF'
#!/bin/sh
echo "apt-get $*" >>"$STUB_LOG"
case " $* " in
*" update "*)
    if [ -n "$APT_OFFLINE" ]; then
        echo "W: Failed to fetch http://deb.debian.org/debian/dists/bookworm/InRelease  Temporary failure resolving 'deb.debian.org'"
        echo "W: Some index files failed to download. They have been ignored, or old ones used instead."
    fi ;;
*" install "*)
    if [ -n "$APT_OFFLINE" ]; then
        for a; do case $a in -*|install|DPkg*) ;; *) echo "E: Unable to locate package $a" ;; esac; done
        exit 100
    fi
    if [ -n "$APT_FAIL" ]; then
        echo "Reading package lists..."
        echo "E: Unable to locate package $APT_FAIL"
        exit 100
    fi ;;
esac
exit 0
EOF
# npm (on PATH only for the npm tests): ls finds nothing; ci fails as
# behind a TLS-intercepting proxy (NPM_CAFILE_OK=1: not with --cafile)
cat >"$OUT/npm/npm" <<'EOF'
#!/bin/sh
echo "npm $*" >>"$STUB_LOG"
case $1 in
ls) exit 1 ;;
config) echo null ;;
ci)
    case "$NPM_CAFILE_OK $*" in 1*--cafile=*) exit 0 ;; esac
    echo "npm error code SELF_SIGNED_CERT_IN_CHAIN"
    echo "npm error errno SELF_SIGNED_CERT_IN_CHAIN"
    echo "npm error request to https://registry.npmjs.org/rp2040js failed, reason: self-signed certificate in certificate chain"
    exit 1 ;;
esac
exit 0
EOF
chmod +x "$OUT/bin/dpkg-query" "$OUT/bin/id" "$OUT/bin/apt-get" "$OUT/npm/npm"
STUB_LOG=$PWD/$OUT/stub.log
export STUB_LOG
# stub CMD...: runs CMD with only the stubs on PATH (NPM=1: npm's too)
stub() { env PATH="$PWD/$OUT/bin${NPM:+:$PWD/$OUT/npm}" "$@" 2>&1; }
# has TEXT WORD...: each word is a word of the text
has() { t=$1; shift; for w; do printf '%s\n' "$t" | tr ' ' '\n' | grep -qxF "$w" || return 1; done; }
# lacks TEXT PATTERN: no word of the text matches the pattern (grep -E)
lacks() { ! printf '%s\n' "$1" | tr ' ' '\n' | grep -qE "$2"; }
# fails_saying WHAT PATTERN...: the run before ($out, its exit $status)
# failed, and its output has a line matching each pattern (grep); one
# check, its line the first pattern's line
fails_saying() {
    _what=$1
    shift
    if [ "$status" -eq 0 ]; then
        bad "$_what: exit 0: $out"
        return
    fi
    for _p; do
        printf '%s\n' "$out" | grep -q -- "$_p" || { bad "$_what: exit $status, no line '$_p': $out"; return; }
    done
    ok "$_what: exit $status, $(printf '%s\n' "$out" | grep -m1 -- "$1" | cut -c1-100)"
}
not_run='^(clang|valgrind|cppcheck|cmake|python3|socat|libclang-rt-dev|libtsan2|gcc-riscv64-unknown-elf|qemu-system-misc|nodejs|npm|rp2040js.*)$'

# the package sets, through the Makefile as a user runs it
out=$(ENSURE_DEPS_DRY_RUN=1 stub "$MAKE_BIN" -s deps-board)
line=$(printf '%s\n' "$out" | grep 'would install for make run (BOARD=mps2-an385):')
if has "$line" gcc binutils make gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm && lacks "$out" "$not_run"; then
    ok "make run: the host build, the ARM toolchain and QEMU only:${line#*:}"
else
    bad "make run: $out"
fi
out=$(ENSURE_DEPS_DRY_RUN=1 stub "$MAKE_BIN" -s deps-board BOARD=pico)
if has "$out" nodejs npm gcc-arm-none-eabi rp2040js@1.4.1 && printf '%s\n' "$out" | grep -q 'for make run (BOARD=pico)' &&
    lacks "$out" '^(qemu-system-.*|clang|valgrind|cppcheck|gcc-riscv64-unknown-elf)$'; then
    ok "make run BOARD=pico: Node.js, npm, rp2040js, the ARM compiler, no QEMU: $(echo $out | sed 's/ensure-deps: would install for make run (BOARD=pico)://g')"
else
    bad "make run BOARD=pico: $out"
fi
out=$(ENSURE_DEPS_DRY_RUN=1 stub "$MAKE_BIN" -s deps-image BOARD=pico)
if has "$out" nodejs gcc-arm-none-eabi && printf '%s\n' "$out" | grep -q 'for make image (BOARD=pico)' &&
    lacks "$out" '^(npm|rp2040js.*|qemu-system-.*)$' && ! grep -q 'npm' "$STUB_LOG" 2>/dev/null; then
    ok "make image BOARD=pico: Node.js (uf2.mjs) and the ARM compiler, no npm or rp2040js:$(echo $out | sed 's/ensure-deps: would install for make image (BOARD=pico)://g')"
else
    bad "make image BOARD=pico: $out"
fi
out=$(ENSURE_DEPS_DRY_RUN=1 stub "$MAKE_BIN" -s deps-image BOARD=stm32f4)
if has "$out" gcc-arm-none-eabi libnewlib-arm-none-eabi && lacks "$out" '^(qemu-system-.*|nodejs|npm)$'; then
    ok "make image BOARD=stm32f4: the ARM toolchain, no QEMU"
else
    bad "make image BOARD=stm32f4: $out"
fi
out=$(ENSURE_DEPS_DRY_RUN=1 stub "$MAKE_BIN" -s deps-host)
if printf '%s\n' "$out" | grep -qxF 'ensure-deps: would install for make host-run: gcc make binutils'; then
    ok "make host-run: the host build only (gcc make binutils)"
else
    bad "make host-run: $out"
fi
out=$(ENSURE_DEPS_DRY_RUN=1 stub "$MAKE_BIN" -s deps)
if has "$out" gcc gcc-arm-none-eabi qemu-system-arm gcc-riscv64-unknown-elf qemu-system-misc socat nodejs npm \
    clang valgrind cppcheck cmake python3 rp2040js@1.4.1 && printf '%s\n' "$out" | grep -q 'for make test:'; then
    ok "make test: everything ($(printf '%s\n' "$out" | head -1 | cut -d: -f3- | wc -w) Debian packages and rp2040js)"
else
    bad "make test: $out"
fi
: >"$STUB_LOG"
out=$(ENSURE_DEPS_DRY_RUN=1 stub sh tools/ensure-deps.sh run gcc-riscv64-unknown-elf qemu-system-misc)
if has "$out" gcc-riscv64-unknown-elf qemu-system-misc && lacks "$out" '^(gcc-arm-none-eabi|qemu-system-arm|nodejs)$' &&
    [ ! -s "$STUB_LOG" ]; then
    ok "run with a board's packages (sifive_e): those, not the default board's; a dry run calls no apt-get"
else
    bad "run sifive_e: $out; $(cat "$STUB_LOG")"
fi

# a failing apt-get: the package, the command, what to do, exit 1
out=$(APT_FAIL=qemu-system-arm ENSURE_DEPS_FOR='make run (BOARD=mps2-an385)' stub sh tools/ensure-deps.sh run)
status=$?
fails_saying "apt-get fails" \
    '^ensure-deps: could not install qemu-system-arm, needed by make run (BOARD=mps2-an385): E: Unable to locate package qemu-system-arm$' \
    'what to do: run `apt-get update`'

# no mirror: every package named, and apt-get update's warning
out=$(APT_OFFLINE=1 stub sh tools/ensure-deps.sh run)
status=$?
fails_saying "no mirror (every package named)" "^ensure-deps: apt-get update had failed before: W: Failed to fetch" \
    "^ensure-deps: could not install gcc make binutils gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm, needed by make run: E: Unable to locate package"

# not root and no sudo: says so, exit 1, no apt-get
: >"$STUB_LOG"
out=$(STUB_UID=1000 stub sh tools/ensure-deps.sh run)
status=$?
if [ -s "$STUB_LOG" ]; then
    bad "not root, no sudo: apt-get ran: $(cat "$STUB_LOG")"
else
    fails_saying "not root, no sudo" \
        "^ensure-deps: could not install .*qemu-system-arm, needed by make run: installing needs root, and there is no sudo"
fi

# a failing npm ci: once more with the system's certificates, then
# rp2040js, the command, the certificates' advice, exit 1
echo "a certificate" >"$OUT/ca.crt"
ENSURE_DEPS_CA_BUNDLE=$PWD/$OUT/ca.crt
export ENSURE_DEPS_CA_BUNDLE
: >"$STUB_LOG"
out=$(NPM=1 NPM_CAFILE_OK=1 stub sh tools/ensure-deps.sh run gcc-arm-none-eabi nodejs)
status=$?
if [ $status -eq 0 ] && grep -q "npm ci .*--cafile=$ENSURE_DEPS_CA_BUNDLE" "$STUB_LOG" &&
    printf '%s\n' "$out" | grep -q "installed with the system's certificates"; then
    ok "npm ci fails on the proxy's certificate: once more with the system's (--cafile, NODE_EXTRA_CA_CERTS), installed"
else
    bad "npm ci with the system's certificates: exit $status: $out; $(cat "$STUB_LOG")"
fi
out=$(NPM=1 ENSURE_DEPS_FOR='make run (BOARD=pico)' stub sh tools/ensure-deps.sh run gcc-arm-none-eabi nodejs)
status=$?
fails_saying "npm ci fails (NODE_EXTRA_CA_CERTS, cafile)" \
    '^ensure-deps: could not install rp2040js@1.4.1 (npm ci in tools/emu/pico), needed by make run (BOARD=pico): npm error' \
    'SELF_SIGNED_CERT_IN_CHAIN' 'NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt' 'NODE_OPTIONS=--use-openssl-ca' \
    'npm config set cafile'

out=$(stub sh tools/ensure-deps.sh build 2>&1)
status=$?
if [ $status -eq 2 ] && printf '%s\n' "$out" | grep -q '^usage: '; then
    ok "an unknown mode: usage, exit 2"
else
    bad "an unknown mode: exit $status: $out"
fi

summary deps-tests
