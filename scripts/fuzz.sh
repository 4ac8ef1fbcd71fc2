#!/usr/bin/env bash
# Time-boxed fuzzing (docs/FUZZING.md): every fuzz target (or those named) for N seconds each,
# from its seed corpus, its regression inputs and what earlier runs found (out/fuzz/<target>/corpus).
# A crash, leak, time-out or out-of-memory is written to out/fuzz/<target>/ and printed in base64
# (to rescue it from a CI log); the script then fails. Copy the input to
# tests/fuzz/regressions/<target>/ when you fix it.
# Usage: scripts/fuzz.sh [seconds per target, default 30] [target ...]   (targets: csv nmea ...)
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-30}; shift || true
BUILD_DIR=${ATHLOS_ASAN_BUILD_DIR:-build-asan}
OUT=${ATHLOS_FUZZ_OUT:-out/fuzz}
# Targets whose findings are reported but do not fail the run (none: Project::open and the BROAD
# importer read damaged files in a child process, so libhdf5's crashes and hangs are refusals).
NONFATAL=" ${ATHLOS_FUZZ_NONFATAL-} "
# A hang of libhdf5 in the child is cut after 3 s, well inside libFuzzer's -timeout=10.
export ATHLOS_ISOLATION_TIMEOUT_S=${ATHLOS_ISOLATION_TIMEOUT_S:-3}

bash scripts/build-asan.sh athlos_fuzzers
source scripts/sanitizer-env.sh

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for src in tests/fuzz/fuzz_*.cpp; do t=${src#tests/fuzz/fuzz_}; targets+=("${t%.cpp}"); done
fi

failed=()
for t in "${targets[@]}"; do
  exe="$BUILD_DIR/bin/fuzz_$t"
  work="$OUT/$t"
  mkdir -p "$work/corpus" "$work/artifacts"
  rm -f "$work"/artifacts/*
  dict=(); [ -f "tests/fuzz/dict/$t.dict" ] && dict=(-dict="tests/fuzz/dict/$t.dict")
  seeds=("tests/fuzz/corpus/$t"); [ -d "tests/fuzz/regressions/$t" ] && seeds+=("tests/fuzz/regressions/$t")
  echo "fuzz: $t for ${SECONDS_PER_TARGET} s"
  start=$(date +%s)
  rc=0
  # libFuzzer stops itself after -max_total_time; timeout is the backstop if it cannot.
  timeout -k 10 $((SECONDS_PER_TARGET + 120)) "$exe" -max_total_time="$SECONDS_PER_TARGET" \
      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
      "${dict[@]}" "$work/corpus" "${seeds[@]}" >"$work/log" 2>&1 || rc=$?
  stats=$(grep -E '^stat::(number_of_executed_units|new_units_added)' "$work/log" | awk '{printf "%s ", $2}' || true)
  echo "fuzz: $t done in $(($(date +%s) - start)) s (exit $rc; runs, new units: ${stats:-?}; corpus $(ls "$work/corpus" | wc -l) files)"
  if [ "$rc" -ne 0 ]; then
    [ "$rc" -eq 124 ] && echo "fuzz: $t did not stop in time"
    grep -E 'ERROR|SUMMARY|==[0-9]+==|#[0-9]+ 0x' "$work/log" | head -40 || tail -40 "$work/log"
    for a in "$work"/artifacts/*; do
      [ -f "$a" ] || continue
      echo "fuzz: $t input $a ($(stat -c %s "$a") bytes), base64:"
      [ "$(stat -c %s "$a")" -le 65536 ] && base64 -w 0 "$a" && echo
    done
    if [[ "$NONFATAL" == *" $t "* ]]; then
      echo "fuzz: $t: finding reported, not fatal (ATHLOS_FUZZ_NONFATAL)"
    else
      failed+=("$t")
    fi
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (logs and inputs in $OUT/<target>/)"
  exit 1
fi
echo "fuzz: ${#targets[@]} targets, no crash"
