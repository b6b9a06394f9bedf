#!/usr/bin/env bash
# check_clean_tree_test.sh CHECK — ci/check_clean_tree.sh (the script CHECK) on a scratch git
# repository: it passes on a clean tree, an ignored file and what was already there before the
# run; it fails, with one line naming the files, on a stray file, a stray file in a new folder
# and a modified tracked file.
set -euo pipefail
check=$(realpath "$1")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"

fail() { echo "check_clean_tree_test: $*" >&2; exit 1; }

# expect_pass / expect_failure NAMES...: run the check (with the snapshot `before` when it
# exists); on failure its message must be one line naming every one of NAMES.
expect_pass() { bash "$check" before.txt 2>message.txt || fail "failed on a clean tree: $(cat message.txt)"; }
expect_failure() {
    if bash "$check" before.txt 2>message.txt; then fail "passed with $* in the tree"; fi
    [ "$(wc -l <message.txt)" -eq 1 ] || fail "more than one line: $(cat message.txt)"
    for name in "$@"; do
        grep -qF "$name" message.txt || fail "the message does not name $name: $(cat message.txt)"
    done
}

git init -q .
printf 'build/\nbefore.txt\nmessage.txt\n' >.gitignore
echo tracked >tracked.txt
git add .gitignore tracked.txt
git -c user.name=test -c user.email=test@example.invalid commit -qm scratch

expect_pass
mkdir build && echo output >build/image.pfm
expect_pass # ignored
echo stray >stray.pfm
expect_failure stray.pfm
mkdir -p out/deep && echo stray >out/deep/image.exr
expect_failure stray.pfm out/deep/image.exr
rm -r stray.pfm out
echo changed >>tracked.txt
expect_failure tracked.txt
# What was there before the run is not the run's doing.
git status --porcelain --untracked-files=all >before.txt
expect_pass
echo stray >late.pfm
expect_failure late.pfm
echo "check_clean_tree_test: passed"
