#!/bin/sh
# Runs a command with the files it writes limited to 1 KiB (ulimit -f 1), the
# way a full disk or a quota stops a write part-way. The display comes first
# (run_with_display.sh, for the commands that render), unlimited; SIGXFSZ is
# ignored, so a write past the limit fails with EFBIG instead of killing the
# command.
if [ "$1" != "--limited" ]; then
  exec "$(cd "$(dirname "$0")" && pwd)/../run_with_display.sh" "$0" --limited "$@"
fi
shift
trap '' XFSZ
ulimit -f 1
exec "$@"
