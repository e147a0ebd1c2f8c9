#!/usr/bin/env bash
# Runs a command on an X server of its own, of the given size, with a window manager (openbox) on
# it, as an artist's desktop has: usage with-window-manager.sh WIDTHxHEIGHT COMMAND [ARG...].
# The window manager takes its struts and decorations from the screen, so the editor's first
# window is placed and sized as on a real desktop.
set -euo pipefail
size=$1
shift
for tool in xvfb-run openbox xprop; do
  command -v "$tool" >/dev/null || { echo "with-window-manager: $tool is missing (scripts/setup.sh installs it)" >&2; exit 1; }
done
exec xvfb-run -a -s "-screen 0 ${size}x24" bash -c '
  openbox --sm-disable >/dev/null 2>&1 &
  wm=$!
  # Wait until the window manager has taken the screen (it names itself on the root window).
  for _ in $(seq 100); do
    xprop -root _NET_SUPPORTING_WM_CHECK 2>/dev/null | grep -q "window id" && break
    sleep 0.05
  done
  status=0
  "$@" || status=$?
  kill "$wm" 2>/dev/null || true
  exit "$status"
' with-window-manager "$@"
