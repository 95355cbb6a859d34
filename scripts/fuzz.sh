#!/usr/bin/env bash
# Short libFuzzer runs of every fuzz target: the drivers' (descriptor parser, report decoder and
# pipeline, recording/table parsers), the daemon's --replay file, and the CLI's file readers
# (polygon x-y/WKT, JSON-lines and $1 XML strokes) with the daemon's config. Seeded from the
# project's generators (penshape-testgen: pen descriptors, polygons, $1-format strokes; the
# generated recordings/) and, when present, ../shared/data/hid. CI calls
# this after the asan preset's build; a finding fails the run and leaves its crash file in
# build/asan/fuzz/.
#   scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
shared="${PENSHAPE_SHARED_DATA_DIR:-$(pwd)/../shared/data}"
build=build/asan
cmake --preset asan >/dev/null
cmake --build --preset asan -j2 --target descriptor_fuzzer report_fuzzer recording_fuzzer \
  replay_file_fuzzer file_readers_fuzzer penshape-testgen

work="$build/fuzz"
rm -rf "$work"
mkdir -p "$work/seeds-descriptor" "$work/seeds-text" "$work/seeds-readers" "$work/corpus"
# Numbered copies: the same file name recurs across devices.
copy_all() { # DEST PREFIX_BYTE_OR_EMPTY FILE...
  local dest="$1" prefix="$2" i=0
  shift 2
  for f in "$@"; do
    if [ -n "$prefix" ]; then
      { printf "$prefix"; cat "$f"; } >"$dest/$i"
    else
      cp "$f" "$dest/$i"
    fi
    i=$((i + 1))
  done
}
testgen="$build/tests/support/penshape-testgen"
mkdir -p "$work/generated/hid"
for name in small-8192-id7 medium-tilt-id2 large-24bit-inch basic-no-id-1024 tiny-inch-255 \
  vendor-graphire; do
  "$testgen" descriptor "$name" "$work/generated/hid/$name.hid.bin"
done
"$testgen" polygons "$work/generated/polygons" --seed 7
"$testgen" corpus "$work/generated/strokes" --seed 7 --subjects 1 --per-kind 1
mapfile -t descriptors < <(find "$work/generated/hid" "$shared/hid/wacom-hid-descriptors" \
  -name '*.hid.bin' 2>/dev/null | sort)
copy_all "$work/seeds-descriptor" "" "${descriptors[@]}"
mapfile -t texts < <({ ls recordings/*.hidrec; find "$shared/hid" \( -name 'hidrecord.txt' -o \
  -name '*.hidrec.txt' -o -path '*dumps*' -name 'pen_*.txt' -size -64k \) 2>/dev/null; } | sort)
copy_all "$work/seeds-text" "" "${texts[@]}" drivers/data/tablets.tsv
# A pause of thirty thousand years between two reports: replay must cross it in a few timeouts.
awk '/^E: / && ++e > 40 { exit } { print }' recordings/generated-shapes.hidrec >"$work/seeds-text/pause"
grep -m 1 '^E: ' recordings/generated-shapes.hidrec |
  sed 's/^E: [0-9.]*/E: 999999999999.000000/' >>"$work/seeds-text/pause"
# File readers: the first byte picks the reader (0 polygon, 1 JSON lines, 2 $1 XML, 3 config,
# 4 verify's JSON answers).
mapfile -t polygons < <(find "$work/generated/polygons" tests/data/adversarial -name '*.txt' \
  -size -8k | sort)
copy_all "$work/seeds-readers" '\x00' "${polygons[@]}"
mapfile -t gestures < <(find "$work/generated/strokes" -name '*.xml' | sort | head -n 20)
mkdir -p "$work/seeds-readers/xml" && copy_all "$work/seeds-readers/xml" '\x02' "${gestures[@]}"
printf '\x01{"points": [[0, 0, 0], [10, 0, 0.1], [10, 10, 0.2, 0.5]], "name": "a\\u00e9"}\n' \
  >"$work/seeds-readers/jsonl"
printf '\x03listen = "unix:/tmp/p.sock"\npen_radius_mm = 1.0\n[device."056a:0010"]\ntolerance_fraction = 0.5\n' \
  >"$work/seeds-readers/config"
printf '\x04{"answer": "YES", "params": {"r": 1.25, "eps": "5/8"}, "p": [[0, 1e-3], [-2, 3.5]]}\n[1]\n' \
  >"$work/seeds-readers/json"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
run() {
  local dir="$1" target="$2"
  shift 2
  mkdir -p "$work/corpus/$target"
  echo "== $target: ${seconds}s"
  (cd "$work" && "../$dir/$target" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
     -print_final_stats=1 "corpus/$target" "$@")
}
run drivers descriptor_fuzzer seeds-descriptor
run drivers report_fuzzer seeds-descriptor
run drivers recording_fuzzer seeds-text
run daemon replay_file_fuzzer seeds-text
run clients file_readers_fuzzer seeds-readers seeds-readers/xml
echo "fuzzing: no findings"
