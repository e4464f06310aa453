#!/usr/bin/env bash
# Extracts every shared map (default parameters, plus a CCL and a coarsened
# variant) and either records the outputs (`record DIR`) or compares them
# byte-for-byte with a recording (`compare DIR`). Used to prove that a
# speed-up changes no result.
set -euo pipefail
mode=${1:?record|compare}; dir=${2:?output dir}
bin=${NRGDB_BIN:-./target/release/nrgdb}
maps=${NRGDB_SHARED:-../shared}/maps
out=$dir; [ "$mode" = compare ] && out=$(mktemp -d)
mkdir -p "$out"
variants=("default:" "ccl:--method ccl" "coarse:--set working_resolution_m=0.1" "nofurn:--set furniture_max_m=0 --set unknown_pocket_max_m2=0")
for y in "$maps"/*.yaml; do
  name=$(basename "$y" .yaml)
  for v in "${variants[@]}"; do
    tag=${v%%:*}; args=${v#*:}
    # shellcheck disable=SC2086
    "$bin" extract "$y" $args --labels "$out/$name.$tag.png" --json "$out/$name.$tag.json" \
      >/dev/null 2>"$out/$name.$tag.err" || echo "exit $?" >>"$out/$name.$tag.err"
  done
done
if [ "$mode" = compare ]; then
  if diff -r -q "$dir" "$out"; then echo "IDENTICAL ($(ls "$out" | wc -l) files)"; else echo "DIFFERENT"; exit 1; fi
  rm -rf "$out"
fi
