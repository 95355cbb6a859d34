#!/usr/bin/env bash
# Short libFuzzer runs of the drivers' fuzz targets (descriptor parser, report decoder and
# pipeline, recording/table parsers), seeded from ../shared/data/hid. CI calls this after the
# asan preset's build; a finding fails the run and leaves its crash file in build/asan/fuzz/.
#   scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
data="${PENSHAPE_SHARED_DATA_DIR:-$(pwd)/../shared/data}/hid"
build=build/asan
cmake --preset asan >/dev/null
cmake --build --preset asan -j2 --target descriptor_fuzzer report_fuzzer recording_fuzzer

work="$build/fuzz"
rm -rf "$work"
mkdir -p "$work/seeds-descriptor" "$work/seeds-text" "$work/corpus"
# Descriptor seeds: every raw descriptor; text seeds: hid-recorder files, dumps, the table.
# (numbered copies: the same file name recurs across devices)
i=0
while IFS= read -r f; do
  cp "$f" "$work/seeds-descriptor/$((i++)).bin"
done < <(find "$data/wacom-hid-descriptors" -name '*.hid.bin' | sort)
i=0
while IFS= read -r f; do
  cp "$f" "$work/seeds-text/$((i++)).txt"
done < <(find "$data" \( -name 'hidrecord.txt' -o -name '*.hidrec.txt' -o -path '*dumps*' \
           -name 'pen_*.txt' -size -64k \) | sort)
cp drivers/data/tablets.tsv "$work/seeds-text/"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
run() {
  local target="$1" seeds="$2"
  mkdir -p "$work/corpus/$target"
  echo "== $target: ${seconds}s"
  (cd "$work" && "../drivers/$target" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
     -print_final_stats=1 "corpus/$target" "$seeds")
}
run descriptor_fuzzer "seeds-descriptor"
run report_fuzzer "seeds-descriptor"
run recording_fuzzer "seeds-text"
echo "fuzzing: no findings"
