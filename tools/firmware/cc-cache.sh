#!/bin/sh
# cc-cache.sh CACHE FW_DIR CC ARGS... -c SOURCE -o OBJECT
# Compiles as CC ARGS would, unless an earlier compile had the same
# preprocessed source and the same flags: then it copies that one's object
# (and its .su and .ci, -fstack-usage's and -fcallgraph-info's). The
# test suites build one firmware after another that differ in the scene,
# size or format, and most of the core's files preprocess to the same text
# for all of them (app/firmware/firmware.mk uses it when FW_CACHE is set;
# tests/run-all.py sets it and empties the folder at its start).
#
# The key: the flags without -D, -U, -I and -include (the preprocessed
# text holds what they do), and the preprocessed text, with the build
# folder FW_DIR written as @FW_DIR@ in both, so that the same source seen
# from two build folders (its scene_data.h on the include path) matches.
# A source inside FW_DIR (the scene's tables) is compiled every time.
cache=$1 fwdir=$2
shift 2
# the rule's layout: CC ARGS... -c SOURCE -o OBJECT
[ $# -gt 4 ] || exec "$@"
eval "c=\${$(($# - 3))} src=\${$(($# - 2))} o=\${$(($# - 1))} out=\${$#}"
[ "$c" = -c ] && [ "$o" = -o ] || exec "$@"
case $src in
    "$fwdir"/*) exec "$@" ;;
esac
# "$@" becomes CC ARGS; flags, the ones that are not the preprocessor's
n=$# i=0 skip=0 flags=""
for a; do
    i=$((i + 1))
    [ $i -le $((n - 4)) ] || continue
    set -- "$@" "$a"
    if [ $skip = 1 ]; then
        skip=0
    else
        case $a in
            -include) skip=1 ;;
            -D* | -U* | -I*) ;;
            *) flags="$flags $a" ;;
        esac
    fi
done
shift $n
base=${out%.o}
key=$({ echo "$flags" && "$@" -E "$src"; } | sed "s#$fwdir#@FW_DIR@#g" | sha1sum | cut -c1-40) ||
    exec "$@" -c "$src" -o "$out"
entry=$cache/$key
if [ -f "$entry/o" ] && cp "$entry/o" "$out"; then
    for x in su ci; do
        if [ -f "$entry/$x" ]; then
            sed "s#@FW_DIR@#$fwdir#g" "$entry/$x" >"$base.$x"
        else
            rm -f "$base.$x"
        fi
    done
    exit 0
fi
rm -f "$base.su" "$base.ci"
"$@" -c "$src" -o "$out" || exit
# stored whole or not at all: a folder renamed into place (two suites
# that compile the same file at once each store theirs; one stays)
mkdir -p "$cache" && tmp=$(mktemp -d "$cache/.new.XXXXXX") || exit 0
cp "$out" "$tmp/o"
for x in su ci; do
    if [ -f "$base.$x" ]; then
        sed "s#$fwdir#@FW_DIR@#g" "$base.$x" >"$tmp/$x"
    fi
done
mv -T "$tmp" "$entry" 2>/dev/null || rm -rf "$tmp"
exit 0
