#!/bin/sh
# Runs a command that renders with VTK's X11 windows: directly when a display
# is available, under a private Xvfb server (xvfb-run -a) when not.
if [ -n "$DISPLAY" ] && command -v xdpyinfo >/dev/null 2>&1 && xdpyinfo >/dev/null 2>&1; then
  exec "$@"
fi
if [ -n "$DISPLAY" ] && ! command -v xdpyinfo >/dev/null 2>&1; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
