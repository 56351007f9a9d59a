#!/usr/bin/env bash
# Installs fabvdb's build dependencies from Debian 12's packages and builds
# fabvdb (Release, Ninja) in build/. Safe to run again: apt-get and the build
# are incremental. Run as root (or with sudo available).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config
  libopenvdb-dev libboost-iostreams-dev libboost-graph-dev libboost-dev libtbb-dev
  libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev
  lib3mf-dev libzip-dev libcairo2-dev libembree-dev nlohmann-json3-dev libgtest-dev
  slurmctld slurmd slurm-client munge procps
  python3 time
  libcivetweb-dev chromium
  groff-base man-db  # the man page: rendered by the reference test, read by `man` after install
  ccache  # compiler cache: a second clone on the same machine builds from it (docs/building.md)
  python3-dev pybind11-dev python3-numpy python3-pytest  # the Python package and its tests
)

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

echo "== installing dependencies (apt-get)"
export DEBIAN_FRONTEND=noninteractive
as_root apt-get update -qq
# The Blender add-on's headless test: Debian ships blender for amd64 and arm64
# only; elsewhere the test reports itself skipped.
if apt-cache show blender >/dev/null 2>&1; then packages+=(blender); fi
as_root apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
# The studio's page and its browser tests use npm packages (studio/package-lock.json).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  as_root apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi

echo "== installing the studio's npm packages (npm ci in studio/)"
(cd studio && npm ci --no-audit --no-fund --loglevel=error)

echo "== building fabvdb in build/"
# Every compiler call goes through ccache with this clone as its base_dir:
# paths inside the clone are hashed relative to the build folder, so another
# clone of the same sources, anywhere on the machine, hits the same cache.
launcher="env;CCACHE_BASEDIR=$PWD;ccache"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  "-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher" "-DCMAKE_C_COMPILER_LAUNCHER=$launcher" >/dev/null
cmake --build build -j 2
