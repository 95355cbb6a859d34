#!/usr/bin/env bash
# Checks clang-format on C++ files: every tracked and untracked (not ignored) file by default, or
# only those changed since BASE. Usage: scripts/check-format.sh [BASE]. Exit 1 lists the files.
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"
if [ $# -ge 1 ]; then
  list() { git diff --name-only --diff-filter=ACMR "$1"; git ls-files --others --exclude-standard; }
  mapfile -t files < <(list "$1" | grep -E '\.(cpp|hpp|h|cc)$' | sort -u)
else
  mapfile -t files < <( { git ls-files; git ls-files --others --exclude-standard; } \
    | grep -E '\.(cpp|hpp|h|cc)$' | sort -u)
fi
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
