#!/usr/bin/env bash
# The ParaView stage (issues 7 and 15): builds the ParaView plugin in ParaView/
# (the filter, and the Smooth Silhouette Surface representation on the
# render-time mapper) and runs its tests: pvbatch tests (for each, an image
# test and an MPI test on two ranks) and a test of the representation in the
# paraview GUI.
#
# Debian's ParaView 5.11 cannot share a system with libvtk9-dev (installing
# python3-paraview removes it), and the main suite needs libvtk9-dev. So this
# stage never touches the host's packages: it makes a separate Debian bookworm
# root with debootstrap, installs ParaView there, bind-mounts this source tree
# into it read-only, and builds and tests inside it with chroot.
#
# The root lives at $SILHOUETTE_PARAVIEW_ROOT (default
# /var/cache/silhouette-paraview/root, outside the source tree, about 3 GB) and
# is reused by later runs: a run on a ready root only rebuilds and tests. The
# build is in /build/paraview inside the root. Remove the root with
#   bash scripts/paraview.sh --remove-root
# (it refuses while anything is mounted under it). To work inside the root
# (the source tree is at /src, read-only; the build at /build/paraview):
#   bash scripts/paraview.sh --run bash
# runs a command there with the mounts in place, after making the root (give
# xvfb-run there a display number of your own, -n 300 say, rather than -a).
#   bash scripts/paraview.sh --prepare
# only makes the root and installs its packages: minutes of downloading and
# unpacking on a fresh machine, little of it CPU, so CI does it in the
# background while the main suite builds and runs (.ci/run); a run that
# follows waits for it on the root's lock. Its one host package, debootstrap,
# is installed by
#   bash scripts/paraview.sh --host-packages
# (which does nothing else), so that .ci/run can install it in the foreground:
# two apt-get runs on the host at once fail on apt's lock.
#
# The mirror is the host's: read at run time from its apt configuration.
# Needs root (or sudo) for debootstrap, mount and chroot.
set -euo pipefail
case "${1:-}" in
  --help | -h)
    sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
    exit 0
    ;;
  "" | --run | --prepare | --host-packages | --remove-root) ;;
  *)
    echo "paraview.sh: unknown option '$1' (--prepare, --host-packages, --run COMMAND..., --remove-root or --help)" >&2
    exit 2
    ;;
esac

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
root="${SILHOUETTE_PARAVIEW_ROOT:-/var/cache/silhouette-paraview/root}"
suite=bookworm
packages=(
  # ParaView 5.11 and its development files (its CMake package).
  paraview paraview-dev python3-paraview
  # What paraview-dev's CMake package looks for when a plugin asks for the
  # few components it needs (ParaView/CMakeLists.txt). Qt is not among them:
  # a plugin with no GUI part needs no Qt development packages.
  libopenmpi-dev libdouble-conversion-dev liblzma-dev liblz4-dev libutfcpp-dev zlib1g-dev libexpat1-dev
  # The representation (ParaView::RemotingViews, VTK::RenderingOpenGL2):
  # VTK's RenderingOpenGL2 package runs find_package(X11) and
  # find_package(OpenGL), its glew module find_package(GLEW) (the mapper
  # calls glBufferSubData through vtk_glew.h), and RemotingViews brings in
  # VTK::freetype, whose link interface names Freetype::Freetype; these give
  # their headers and link libraries.
  libx11-dev libgl-dev libglew-dev libfreetype-dev
  # Our module: a compiler and GLM for the core (the plugin's modules need no
  # OpenSubdiv: vtkOpenSubdivRefiner is in a module of its own).
  cmake make g++ libglm-dev
  # pvbatch renders through X: a virtual X server. Two ranks: Open MPI.
  xvfb xauth openmpi-bin
  # The GUI test (paraview.RepresentationGUI): ImageMagick's import captures
  # the screen; the GUI's text needs a font (paraview pulls this one in
  # today; named so that it stays) and its icons, Qt's SVG plugin.
  imagemagick fonts-dejavu-core libqt5svg5)

log() { echo "paraview: $*"; }
die() {
  echo "paraview: FAILED: $*" >&2
  exit 1
}

if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || die "needs root (or sudo) for debootstrap, mount and chroot"
  exec sudo --preserve-env=SILHOUETTE_PARAVIEW_ROOT bash "$0" "$@"
fi

# Mounts made by this run, in order; unmounted in reverse on any exit.
mounts=()
unmount_all() {
  local i
  for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do
    umount "${mounts[i]}" 2>/dev/null || umount -l "${mounts[i]}" 2>/dev/null ||
      echo "paraview: could not unmount ${mounts[i]}" >&2
  done
  mounts=()
}
trap unmount_all EXIT
trap 'exit 130' INT TERM

mounted_under_root() { findmnt -rn -o TARGET | grep -F -- "$root/" || true; }

# shellcheck source=packages.sh
source "$here/scripts/packages.sh"
# debootstrap is the one package the host gets; everything else goes in the root.
install_host_packages() { install_missing paraview debootstrap; }
if [ "${1:-}" = "--host-packages" ]; then
  install_host_packages
  exit 0
fi

