#!/usr/bin/env bash
# run_tests.sh: builds the C# binding and its tests with mcs into OUT_DIR and runs them with mono
# against the shared library in LIB_DIR.
# usage: run_tests.sh OUT_DIR LIB_DIR ABI_LAYOUT_EXE CLI_EXE TEST_DATA_DIR
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=$1 lib=$2
mkdir -p "$out"
mcs -nologo -warnaserror -unsafe -target:library -out:"$out/CoverageAxis.dll" "$here/CoverageAxis.cs"
mcs -nologo -warnaserror -r:"$out/CoverageAxis.dll" -out:"$out/TestCoverageAxis.exe" "$here/tests/TestCoverageAxis.cs"
LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" mono "$out/TestCoverageAxis.exe" "$3" "$4" "$5"
