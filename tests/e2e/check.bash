# check.bash: the harness the e2e scripts source (not a test itself: ctest runs tests/e2e/*.sh):
# the tool and data paths from the arguments, this folder, a temp folder removed at exit, check(),
# which runs a command and counts it as passed or failed, and the helpers the scripts share: JSON
# predicates, the npm packages and the glTF validator.
# usage (in a test): source "$(dirname "$0")/check.bash" "$@"; ...; finish NAME
tool=$1
data=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
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
# py EXPR FILE: true when the Python expression EXPR holds for the JSON document in FILE (as j).
py() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); sys.exit(0 if ($1) else 1)" "$2"; }
# pylines EXPR FILE: the same for a file of JSON lines (as the list L).
pylines() { python3 -c "import json,sys; L=[json.loads(l) for l in open(sys.argv[1])]; sys.exit(0 if ($1) else 1)" "$2"; }
# validate_gltf FILE...: the Khronos glTF validator (validate_gltf.js) with 0 errors on every file;
# after npm_packages NAME gltf-validator@...
validate_gltf() { NODE_PATH="$modules" node "$here/validate_gltf.js" "$@"; }
