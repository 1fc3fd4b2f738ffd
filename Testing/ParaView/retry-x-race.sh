#!/bin/sh
# Runs a command; when it fails and its output says "bad X server
# connection" (a client that could not open the virtual display: the
# xvfb-run race of Documentation/testing.md, seen here with ParaView's
# pvbatch when other Xvfb servers start and stop beside it), runs it again,
# at most three times in all. Any other failure is returned at once, and
# nothing about the command's own checks changes.
#   retry-x-race.sh COMMAND [ARGUMENTS...]
set -u
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
attempt=1
while :; do
  "$@" >"$log" 2>&1
  status=$?
  cat "$log"
  if [ "$status" -eq 0 ] || [ "$attempt" -ge 3 ] ||
    ! grep -q "bad X server connection" "$log"; then
    exit "$status"
  fi
  echo "retry-x-race.sh: the X display refused the client (attempt $attempt); running again" >&2
  attempt=$((attempt + 1))
  sleep 2
done
