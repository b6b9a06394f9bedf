#!/usr/bin/env bash
# check_clean_tree.sh [BEFORE] — whether what ran in this checkout (the test suite) left files
# behind: every entry of `git status --porcelain` (untracked or modified files; what .gitignore
# ignores, such as build/, does not count) that is not already listed in the file BEFORE, which
# holds that command's output from before the run. Prints one line naming the files and exits 1
# if there are any; silent and 0 otherwise. Run from the checkout's root.
set -euo pipefail

current=$(git status --porcelain --untracked-files=all)
before=""
if [ $# -ge 1 ] && [ -f "$1" ]; then before=$(cat "$1"); fi

# Entries new since BEFORE, their status columns cut off: "?? out.pfm" → out.pfm.
left=$(comm -13 <(printf '%s\n' "$before" | sort) <(printf '%s\n' "$current" | sort) |
    sed -e '/^$/d' -e 's/^...//' | paste -sd' ')

if [ -n "$left" ]; then
    echo "check_clean_tree: the run left untracked or modified files in the checkout: $left" >&2
    exit 1
fi
