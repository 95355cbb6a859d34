#!/usr/bin/env bash
# Installs exactly the Debian packages penshape needs to build, test and run. Idempotent:
# packages already present are not reinstalled, and apt is not touched when nothing is missing.
set -euo pipefail

PACKAGES=(
  cmake ninja-build g++ clang-14 libclang-rt-14-dev clang-tidy-14 pkg-config ccache clang-format
  pmccabe
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libhidapi-dev libusb-1.0-0-dev libudev-dev
  libprotobuf-dev protobuf-compiler libgrpc++-dev protobuf-compiler-grpc
  libgtest-dev libgmock-dev
  libsdl2-dev xvfb python3-grpcio python3-protobuf
  libpolyclipping-dev nlohmann-json3-dev libcli11-dev libtomlplusplus-dev
  dpkg-dev file
  libpugixml-dev zlib1g-dev libzip-dev libpng-dev
  inkscape xournalpp python3-lxml python3-cssselect python3-numpy poppler-utils
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages are installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  SUDO=(sudo -n)
else
  echo "setup: these packages are missing and this user can neither install them (not root)" >&2
  echo "       nor use sudo without a password. Ask an administrator to run:" >&2
  echo "       apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
