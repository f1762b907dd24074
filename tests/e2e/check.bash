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
# npm_packages NAME PACKAGE@VERSION...: the e2e's npm packages under the build folder's npm/,
# installed on first use (one folder for every test); without npm, or when the install fails, the
# test fails saying so. Sets npm_dir and modules (its node_modules, for NODE_PATH).
npm_packages() {
  local name=$1 p missing=0; shift
  npm_dir="$(cd "$(dirname "$tool")" && pwd)/npm"
  modules="$npm_dir/node_modules"
  for p in "$@"; do [ -f "$modules/${p%@*}/package.json" ] || missing=1; done
  [ "$missing" -eq 0 ] && return 0
  command -v npm > /dev/null || { echo "$name: npm is missing (scripts/install-deps.sh installs it)"; exit 1; }
  npm install --no-audit --no-fund --silent --prefix "$npm_dir" "$@" > /dev/null ||
    { echo "$name: npm could not install $*"; exit 1; }
}
