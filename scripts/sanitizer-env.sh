# Sourced: how the sanitizers report in tests, fuzzing and the build (gtest discovery runs tests).
# Stop at the first error of either sanitizer, with a stack trace; leaks are checked at exit, with
# the suppressions of tests/fuzz/lsan.supp (leaks of system libraries we do not own) and
# tests/fuzz/ubsan.supp (findings reported to their owners, not fixed yet).
_fuzz="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/fuzz"
export ASAN_OPTIONS="${ASAN_OPTIONS:-check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$_fuzz/ubsan.supp}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$_fuzz/lsan.supp:print_suppressions=0}"
unset _fuzz
