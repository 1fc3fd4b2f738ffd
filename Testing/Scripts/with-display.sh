#!/usr/bin/env bash
# Runs a command under one virtual X display of its own, for the whole run:
#
#   bash Testing/Scripts/with-display.sh COMMAND [ARGUMENTS...]
#
# Debian's VTK renders through GLX only, so every rendering test and program
# needs an X display. This replaces `xvfb-run -a`, whose two races failed
# tests with "bad X server connection" (Documentation/testing.md):
#
# - Xvfb resets when its last client leaves, and a client that connects
#   during the reset is refused. With -noreset the server never resets, so
#   tests that start and end beside each other (ctest -j) never meet one.
# - `xvfb-run -a` picks a free display number by looking for lock files and
#   then starts the server: two started together can pick the same number.
#   Here Xvfb picks the number itself (-displayfd: it binds the first free
#   display and writes its number), which no other server can take.
#
# The exit status is the command's. The server is stopped when the command
# ends, however it ends. With TYNDALL_DISPLAY_SCREEN the screen is another
# size (default 1280x1024x24).
set -euo pipefail

if [ "$#" -eq 0 ]; then
  echo "usage: with-display.sh COMMAND [ARGUMENTS...]" >&2
  exit 2
fi
if ! command -v Xvfb >/dev/null 2>&1; then
  echo "with-display.sh: Xvfb is not installed (Debian: apt-get install xvfb)" >&2
  exit 2
fi

screen="${TYNDALL_DISPLAY_SCREEN:-1280x1024x24}"
dir="$(mktemp -d)"
server=""
cleanup() {
  if [ -n "$server" ] && kill -0 "$server" 2>/dev/null; then
    kill "$server" 2>/dev/null || true
    wait "$server" 2>/dev/null || true
  fi
  rm -rf "$dir"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# -displayfd 3: Xvfb writes the display number it bound to descriptor 3 once
# it accepts connections. -nolisten tcp: local clients only.
Xvfb -displayfd 3 -screen 0 "$screen" -noreset -nolisten tcp 3>"$dir/display" \
  >"$dir/xvfb.log" 2>&1 &
server=$!

# Wait for the number (at most 30 s), or for the server to fail.
for _ in $(seq 300); do
  if [ -s "$dir/display" ] && grep -q '^[0-9][0-9]*$' "$dir/display"; then
    break
  fi
  if ! kill -0 "$server" 2>/dev/null; then
    echo "with-display.sh: Xvfb failed to start:" >&2
    cat "$dir/xvfb.log" >&2
    exit 2
  fi
  sleep 0.1
done
if ! grep -q '^[0-9][0-9]*$' "$dir/display" 2>/dev/null; then
  echo "with-display.sh: Xvfb gave no display number within 30 s:" >&2
  cat "$dir/xvfb.log" >&2
  exit 2
fi

export DISPLAY=":$(cat "$dir/display")"
# Clients connect without a cookie: the server listens on its local socket
# only, and xauth's file would belong to xvfb-run.
unset XAUTHORITY
set +e
"$@"
status=$?
set -e
exit "$status"
