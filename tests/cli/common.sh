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

# expect STATUS MESSAGE CMD...: the command exits with STATUS and prints MESSAGE on stderr
# (out.txt and err.txt in the current directory keep what it printed).
expect() {
    want=$1 message=$2
    shift 2
    timeout 60 "$@" >out.txt 2>err.txt
    got=$?
    [ $got = "$want" ] || fail "$*: exit status $got, not $want ($(head -c 300 err.txt))"
    grep -qF -- "$message" err.txt || fail "$*: no '$message' in: $(head -c 300 err.txt)"
}
