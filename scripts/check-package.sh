#!/usr/bin/env bash
# Builds the Debian package from the release build, installs it with apt (as a user would), and
# checks that the installed files work on their own: both programs answer --version, the udev
# rules, systemd user unit, man pages, Python stubs, CMake package and Inkscape extension are where
# Debian looks, and the installed penshaped replays an installed recording to the installed
# penshape. Removes the package when done.
#   scripts/check-package.sh            (root, or passwordless sudo; after a release build)
set -euo pipefail
cd "$(dirname "$0")/.."
SUDO=()
[ "$(id -u)" -eq 0 ] || SUDO=(sudo -n)

rm -f build/release/penshape_*.deb
(cd build/release && cpack -G DEB >/dev/null)
deb=$(ls build/release/penshape_*.deb)
echo "package: $deb ($(du -h "$deb" | cut -f1))"
dpkg-deb -f "$deb" Depends | tr ',' '\n' | sed 's/^ */  depends: /'
DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq --reinstall "./$deb" >/dev/null

fail() { echo "check-package: $*" >&2; exit 1; }
/usr/bin/penshaped --version | grep -q '^penshaped ' || fail "penshaped --version"
/usr/bin/penshape --version | grep -q 'penshape' || fail "penshape --version"
for f in /usr/lib/udev/rules.d/70-penshape-tablets.rules /usr/lib/systemd/user/penshaped.service \
         /usr/share/man/man1/penshape.1.gz /usr/share/man/man1/penshaped.1.gz \
         /usr/share/penshape/python/penshape_watch.py /usr/lib/cmake/penshape/penshapeConfig.cmake \
         /usr/include/penshape/core/deconstruct.hpp /usr/share/inkscape/extensions/penshape_snap.inx \
         /usr/share/inkscape/extensions/penshape_snap.py; do
  [ -e "$f" ] || [ -e "${f/\/usr\/lib\/cmake//usr/lib/$(gcc -print-multiarch)/cmake}" ] ||
    fail "missing $f"
done
grep -q '^ExecStart=/usr/bin/penshaped$' /usr/lib/systemd/user/penshaped.service ||
  fail "the unit does not start /usr/bin/penshaped"
/usr/bin/python3 -c 'import penshape.v1.live_pb2_grpc' || fail "the Python stubs do not import"

# The installed daemon replays an installed recording; the installed client sees its shapes. The
# package is removed again at the end: a system-wide copy of the Inkscape extension beside the
# one the app tests install in their own HOME would make Inkscape see the extension twice.
dir=$(mktemp -d)
trap 'kill %1 2>/dev/null; wait 2>/dev/null; rm -rf "$dir";
      DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get remove -y -qq penshape >/dev/null' EXIT
recording=/usr/share/penshape/recordings/generated-shapes.hidrec
# Watch from before the replay starts until it has played (its last report's time) and its last
# stroke has been recognized.
last=$(grep '^E:' "$recording" | tail -n 1 | awk '{print int($2)}')
/usr/bin/penshaped --listen "unix:$dir/s.sock" --replay "$recording" --replay-delay 2 \
  >"$dir/daemon.log" 2>&1 &
for _ in $(seq 50); do [ -S "$dir/s.sock" ] && break; sleep 0.1; done
/usr/bin/penshape watch --json --socket "$dir/s.sock" --duration $((last + 8)) >"$dir/watch.jsonl"
shapes=$(grep -c '"type":"shape"' "$dir/watch.jsonl" || true)
[ "$shapes" -ge 8 ] || fail "the installed daemon's replay gave $shapes shapes (want 8)"
/usr/bin/penshape replay --socket "$dir/s.sock" "$recording" >"$dir/replay.txt" 2>"$dir/replay.err"
grep -q 'through penshaped' "$dir/replay.err" || fail "penshape replay did not reach penshaped"
[ "$(grep -c '  shape: ' "$dir/replay.txt")" -eq 8 ] || fail "penshape replay: 8 shapes expected"
echo "check-package: installed package works ($shapes shapes from the installed replay)"
