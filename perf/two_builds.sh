#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Loop times of the same inputs with the plugins of two checkouts, alternating (A B A B ...):
# does a change make a style slower? Each checkout needs its plugin built (tools/bootstrap).
#   perf/two_builds.sh BASE_CHECKOUT NEW_CHECKOUT ROUNDS INPUT... > perf/results/NAME.csv
# e.g. perf/two_builds.sh ../base . 3 perf/two_builds/in.plate-gaussian examples/peri-pmb-dropin/in.bbpd.pmb
# Prints CSV rows: round, input, build (base or new), loop time (s), 1-min load, CPU model name.
set -euo pipefail
case "${1:-}" in
  -h|--help|"") sed -n '3,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac
base=$(cd "$1" && pwd); new=$(cd "$2" && pwd); rounds=$3; shift 3
cpu=$(grep -m1 "model name" /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//; s/,/ /g')
echo "round,input,build,loop_s,load,cpu"
for r in $(seq "$rounds"); do
  for input in "$@"; do
    for build in base new; do
      root=$base; [ "$build" = new ] && root=$new
      loop=$("$root/tools/lmp" -in "$input" -log none 2>&1 | awk '/^Loop time/ {print $4}')
      echo "$r,$(basename "$input"),$build,$loop,$(cut -d' ' -f1 /proc/loadavg),$cpu"
    done
  done
done
