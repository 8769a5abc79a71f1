#!/bin/sh
# Runs a command with no X display: DISPLAY unset, so the silhouette program
# renders through its OSMesa back-end (and VTK never opens an X connection).
# The suite runs under one xvfb-run; the OSMesa tests use this to leave it.
unset DISPLAY
exec "$@"
