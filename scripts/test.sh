#!/usr/bin/env bash
# Sets up (installs the Debian packages), builds the release preset and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release -j2
