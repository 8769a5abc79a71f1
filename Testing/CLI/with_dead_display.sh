#!/bin/sh
# Runs a command with DISPLAY naming an X display that no server answers: the
# first number from 7000 with neither a socket in /tmp/.X11-unix nor a lock
# file (a server makes both). Tests what the program does with a DISPLAY that
# is set but useless (a closed ssh -X session, a stopped Xvfb).
n=7000
while [ -e "/tmp/.X11-unix/X$n" ] || [ -e "/tmp/.X$n-lock" ]; do
  n=$((n + 1))
done
DISPLAY=":$n"
export DISPLAY
exec "$@"
