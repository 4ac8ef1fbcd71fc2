# Sourced: how the sanitizers report in tests, fuzzing and the build (gtest discovery runs tests).
# Stop at the first error of either sanitizer, with a stack trace; leaks are checked at exit, with
# the suppressions of tests/fuzz/lsan.supp (leaks of system libraries we do not own).
_supp="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/fuzz/lsan.supp"
export ASAN_OPTIONS="${ASAN_OPTIONS:-check_initialization_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$_supp:print_suppressions=0}"
unset _supp
