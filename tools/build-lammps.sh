#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Build LAMMPS (PERI, PLUGIN, MPI, OpenMP, shared lib) from Debian's source package into a
# cache outside the clone, keyed by version and options. Reused when present.
# Usage: tools/build-lammps.sh [VERSION_KEY]   (default: $BBPD_LAMMPS_VERSION or 20260704)
# Prints the install prefix on stdout.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/env.sh"

key=${1:-$BBPD_LAMMPS_VERSION}
opts=(-D PKG_PERI=on -D PKG_PLUGIN=on -D PKG_OPENMP=on -D BUILD_MPI=on -D BUILD_OMP=on
      -D BUILD_SHARED_LIBS=on -D CMAKE_BUILD_TYPE=Release -D PKG_PYTHON=off
      -D BUILD_TOOLS=off -D WITH_JPEG=on -D WITH_PNG=on -D WITH_GZIP=on -D WITH_FFMPEG=off
      -D LAMMPS_MACHINE= -D CMAKE_CXX_COMPILER=g++)
# dump image (the examples' pictures of the damage) left the core for the GRAPHICS package
# after 4 Feb 2025; older versions have it built in.
[ "$key" = 20250204 ] || opts+=(-D PKG_GRAPHICS=on)
tag=$(printf '%s\n' "$key" "${opts[@]}" | sha256sum | cut -c1-12)
prefix="$BBPD_CACHE/lammps/install-$key-$tag"
if [ -f "$prefix/.complete" ]; then echo "$prefix"; exit 0; fi

src=$("$here/lammps-source.sh" "$key" "$BBPD_CACHE/lammps")
build="$BBPD_CACHE/lammps/build-$key-$tag"
echo "build-lammps: configuring LAMMPS $key (about 4 minutes on 2 cores; cached afterwards in $prefix)" >&2
rm -rf "$build"
cmake -S "$src/cmake" -B "$build" "${opts[@]}" -D CMAKE_INSTALL_PREFIX="$prefix" >"$build.log" 2>&1 \
  || { tail -n 40 "$build.log" >&2; exit 1; }
echo "build-lammps: compiling (log: $build.log)" >&2
cmake --build "$build" -j "$(nproc)" >>"$build.log" 2>&1 || { tail -n 40 "$build.log" >&2; exit 1; }
cmake --install "$build" >>"$build.log" 2>&1 || { tail -n 40 "$build.log" >&2; exit 1; }
# Source tree kept beside the install: the plugin needs PERI's headers, which are not installed.
ln -sfn "$src" "$prefix/source"
touch "$prefix/.complete"
echo "$prefix"
