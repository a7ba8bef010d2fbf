#!/usr/bin/env bash
# Regenerates package_info/VTP_geodesics/dependencies: the CGAL packages whose headers are reached,
# directly or not, by the headers of include/ (each header is preprocessed on its own, as CGAL's
# header check does). Installed CGAL headers carry their package in their expanded $URL$ line
# (".../blob/v5.5.1/<Package>/include/..."), which gives the header -> package mapping.
# Usage: bash scripts/update_package_dependencies.sh [--check]
#   --check: do not write; exit 1 if the file is out of date.
set -euo pipefail
export LC_ALL=C

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/package_info/VTP_geodesics/dependencies"
cxx="${CXX:-c++}"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

: > "$tmp/headers"
while IFS= read -r h; do
  printf '#include <%s>\n' "${h#"$root"/include/}" > "$tmp/tu.cpp"
  # -M lists every header the translation unit reads; -fopenmp and the package macro also reach
  # the code of the OpenMP path.
  "$cxx" -std=c++17 -fopenmp -DCGAL_VTP_GEODESICS_LINKED_WITH_OPENMP -I"$root/include" -M "$tmp/tu.cpp" \
    | tr ' \\' '\n\n' | grep -E '/CGAL/' | grep -v "^$root/" >> "$tmp/headers" || true
done < <(find "$root/include" -name '*.h' | sort)

{
  echo VTP_geodesics
  sort -u "$tmp/headers" | while IFS= read -r f; do
    [ -n "$f" ] || continue
    pkg="$(grep -m1 -oE 'blob/v[0-9][^/]*/[A-Za-z0-9_]+/' "$f" | cut -d/ -f3 || true)"
    if [ -z "$pkg" ]; then
      echo "warning: no package found in the \$URL\$ line of $f" >&2
      continue
    fi
    echo "$pkg"
  done
} | sort -u > "$tmp/dependencies"

if [ "${1:-}" = "--check" ]; then
  if diff -u "$out" "$tmp/dependencies"; then
    echo "package_info/VTP_geodesics/dependencies is up to date"
  else
    echo "package_info/VTP_geodesics/dependencies is out of date: run scripts/update_package_dependencies.sh" >&2
    exit 1
  fi
else
  cp "$tmp/dependencies" "$out"
  echo "wrote $out:"
  cat "$out"
fi
