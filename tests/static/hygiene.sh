#!/bin/sh
# Hygiene: the repository root holds only the entries the README's layout
# table names (the first path component of each row's paths), counting
# tracked files and untracked ones git does not ignore.
. tests/lib/check.sh
allowed=$(sed -n '/^## Layout/,/^## /p' README.md | grep '^| `' | cut -d'|' -f2 |
          grep -o '`[^`]*`' | tr -d '`' | cut -d/ -f1 | sort -u)
present=$(git ls-files --cached --others --exclude-standard | cut -d/ -f1 | sort -u)
stray=""
for e in $present; do
    echo "$allowed" | grep -qxF "$e" || stray="$stray $e"
done
if [ -z "$stray" ]; then
    ok "repository root: $(echo $present | wc -w) entries, all in the README's layout table"
else
    bad "repository root: not in the README's layout table:$stray"
fi
summary hygiene
