# SPDX-License-Identifier: GPL-2.0-or-later
# Shared settings for the project's scripts (sourced, not run).
BBPD_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
: "${BBPD_CACHE:=${XDG_CACHE_HOME:-$HOME/.cache}/bbpd}"
: "${BBPD_LAMMPS_VERSION:=20260704}"
BBPD_PYTHON=/usr/bin/python3
export BBPD_ROOT BBPD_CACHE BBPD_LAMMPS_VERSION BBPD_PYTHON
