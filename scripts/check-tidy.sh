#!/usr/bin/env bash
# Runs clang-tidy (the checks of .clang-tidy, the nearest one to each file) over the project's own
# translation units in a build's compile_commands.json, never the generated proto code nor the
# tables CMake writes, and reports findings in the project's headers too. Exit 1 on any finding, 2
# when the build is missing. Run it after the build: generated headers are needed.
# Usage: scripts/check-tidy.sh [BUILD_DIR] [FILE_REGEX]
#   BUILD_DIR   default build/release
#   FILE_REGEX  which files (paths from the repository's root), default the code the programs are
#               made of: '^(core|daemon|drivers|clients|proto)/'. '.' adds tests/ and bench/
#               (about as long again); CI runs '.', the whole tree.
#   PENSHAPE_TIDY_JOBS parallel runs, default 2.
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"
root=$(pwd)
build=${1:-build/release}
only=${2:-^(core|daemon|drivers|clients|proto)/}
jobs=${PENSHAPE_TIDY_JOBS:-2}
tidy=$(command -v clang-tidy-14 || command -v clang-tidy || true)
if [ -z "$tidy" ]; then
  echo "tidy: clang-tidy not found (scripts/setup.sh installs clang-tidy-14)" >&2
  exit 2
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "tidy: $build/compile_commands.json is missing: configure and build that preset first" >&2
  exit 2
fi
# The project's own sources only; findings in headers outside these folders are not ours.
mapfile -t files < <(/usr/bin/python3 - "$build/compile_commands.json" "$root" "$only" <<'EOF'
import json, re, sys
db, root, only = sys.argv[1], sys.argv[2] + "/", re.compile(sys.argv[3])
own = re.compile(r"(core|drivers|daemon|clients|proto/src|tests|bench)/")
for f in sorted({e["file"] for e in json.load(open(db))}):
    if f.startswith(root) and own.match(f[len(root):]) and only.search(f[len(root):]):
        print(f)
EOF
)
header_filter="^$root/(core|drivers|daemon|clients|proto/(src|include)|tests|bench)/"
# PENSHAPE_TIDY_LOGS=DIR keeps each file's output there (N.log, N.failed); else a temporary folder.
if [ -n "${PENSHAPE_TIDY_LOGS:-}" ]; then
  logs=$PENSHAPE_TIDY_LOGS
  mkdir -p "$logs"
else
  logs=$(mktemp -d)
  trap 'rm -rf "$logs"' EXIT
fi
export tidy build header_filter logs
start=$(date +%s)
# One clang-tidy per file, its output kept apart so parallel runs do not interleave.
# PENSHAPE_TIDY_TIMES=FILE appends "user_s system_s wall_s file" per file (to find the slow ones).
times=${PENSHAPE_TIDY_TIMES:-}
export times
printf '%s\n' "${files[@]}" | nl -ba -w1 -s' ' | xargs -P "$jobs" -L1 sh -c '
  timed() {
    label=$1; shift
    if [ -n "$times" ]; then /usr/bin/time -a -o "$times" -f "%U %S %e $label" "$@"; else "$@"; fi
  }
  if ! timed "$1" "$tidy" -p "$build" --quiet --warnings-as-errors="*" --header-filter="$header_filter" \
      "$1" >"$logs/$0.log" 2>&1; then
    touch "$logs/$0.failed"
  fi' || true
failed=$(find "$logs" -name '*.failed' | wc -l)
# Show each finding once (a header's finding repeats in every file that includes it).
cat "$logs"/*.log 2>/dev/null | grep -v -E '^[0-9]+ (warning|error)s? (generated|treated as error)' \
  | awk '/: (warning|error): / { seen_it = seen[$0]++ } !seen_it' || true
echo "tidy: ${#files[@]} files in $(( $(date +%s) - start )) s, $failed with findings (-j$jobs)"
[ "$failed" -eq 0 ]
