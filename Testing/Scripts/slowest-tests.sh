#!/usr/bin/env bash
# Prints the slowest tests of a build directory's last ctest run, with their
# share of the suite's test time:
#
#   bash Testing/Scripts/slowest-tests.sh BUILD_DIR [COUNT]   (COUNT: default 20)
#
# It reads CTest's own record of the last run
# (BUILD_DIR/Testing/Temporary/LastTest.log: each test's "Test time"), so it
# works after any ctest run, whole suite or a selection.
set -euo pipefail

dir="${1:?usage: slowest-tests.sh BUILD_DIR [COUNT]}"
count="${2:-20}"
log="$dir/Testing/Temporary/LastTest.log"
if [ ! -f "$log" ]; then
  echo "slowest-tests.sh: no ctest run recorded in $dir ($log is missing)" >&2
  exit 1
fi

# LastTest.log holds, per test, a line "N/M Testing: NAME" and later
# "Test time =  12.34 sec". (POSIX awk and sort: Debian's default awk is mawk.)
awk '
  /^[0-9]+\/[0-9]+ Testing: / { name = $3; next }
  /^Test time = / && name != "" { print $4, name; name = "" }' "$log" |
  sort -k1,1 -g -r |
  awk -v count="$count" '
    { t[NR] = $1; name[NR] = $2; total += $1 }
    END {
      if (NR == 0) { print "no test times recorded"; exit }
      printf "%d tests, %.0f s of test time in all (summed over tests, not wall time)\n", NR, total
      printf "%9s %6s  %s\n", "seconds", "share", "test"
      for (k = 1; k <= NR && k <= count; ++k) {
        printf "%9.1f %5.1f%%  %s\n", t[k], 100 * t[k] / total, name[k]
      }
    }'
