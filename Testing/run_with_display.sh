#!/bin/sh
# Runs a command that renders with VTK's X11 windows (Debian's VTK has no
# OSMesa or EGL): directly when a display is set, under a private Xvfb server
# (xvfb-run -a) when not.
if [ -n "$DISPLAY" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
