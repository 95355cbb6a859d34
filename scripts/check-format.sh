#!/usr/bin/env bash
# Checks clang-format on the C++ files changed against a base (default: the first commit, i.e.
# every tracked file). Usage: scripts/check-format.sh [BASE]. Exit 1 lists the files to fix.
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"
base=${1:-$(git rev-list --max-parents=0 HEAD | tail -n 1)}
mapfile -t files < <( { git diff --name-only --diff-filter=ACMR "$base" -- ; \
  git ls-files --others --exclude-standard ; [ "$base" = "$(git rev-list --max-parents=0 HEAD | tail -n 1)" ] && git ls-files ; } \
  | grep -E '\.(cpp|hpp|h|cc)$' | sort -u)
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "format: these files need clang-format -i:" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "format: ${#files[@]} files checked, all formatted"
