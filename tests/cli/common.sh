# Shared by the tests/cli scripts (sourced after they set src and glslrun):
# a temporary directory removed on exit, and fail/finish to count failed
# checks and end with their verdict.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
# finish "what passed": prints it when no check failed; the exit status says.
finish() {
    [ $failures = 0 ] && echo "$1"
    exit $((failures != 0))
}
