#!/usr/bin/env bash
# Runs what CI runs, on a fresh clone, and prints what each stage cost:
#
#   bash Testing/Scripts/ci-profile.sh [COMMIT]     (default: HEAD)
#
# CI clones main next to ../shared and runs `CI=true bash .ci/run`, which is
# `setup.sh test`. This does the same with COMMIT of this checkout, in a
# clone beside it (../tyndall-ci-profile, so that ../shared is found the same
# way), and keeps the whole log there (ci.log). setup.sh ends with the time of
# each stage (packages, the two builds, the two suites) and the 20 slowest
# tests of each suite; this prints them again at the end with the total.
# Documentation/testing.md ("What CI costs") holds the figures.
#
# Packages already installed cost nothing here; a fresh machine adds their
# download and installation (the "packages" stage of a first run).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
commit="${1:-HEAD}"
dest="$(dirname "$root")/tyndall-ci-profile"

rm -rf "$dest"
git clone --quiet --no-local "$root" "$dest"
git -C "$dest" checkout --quiet --detach "$(git -C "$root" rev-parse "$commit")"
echo "ci-profile: a fresh clone of $(git -C "$dest" log --oneline -1) in $dest" >&2

start=$SECONDS
set +e
(cd "$dest" && CI=true bash .ci/run) >"$dest/ci.log" 2>&1
status=$?
set -e
elapsed=$((SECONDS - start))

# The stage table and the slowest tests that setup.sh printed last.
sed -n '/^setup: time per stage/,$p' "$dest/ci.log"
echo "ci-profile: CI=true bash .ci/run exited $status after $elapsed s ($((elapsed / 60)) min $((elapsed % 60)) s); log: $dest/ci.log"
exit "$status"
