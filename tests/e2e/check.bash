# check.bash: the harness the e2e scripts source (not a test itself: ctest runs tests/e2e/*.sh):
# the tool and data paths from the arguments, a temp folder removed at exit, and check(), which
# runs a command and counts it as passed or failed.
# usage (in a test): source "$(dirname "$0")/check.bash" "$@"; ...; finish NAME
tool=$1
data=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
check() {  # check "description" command...
  local what=$1; shift
  if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAILED: $what"; fi
}
finish() {  # finish NAME: the closing line and the exit status
  echo "$1: $pass passed, $fail failed"
  test "$fail" -eq 0
}
