#!/usr/bin/env bash
# Installs the npm packages of each JavaScript peer's adapter: every folder
# validation/plugins/<peer>/ with a package-lock.json (planck.js, Rapier, Jolt), into
# build/npm/<peer>/, outside the source tree, and the JavaScript formatter (scripts/format/, into
# build/npm/format/), each only when its lockfile differs from the copy
# installed last. Each peer's CMakeLists.txt builds its adapter when
# build/npm/<peer>/node_modules/<package> exists. Called by scripts/setup.sh; runs alone too.
#
# Node: the node and npm found on PATH (a NodeSource Node 20 here, whose package conflicts with
# Debian's npm: `apt-get install npm` fails there). Only when there is none, Debian's nodejs (18
# on Debian 12) and npm are installed (as root), or the exact command is printed.
# Exit codes: 0 installed (or already up to date), 3 node or npm missing and we cannot install
# them (not root, or no apt-get), 1 npm ci failed.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  cmd="apt-get update && apt-get install -y --no-install-recommends nodejs npm"
  if [[ $(id -u) -ne 0 ]] || ! command -v apt-get >/dev/null; then
    echo "setup_npm: node or npm not found on PATH (the JavaScript peers' adapters need them)" >&2
    echo "setup_npm: run as root:  $cmd" >&2
    exit 3
  fi
  echo "setup_npm: installing Debian's nodejs and npm" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi

# One peer's folder: npm ci into build/npm/<peer>/ unless its lockfile is the one installed there.
install_peer() {
  local src=$1 dest=$root/build/npm/$(basename "$1")
  if [[ -d $dest/node_modules ]] && cmp -s "$src/package-lock.json" "$dest/package-lock.json" \
     && cmp -s "$src/package.json" "$dest/package.json"; then
    return 0
  fi
  mkdir -p "$dest"
  cp "$src/package.json" "$src/package-lock.json" "$dest/"
  echo "setup_npm: npm ci in $dest (node $(node --version), npm $(npm --version))" >&2
  # planck 1.5.0 declares engines node >= 24; npm only warns (EBADENGINE), and the adapter's path
  # runs on Node 18 and 20 (docs/peers/planck.md). --ignore-scripts: no package code runs.
  if ! (cd "$dest" && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error); then
    rm -f "$dest/package-lock.json" # the next run tries again
    echo "setup_npm: npm ci failed in $dest" >&2
    return 1
  fi
}

status=0
# scripts/format/: the JavaScript formatter of scripts/check_format.sh (prettier), into build/npm/format/.
for lock in "$root"/validation/plugins/*/package-lock.json "$root"/scripts/format/package-lock.json; do
  install_peer "$(dirname "$lock")" || status=1
done
exit $status
