#!/usr/bin/env bash
# Counts each function's McCabe complexity and length with pmccabe over the code the programs are
# made of (core, daemon, drivers, clients, proto; tests and benches may read as long scripts), and
# fails on any function above complexity 25 or over 80 lines: functions you can read at once.
# clang-tidy's readability-function-size checks the lines too (scripts/check-tidy.sh); this is the
# complexity count, the same one the project is checked with.
# Usage: scripts/check-complexity.sh [MAX_COMPLEXITY] [MAX_LINES]   (defaults 25 and 80)
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"
max_complexity=${1:-25}
max_lines=${2:-80}
if ! command -v pmccabe >/dev/null; then
  echo "complexity: pmccabe not found (scripts/setup.sh installs it)" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mapfile -t files < <(git ls-files -- 'core/*.cpp' 'core/*.hpp' 'daemon/*.cpp' 'daemon/*.hpp' \
  'drivers/*.cpp' 'drivers/*.hpp' 'clients/*.cpp' 'clients/*.hpp' 'proto/*.cpp' 'proto/*.hpp')
# pmccabe predates C++17: it misreads nested namespace names (a::b) and digit separators (1'000),
# so copies with those rewritten are counted; line numbers stay the same.
for f in "${files[@]}"; do
  mkdir -p "$work/$(dirname "$f")"
  sed -E -e 's/^namespace [A-Za-z_][A-Za-z_0-9]*(::[A-Za-z_][A-Za-z_0-9]*)+ \{/namespace nested {/' \
    -e ":a; s/([0-9])'([0-9])/\1\2/; ta" "$f" >"$work/$f"
done
# pmccabe's columns: modified McCabe, McCabe, statements, first line, lines, file(line): name.
report=$(cd "$work" && pmccabe "${files[@]}" 2>/dev/null |
  awk -v c="$max_complexity" -v l="$max_lines" '$2 > c || $5 > l {
    printf "%s: complexity %d, %d lines (limits %d, %d)\n", $6 " " $7, $2, $5, c, l }')
if [ -n "$report" ]; then
  echo "$report"
  echo "complexity: $(wc -l <<<"$report") functions over the limits in ${#files[@]} files"
  exit 1
fi
echo "complexity: ${#files[@]} files, no function above complexity $max_complexity or over $max_lines lines"
