#!/usr/bin/env bash
# Runs a fuzz target once on every file in the given folders (missing folders are skipped): the
# ctest fuzz.<target>. Works with a libFuzzer binary (files as arguments run once each, no
# fuzzing) and with the replay main of a build without libFuzzer.
set -euo pipefail
exe=$1; shift
files=()
for dir in "$@"; do
  [ -d "$dir" ] || continue
  while IFS= read -r -d '' f; do files+=("$f"); done \
    < <(find "$dir" -maxdepth 1 -type f ! -name 'README*' ! -name '.*' -print0 | sort -z)
done
if [ ${#files[@]} -eq 0 ]; then
  echo "replay: no inputs in $*"
  exit 0
fi
exec "$exe" "${files[@]}"
