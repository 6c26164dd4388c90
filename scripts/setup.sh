#!/usr/bin/env bash
# Installs the Debian packages this project needs, only when some are missing.
#   scripts/setup.sh          packages to build and run the validation campaign
#   scripts/setup.sh --tests  also what the test suite alone needs: Chromium and Python for the browser
#                             tests, clang (clang++) for the flag builds (CTest label flags),
#                             clang-format (14, Debian 12's) and black for the format checks,
#                             pybind11, NumPy and pytest for the Python package gjk2d
#                             (docs/python.md), venv, pip, build, wheel and mypy for its wheel
#   scripts/setup.sh --fuzz   also what the fuzz targets need (clang 14 and its libFuzzer/sanitizer runtimes)
# Exit codes: 0 everything present (or installed), 3 packages missing and we cannot install them
# (not root, or no apt-get): the exact command to run is printed.
set -euo pipefail

# catch2 is in the base list: configuring the project (even to build only the runner) finds it.
# libbox2d-dev (Box2D 2.4.1): the runner's engine families step Box2D worlds.
# libmsgpack-cxx-dev (header only): binary case files, gjk-cases-msgpack/1 (docs/case-files.md).
# libsimdjson-dev: the case-file reader parses cases with simdjson (docs/speed.md, "Case files").
# openmpi-bin, libopenmpi-dev: `mpirun -n N gjk-validate run` (optional in the build, GJK2D_WITH_MPI).
# dpkg-dev (dpkg-shlibdeps: the .deb's Depends) and pkgconf (the SDK's gjk2d.pc): `cpack` and the
# install tests (docs/validate-your-gjk.md).
# The peers (docs/peers.md): each folder of validation/plugins/ names its Debian packages in its
# peer.txt (`package` lines: FCL, Bullet, GEOS through shapely); planck.js and Jolt
# (jolt-physics) come from the npm registry (scripts/setup_npm.sh, below).
packages=(build-essential cmake libcgal-dev libgmp-dev libmpfr-dev libboost-dev
          nlohmann-json3-dev libsimdjson-dev libcli11-dev libfmt-dev libbenchmark-dev catch2 libbox2d-dev
          openmpi-bin libopenmpi-dev dpkg-dev pkgconf libmsgpack-cxx-dev)
for peer in "$(dirname "$0")"/../validation/plugins/*/peer.txt; do
  while read -r word rest; do
    if [[ "$word" == package ]]; then
      read -r -a named <<<"$rest"
      packages+=("${named[@]}")
    fi
  done <"$peer"
done
if [[ "${1:-}" == "--tests" ]]; then
  packages+=(chromium python3 clang clang-format)
  # The Python formatter (scripts/check_format.sh python): black 23.1.
  packages+=(black)
  # The Python package (python/, docs/python.md): built against Debian's /usr/bin/python3.
  packages+=(python3-dev pybind11-dev python3-numpy python3-pytest python3-msgpack)
  # Its wheel (pyproject.toml): venv and pip to install it, python3-build and python3-wheel to
  # make it, mypy's stubgen for its type stubs.
  packages+=(python3-venv python3-pip python3-build python3-wheel mypy)
  # The cross-platform check (CTest label cross, docs/gjk.md): cross g++ and qemu-user.
  packages+=(g++-aarch64-linux-gnu g++-riscv64-linux-gnu g++-s390x-linux-gnu qemu-user)
fi
if [[ "${1:-}" == "--fuzz" ]]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  # dpkg-query is fast (no network): the common case, everything present, costs well under a second.
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [[ ${#missing[@]} -gt 0 ]]; then
  cmd="apt-get update && apt-get install -y --no-install-recommends ${missing[*]}"
  if [[ $(id -u) -ne 0 ]] || ! command -v apt-get >/dev/null; then
    echo "setup: missing Debian packages: ${missing[*]}" >&2
    echo "setup: run as root:  $cmd" >&2
    exit 3
  fi
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# planck.js and Jolt (peers, docs/peers.md) from the npm registry, each pinned by its lockfile, into
# build/npm/.
exec "$(dirname "$0")/setup_npm.sh"
