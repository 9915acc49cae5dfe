#!/usr/bin/env bash
# Runs one command (one GUI test) on a virtual X server of its own.
#
# ctest runs tests as processes side by side. On one shared X server without a window manager, a test that
# activates its window takes the keyboard focus from the window of the test running beside it, so focus and
# activation checks failed now and then. Xvfb picks a free display itself (-displayfd), so two of these
# never race for one.
set -euo pipefail
scratch=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp 3>"$scratch/display" 2>"$scratch/log" &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null || true; wait "$xvfb" 2>/dev/null || true; rm -rf "$scratch"' EXIT
for _ in $(seq 1 400); do  # at most 10 s
  [ -s "$scratch/display" ] && break
  if ! kill -0 "$xvfb" 2>/dev/null; then
    echo "own_x_server.sh: Xvfb did not start:" >&2
    cat "$scratch/log" >&2
    exit 1
  fi
  sleep 0.025
done
if [ ! -s "$scratch/display" ]; then
  echo "own_x_server.sh: Xvfb gave no display within 10 s" >&2
  exit 1
fi
DISPLAY=":$(tr -d '\n' <"$scratch/display")" "$@"
