#!/usr/bin/env bash
# Sourced by the figure scripts, with `here` set to the source folder. Sets
# `silhouette`, the program: $SILHOUETTE when given, else build/'s (built by
# setup.sh); `display`, the xvfb-run prefix when there is no display (empty
# otherwise); `work`, a scratch folder removed when the script exits.
# shellcheck disable=SC2034 # the sourcing script uses them
if [ -n "${SILHOUETTE:-}" ]; then
  silhouette="$SILHOUETTE"
else
  # shellcheck source=setup.sh
  source "$here/scripts/setup.sh"
  silhouette="$build/bin/silhouette"
fi
display=()
if [ -z "${DISPLAY:-}" ]; then
  display=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