# One run at a time on one root.
mkdir -p "$(dirname "$root")"
exec 9>"$root.lock"
flock 9

if [ "${1:-}" = "--remove-root" ]; then
  [ -z "$(mounted_under_root)" ] || die "something is mounted under $root: $(mounted_under_root)"
  rm -rf --one-file-system "$root"
  rm -f "$root.debootstrap.log" "$root.apt.log"
  log "removed $root"
  exit 0
fi

# Seconds per step, printed as they end and again at the close.
timings=()
step_start() { step_t0=$SECONDS; }
step_end() {
  local took=$((SECONDS - step_t0))
  timings+=("$1: ${took} s")
  log "$1 took ${took} s"
}

# The host's Debian mirror, from its apt configuration: the URI of the first
# deb822 stanza (or one-line entry) that serves the suite itself.
host_mirror() {
  local uri=""
  if compgen -G "/etc/apt/sources.list.d/*.sources" >/dev/null; then
    uri="$(awk -v suite="$suite" '
      function check() {
        if (!done && uris != "" && (" " suites " ") ~ (" " suite " ") && types ~ /(^| )deb( |$)/) { print uris; done = 1; exit }
      }
      /^[ \t]*$/ { check(); uris = suites = types = ""; next }
      tolower($1) == "uris:" { uris = $2 }
      tolower($1) == "suites:" { $1 = ""; suites = $0 }
      tolower($1) == "types:" { $1 = ""; types = $0 }
      END { check() }' /etc/apt/sources.list.d/*.sources)"
  fi
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    uri="$(awk -v suite="$suite" '$1 == "deb" { for (i = 2; i < NF; i++) if ($i ~ /:\/\// && $(i + 1) == suite) { print $i; exit } }' \
      /etc/apt/sources.list)"
  fi
  [ -n "$uri" ] || die "no Debian $suite mirror found in /etc/apt/sources.list.d/*.sources or /etc/apt/sources.list"
  echo "$uri"
}

in_root() {
  chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
    LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"
}

