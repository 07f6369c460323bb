#!/usr/bin/env bash
# One style for the whole tree: every C++ and CUDA source file is as
# clang-format writes it (.clang-format), and every header guard is the
# header's path in lower case (particulate_<module>_<file>_h), and every
# namespace is opened one level at a time (`namespace particulate {
# namespace fluid {`, not `namespace particulate::fluid {`). Prints the
# files that differ and exits 1; `scripts/check-format.sh --fix` reformats
# them (the guards it only reports). The CTest style_source_is_formatted
# runs it.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || {
  echo "check-format: clang-format is not installed (scripts/setup.sh installs it)" >&2
  exit 1
}
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cc' '*.h' '*.cu' '*.cuh')
else
  mapfile -t files < <(find source include tests cuda \
    \( -name '*.cc' -o -name '*.h' -o -name '*.cu' -o -name '*.cuh' \) | sort)
fi

unformatted=()
bad_guards=()
compound_namespaces=()
for f in "${files[@]}"; do
  if [[ "${1:-}" == "--fix" ]]; then
    clang-format -i "$f"
  elif ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
    unformatted+=("$f")
  fi
  if grep -qE '^\s*namespace [A-Za-z_0-9]+::' "$f"; then
    compound_namespaces+=("$f")
  fi
  if [[ "$f" == *.h || "$f" == *.cuh ]]; then
    guard=$(sed -n 's/^#ifndef \([A-Za-z0-9_]*\)$/\1/p' "$f" | head -1)
    if ! [[ "$guard" =~ ^particulate_[a-z0-9_]+_(h|cuh)$ ]] \
       || ! grep -qx "#define $guard" "$f"; then
      bad_guards+=("$f (${guard:-no guard})")
    fi
  fi
done

status=0
if (( ${#unformatted[@]} )); then
  printf 'not as clang-format writes it: %s\n' "${unformatted[@]}"
  echo "fix: scripts/check-format.sh --fix"
  status=1
fi
if (( ${#bad_guards[@]} )); then
  printf 'header guard not particulate_<path>_h: %s\n' "${bad_guards[@]}"
  status=1
fi
if (( ${#compound_namespaces[@]} )); then
  printf 'namespace not opened one level at a time: %s\n' "${compound_namespaces[@]}"
  status=1
fi
(( status )) || echo "check-format: ${#files[@]} files in style"
exit $status
