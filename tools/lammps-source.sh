#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Fetch a pinned LAMMPS source tarball from Debian's source package, through a private
# apt configuration derived from this machine's own Debian sources (system apt is untouched).
# Usage: tools/lammps-source.sh VERSION_KEY DEST_DIR   (VERSION_KEY: 20260704 | 20250204)
# Prints the directory holding the unpacked source tree.
set -euo pipefail

key=${1:?version key (20260704 or 20250204)}
dest=${2:?destination directory}

case "$key" in
  20260704) upstream="20260704+dfsg"; suite=sid
            sha=cddbc45a047416bd48a4a0b87f24a5b61b3446982b74d18cafe619c22b17eb62 ;;
  20250204) upstream="20250204+dfsg.1"; suite=trixie
            sha=3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7 ;;
  *) echo "lammps-source: unknown LAMMPS version key '$key' (use 20260704 or 20250204)" >&2; exit 2 ;;
esac

mkdir -p "$dest"
src="$dest/src-$key"
if [ -f "$src/.unpacked" ]; then echo "$src"; exit 0; fi

# First Debian archive URI and keyring from the machine's configured sources (deb822 or one-line).
uri="" keyring=""
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  u=$(awk '/^URIs:/{print $2; exit}' "$f")
  k=$(awk '/^Signed-By:/{print $2; exit}' "$f")
  case "$u" in */debian) uri=$u; keyring=$k; break ;; esac
done
if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
  uri=$(awk '$1=="deb" && $0 !~ /security/ {for(i=2;i<=NF;i++) if ($i ~ /^(https?|file|ftp):/) {print $i; exit}}' /etc/apt/sources.list)
fi
[ -n "$uri" ] || { echo "lammps-source: no Debian archive found in /etc/apt/sources*; cannot derive a deb-src entry" >&2; exit 1; }
[ -n "$keyring" ] || keyring=/usr/share/keyrings/debian-archive-keyring.gpg

aptdir="$dest/apt-$suite"
mkdir -p "$aptdir/lists/partial" "$aptdir/archives/partial"
echo "deb-src [signed-by=$keyring] $uri $suite main" > "$aptdir/sources.list"
opts=(-o Dir::Etc::SourceList="$aptdir/sources.list" -o Dir::Etc::SourceParts=/dev/null
      -o Dir::State::Lists="$aptdir/lists" -o Dir::Cache::Archives="$aptdir/archives"
      -o Debug::NoLocking=1 -o APT::Sandbox::User=root)
echo "lammps-source: updating private source index ($suite)" >&2
apt-get "${opts[@]}" -qq update >&2

# Any Debian revision carrying the pinned upstream tarball is accepted (sid moves).
versions=$(apt-cache "${opts[@]}" showsrc lammps 2>/dev/null | awk '/^Version:/{print $2}' | grep -F "$upstream-" || true)
[ -n "$versions" ] || { echo "lammps-source: no lammps $upstream-* source package in $suite" >&2; exit 1; }
ver=$(echo "$versions" | sort -V | tail -n1)
dl="$dest/download-$key"
mkdir -p "$dl"
tarball=$(ls "$dl"/lammps_"$upstream".orig.tar.* 2>/dev/null | head -n1 || true)
if [ -z "$tarball" ]; then
  echo "lammps-source: downloading lammps=$ver tarball (about 200 MB)" >&2
  (cd "$dl" && apt-get "${opts[@]}" -qq source --download-only --tar-only "lammps=$ver" >&2)
  tarball=$(ls "$dl"/lammps_"$upstream".orig.tar.* | head -n1)
fi
got=$(sha256sum "$tarball" | cut -d' ' -f1)
if [ "$got" != "$sha" ]; then
  echo "lammps-source: SHA-256 mismatch for $(basename "$tarball"): got $got, want $sha" >&2
  rm -f "$tarball"; exit 1
fi
rm -rf "$src.tmp"; mkdir -p "$src.tmp"
tar -xf "$tarball" -C "$src.tmp"
# The tarball has no top-level folder; tolerate one if a revision adds it.
if [ ! -d "$src.tmp/cmake" ] && [ "$(ls "$src.tmp" | wc -l)" = 1 ]; then
  inner="$src.tmp/$(ls "$src.tmp")"; mv "$inner" "$src"; rmdir "$src.tmp"
else
  mv "$src.tmp" "$src"
fi
touch "$src/.unpacked"
echo "$src"