# 1. The root.
step_start
if [ ! -f "$root/.silhouette-root-complete" ]; then
  install_host_packages
  if [ -e "$root" ]; then
    [ -z "$(mounted_under_root)" ] || die "an unfinished root at $root has mounts in it: $(mounted_under_root)"
    log "removing an unfinished root at $root"
    rm -rf --one-file-system "$root"
  fi
  mirror="$(host_mirror)"
  [[ "$mirror" =~ ^[a-z+]+://[^[:space:]]+$ ]] || die "not one mirror URI: '$mirror'"
  log "creating a $suite root (minbase) at $root"
  # Up to three tries: a mirror can fail one request now and then.
  for attempt in 1 2 3; do
    if debootstrap --variant=minbase "$suite" "$root" "$mirror" >"$root.debootstrap.log" 2>&1; then
      break
    fi
    [ -z "$(mounted_under_root)" ] || die "debootstrap failed and left mounts under $root: $(mounted_under_root)"
    rm -rf --one-file-system "$root"
    if [ "$attempt" -eq 3 ]; then
      tail -30 "$root.debootstrap.log" >&2
      die "debootstrap failed three times (log: $root.debootstrap.log)"
    fi
    log "debootstrap failed (try $attempt of 3), trying again in 10 s"
    sleep 10
  done
  touch "$root/.silhouette-root-complete"
  step_end "root creation"
else
  log "reusing the root at $root"
  step_end "root check"
fi

# 2. Mounts: the kernel's file systems, a private /dev/shm (Open MPI's shared
# memory) and the source tree, read-only. Mounts left by a run that was
# killed (we hold the lock, so no run is using them) are undone first,
# deepest first.
stale="$(mounted_under_root)"
if [ -n "$stale" ]; then
  log "undoing mounts left by an earlier run: ${stale//$'\n'/ }"
  while read -r target; do
    umount "$target" 2>/dev/null || umount -l "$target"
  done < <(echo "$stale" | awk '{ print length($0) " " $0 }' | sort -rn | cut -d' ' -f2-)
  [ -z "$(mounted_under_root)" ] || die "could not undo the mounts under $root: $(mounted_under_root)"
fi
bind() { # bind SOURCE TARGET [ro]
  mkdir -p "$2"
  mount --bind "$1" "$2"
  mounts+=("$2")
  mount --make-private "$2"
  if [ "${3:-}" = ro ]; then
    mount -o remount,bind,ro "$2"
  fi
}
bind /proc "$root/proc"
bind /sys "$root/sys" ro
bind /dev "$root/dev"
bind /dev/pts "$root/dev/pts"
mkdir -p "$root/dev/shm"
mount -t tmpfs -o size=1g,mode=1777 tmpfs "$root/dev/shm"
mounts+=("$root/dev/shm")
bind "$here" "$root/src" ro
# Name resolution for apt, and localhost for Open MPI.
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
cp /etc/hosts "$root/etc/hosts" 2>/dev/null || true

# 3. Packages, when some are missing. The root's apt uses the host's sources
# and the host's date checks (a mirror snapshot has an old Release date).
need=()
for package in "${packages[@]}"; do
  # shellcheck disable=SC2016 # dpkg-query's own format, not the shell's
  if ! in_root dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    need+=("$package")
  fi
done
step_start
if [ "${#need[@]}" -gt 0 ]; then
  rm -f "$root/etc/apt/sources.list"
  rm -f "$root"/etc/apt/sources.list.d/*
  if compgen -G "/etc/apt/sources.list.d/*.sources" >/dev/null; then
    cp /etc/apt/sources.list.d/*.sources "$root/etc/apt/sources.list.d/"
  fi
  if [ -f /etc/apt/sources.list ]; then cp /etc/apt/sources.list "$root/etc/apt/sources.list"; fi
  apt-config dump | grep -E '^Acquire::(Check-Valid-Until|Check-Date) ' >"$root/etc/apt/apt.conf.d/99host-checks" || true
  log "installing ${#need[@]} packages in the root: ${need[*]}"
  in_root apt-get -o Acquire::Retries=3 update -qq >"$root.apt.log" 2>&1 || { tail -30 "$root.apt.log" >&2; die "apt-get update failed"; }
  # --force-unsafe-io: dpkg skips its sync of each unpacked file, which on a
  # busy machine slowed the install and the builds beside it. Only a crash of
  # the machine itself during the install could leave files half written
  # (then remove the root: --remove-root).
  in_root apt-get -o Acquire::Retries=3 -o Dpkg::Options::=--force-unsafe-io \
    install -y -q --no-install-recommends "${need[@]}" >>"$root.apt.log" 2>&1 ||
    { tail -30 "$root.apt.log" >&2; die "package installation failed (log: $root.apt.log)"; }
  in_root apt-get clean
  step_end "package install"
else
  step_end "package check"
fi

if [ "${1:-}" = "--prepare" ]; then
  log "the root is ready at $root"
  exit 0
fi
if [ "${1:-}" = "--run" ]; then
  shift
  set +e
  in_root "$@"
  exit $?
fi

# 4. The plugin.
step_start
log "building the plugin in $root/build/paraview"
mkdir -p "$root/build/paraview"
in_root cmake -S /src/ParaView -B /build/paraview -DCMAKE_BUILD_TYPE=Release >"$root/build/paraview/configure.log" 2>&1 ||
  { tail -40 "$root/build/paraview/configure.log" >&2; die "configuring the plugin failed"; }
in_root cmake --build /build/paraview -j "$(nproc 2>/dev/null || echo 2)" >"$root/build/paraview/build.log" 2>&1 ||
  { grep -B2 -A8 -m5 'error' "$root/build/paraview/build.log" >&2 || tail -40 "$root/build/paraview/build.log" >&2; die "building the plugin failed"; }
step_end "plugin build"

# 5. The tests, under a private X server (pvbatch renders through X; the GUI
# test's baseline is a capture of this 1280x1024 screen). Its
# display number is chosen here, not by xvfb-run -a inside the root: the root
# cannot see the host's X lock files, but shares its abstract X sockets, so
# it would pick :99 where the host's own xvfb-run may already serve.
free_display() {
  local n
  for n in $(seq 200 999); do
    if [ ! -e "/tmp/.X$n-lock" ] && [ ! -e "$root/tmp/.X$n-lock" ] &&
      ! grep -q "/tmp/.X11-unix/X$n\$" /proc/net/unix 2>/dev/null; then
      echo "$n"
      return
    fi
  done
  die "no free X display number between 200 and 999"
}
display="$(free_display)"
step_start
set +e
in_root xvfb-run -n "$display" -s "-screen 0 1280x1024x24 -noreset" ctest --test-dir /build/paraview --output-on-failure \
  --repeat until-pass:2 2>&1 | tee "$root/build/paraview/ctest.log"
status=${PIPESTATUS[0]}
set -e
step_end "tests"

total="$(sed -n 's/.* tests failed out of \([0-9][0-9]*\).*/\1/p' "$root/build/paraview/ctest.log" | tail -1)"
failed="$(sed -n 's/.*, \([0-9][0-9]*\) tests failed out of.*/\1/p' "$root/build/paraview/ctest.log" | tail -1)"
total="${total:-0}"
failed="${failed:-0}"
# The tests' own figures (ctest shows a passing test's output only in its log).
grep -hE '^(GUI |input triangles|output triangles|silhouette|image difference|ranks|PerturbVertices|camera move|SilhouetteTolerance|interactive render|cells selected|piece [0-9]|the reader|pose [0-9]|  [a-z])' \
  "$root/build/paraview/Testing/Temporary/LastTest.log" 2>/dev/null | sed 's/^/paraview:   /' || true
summary=""
for timing in "${timings[@]}"; do summary+="${summary:+, }$timing"; done
log "times: $summary"
log "test outputs in $root/build/paraview/Testing/Temporary"
if [ "$status" -ne 0 ] || [ "$total" -eq 0 ]; then
  [ "$failed" -gt 0 ] || failed=1
  echo "paraview: $((total - failed < 0 ? 0 : total - failed)) passed, $failed failed"
  die "the ParaView tests failed (ctest exit $status)"
fi
echo "paraview: $total passed, 0 failed"
