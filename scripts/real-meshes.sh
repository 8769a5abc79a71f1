#!/usr/bin/env bash
# Fetches the real meshes of the fidelity evaluation (docs/fidelity.md) and
# writes them as PLY into DIR (default: build/real-meshes):
#   cow elephant elk hand homer knot1   closed triangle meshes of 2,390 to
#                                       9,856 triangles, from CGAL 5.5's
#                                       data/meshes, as Debian's libcgal-demo
#                                       package ships them
# The package is downloaded (apt-get download: no install, no dependencies)
# into DIR/.cache and only the named OFF files are taken out of it and turned
# into ASCII PLY, same points in the same order, same triangles. Runs again in
# no time once DIR holds them. DIR/PROVENANCE.md records where each came from
# and its sha256.
#
#   bash scripts/real-meshes.sh [DIR]
set -euo pipefail
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
  exit 0
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${1:-$here/build/real-meshes}"
meshes=(cow elephant elk hand homer knot1)
mkdir -p "$dir"

missing=0
for mesh in "${meshes[@]}"; do
  [ -s "$dir/$mesh.ply" ] || missing=1
done
if [ "$missing" -eq 0 ] && [ -s "$dir/PROVENANCE.md" ]; then
  exit 0
fi

cache="$dir/.cache"
mkdir -p "$cache"
deb="$(ls "$cache"/libcgal-demo_*.deb 2>/dev/null | head -n 1 || true)"
if [ -z "$deb" ]; then
  echo "real-meshes: downloading Debian's libcgal-demo (about 24 MB)"
  if ! (cd "$cache" && apt-get download libcgal-demo >/dev/null 2>&1); then
    # The package lists may never have been fetched on a fresh machine.
    sudo_cmd=()
    if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then
      sudo_cmd=(sudo)
    fi
    "${sudo_cmd[@]}" apt-get update -qq
    (cd "$cache" && apt-get download libcgal-demo >/dev/null) ||
      { echo "real-meshes: cannot download libcgal-demo" >&2; exit 1; }
  fi
  deb="$(ls "$cache"/libcgal-demo_*.deb | head -n 1)"
fi
version="$(dpkg-deb -f "$deb" Version)"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$work" ./usr/share/doc/libcgal-dev/data.tar.gz
members=()
for mesh in "${meshes[@]}"; do
  members+=("data/meshes/$mesh.off")
done
tar -xzf "$work/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" "${members[@]}"

# OFF (header "OFF", counts, one vertex per line, one face per line with its
# corner count first) to ASCII PLY. Comments and blank lines are skipped.
off_to_ply() {
  awk '
    /^[ \t]*#/ || NF == 0 { next }
    state == 0 {
      if ($1 != "OFF") { print "not an OFF file" > "/dev/stderr"; exit 1 }
      state = 1
      if (NF >= 3) { vertices = $2; faces = $3; state = 2; header() }
      next
    }
    state == 1 { vertices = $1; faces = $2; state = 2; header(); next }
    state == 2 && v < vertices { print $1, $2, $3; v++; next }
    state == 2 && f < faces {
      line = $1
      for (i = 2; i <= $1 + 1; i++) line = line " " $i
      print line
      f++
    }
    function header() {
      printf "ply\nformat ascii 1.0\ncomment from CGAL data/meshes (libcgal-demo)\n"
      printf "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n", vertices
      printf "element face %d\nproperty list uchar int vertex_indices\nend_header\n", faces
    }
    END { if (v != vertices || f != faces) { print "truncated OFF file" > "/dev/stderr"; exit 1 } }
  ' "$1" > "$2"
}

{
  echo "# Real meshes of the fidelity evaluation"
  echo
  echo "Written by scripts/real-meshes.sh from Debian's libcgal-demo $version"
  echo "(usr/share/doc/libcgal-dev/data.tar.gz, CGAL 5.5's data/meshes; the"
  echo "CGAL project distributes its data with the library, under the"
  echo "licences Debian's libcgal-dev copyright file gives), converted from OFF"
  echo "to ASCII PLY with the same points and triangles."
  echo
  echo "| file | triangles | OFF sha256 |"
  echo "|---|---:|---|"
} > "$dir/PROVENANCE.md.partial"
for mesh in "${meshes[@]}"; do
  off="$work/data/meshes/$mesh.off"
  off_to_ply "$off" "$dir/$mesh.ply.partial"
  mv "$dir/$mesh.ply.partial" "$dir/$mesh.ply"
  triangles="$(awk '/^element face/ { print $3 }' "$dir/$mesh.ply")"
  echo "| $mesh.ply | $triangles | $(sha256sum "$off" | cut -d' ' -f1) |" >> "$dir/PROVENANCE.md.partial"
done
mv "$dir/PROVENANCE.md.partial" "$dir/PROVENANCE.md"
echo "real-meshes: ${meshes[*]} in $dir"
