#!/usr/bin/env bash
# hostile_readers.sh: end-to-end tests of the reads through assimp, which run in a child process:
# each file of tests/data/hostile (assimp's importer crashes on one, loops allocating on another,
# its post-processing crashed or aborted on the other two) ends a run with exit 3 and one line
# naming the file, within the read's time limit; in a batch those files get error lines while
# the good files beside them still get skeletons; a good assimp file reads as the same mesh.
# usage: hostile_readers.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"
# pylines 'expression over the list of line objects L' FILE
h=$data/hostile
fast=(--samples 300 --voronoi-samples 800)
# timed CMD...: runs CMD under a hard outer bound (a hang must not hang the test); sets code and
# elapsed (seconds)
timed() {
  local start=$EPOCHREALTIME
  timeout -s KILL 120 "$@"
  code=$?
  elapsed=$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN{printf "%.2f", b - a}')
}
within() { awk -v e="$1" -v l="$2" 'BEGIN{exit !(e <= l)}'; }

# 1. each hostile file alone: exit 3, one line naming the file, within the read's bound (10 s)
#    plus the time to start and report
for f in misc_telep.md3 assimp_md3_segv.md3 assimp_ac_abort.ac assimp_md3_hang.md3; do
  timed "$tool" "$h/$f" -o "$tmp/$f.ma" --quiet --read-time-limit 10 "${fast[@]}" 2> "$tmp/err"
  check "$f: exit 3 (got $code)" test "$code" -eq 3
  check "$f: one-line message naming the file" test "$(wc -l < "$tmp/err")" -eq 1 -a -n "$(grep -F "$h/$f: " "$tmp/err")"
  check "$f: ended in $elapsed s, within 10 s + 5" within "$elapsed" 15
  check "$f: no .ma" test ! -e "$tmp/$f.ma"
done
# what ended each: the scene check (no post-processing ran), the crash, the memory limit
timed "$tool" "$h/misc_telep.md3" -o "$tmp/t.ma" --quiet 2> "$tmp/err"
check "misc_telep.md3: refused before post-processing (a null mesh)" grep -q "mMeshes\[0\] is nullptr\|mesh 0 is missing" "$tmp/err"
timed "$tool" "$h/assimp_ac_abort.ac" -o "$tmp/a.ma" --quiet 2> "$tmp/err"
check "assimp_ac_abort.ac: refused before triangulation (a face without indices)" grep -q "mIndices is nullptr\|has no indices" "$tmp/err"
timed "$tool" "$h/assimp_md3_segv.md3" -o "$tmp/s.ma" --quiet 2> "$tmp/err"
check "assimp_md3_segv.md3: the reader's crash is reported" grep -q "the assimp reader crashed (SIGSEGV" "$tmp/err"
timed "$tool" "$h/assimp_md3_hang.md3" -o "$tmp/h.ma" --quiet --read-memory-limit 256 2> "$tmp/err"
check "assimp_md3_hang.md3, 256 MiB: exit 3 (got $code)" test "$code" -eq 3
check "assimp_md3_hang.md3, 256 MiB: the memory limit is named" grep -q "memory limit is 256 MiB" "$tmp/err"

# 2. the hang with memory to spare: --time-limit bounds the read (and the run)
timed "$tool" "$h/assimp_md3_hang.md3" -o "$tmp/h.ma" --json --time-limit 3 --read-memory-limit 100000 > "$tmp/h.json"
check "hang, --time-limit 3: exit 3 (got $code)" test "$code" -eq 3
check "hang, --time-limit 3: ended in $elapsed s, within 3 s + 3" within "$elapsed" 6
check "hang, --time-limit 3: a FILE_ERROR naming the time limit" pylines \
  "L[0]['error']['status'] == 'FILE_ERROR' and 'did not end within its time limit of 3 s' in L[0]['error']['message']" "$tmp/h.json"
timed "$tool" "$h/assimp_md3_hang.md3" -o "$tmp/h.ma" --quiet --time-limit 30 --read-time-limit 2 --read-memory-limit 100000 2> "$tmp/err"
check "hang, --read-time-limit 2 under --time-limit 30: ended in $elapsed s, within 2 s + 3" within "$elapsed" 5
check "hang, --read-time-limit 2: the message names 2 s" grep -q "time limit of 2 s" "$tmp/err"

# 3. standard input and the evaluate command read through the child as well
timed "$tool" - --format md3 -o "$tmp/i.ma" --quiet < "$h/assimp_md3_segv.md3" 2> "$tmp/err"
check "crash from standard input: exit 3 naming <stdin> (got $code)" test "$code" -eq 3 -a -n "$(grep -F "<stdin>: the assimp reader crashed" "$tmp/err")"
"$tool" "$data/fox.obj" -o "$tmp/fox.ma" --quiet "${fast[@]}"
timed "$tool" evaluate "$h/assimp_md3_segv.md3" "$tmp/fox.ma" 2> "$tmp/err"
check "evaluate on the crashing file: exit 3 with one line (got $code)" test "$code" -eq 3 -a "$(wc -l < "$tmp/err")" -eq 1

# 4. a good assimp file: read in the child, the same mesh and skeleton as its glTF twin (both
#    fox.obj at float32)
cp "$data/formats/fox.dae" "$tmp/fox_dae.dae"
"$tool" "$tmp/fox_dae.dae" -o "$tmp/fox_dae.ma" --json "${fast[@]}" > "$tmp/dae.json"
check "fox.dae through the child runs (exit $?)" test -s "$tmp/fox_dae.ma"
"$tool" "$data/formats/fox.glb" -o "$tmp/fox_glb.ma" --json "${fast[@]}" > "$tmp/glb.json"
check "fox.dae: fox.glb's vertex and triangle counts" pylines \
  "L[0]['input_vertices'] == $(python3 -c "import json; print(json.load(open('$tmp/glb.json'))['input_vertices'])") and L[0]['input_triangles'] == $(python3 -c "import json; print(json.load(open('$tmp/glb.json'))['input_triangles'])")" "$tmp/dae.json"
check "fox.dae: fox.glb's skeleton, byte for byte" cmp -s "$tmp/fox_dae.ma" "$tmp/fox_glb.ma"

# 5. batch: the hostile files beside good ones, two at a time
cp "$data/fox.obj" "$data/torus.obj" "$tmp/"
timed "$tool" batch -O "$tmp/out" -j 2 --read-time-limit 10 "${fast[@]}" "$tmp/fox.obj" "$h/misc_telep.md3" \
  "$h/assimp_md3_hang.md3" "$h/assimp_md3_segv.md3" "$tmp/fox_dae.dae" "$h/assimp_ac_abort.ac" "$tmp/torus.obj" > "$tmp/b.jsonl"
check "batch: exit 1, some input failed (got $code)" test "$code" -eq 1
check "batch: ended in $elapsed s, within 60 s" within "$elapsed" 60
check "batch: one line per input" test "$(wc -l < "$tmp/b.jsonl")" -eq 7
check "batch: the four hostile files have FILE_ERROR lines naming them" pylines \
  "all(L[i]['error']['status'] == 'FILE_ERROR' and L[i]['error']['message'].startswith(L[i]['input'] + ': ') for i in (1, 2, 3, 5))" "$tmp/b.jsonl"
check "batch: fox.obj, fox_dae.dae and torus.obj have skeletons" pylines \
  "all('error' not in L[i] and L[i]['selected'] > 0 for i in (0, 4, 6))" "$tmp/b.jsonl"
check "batch: .ma files for the good inputs only" test -s "$tmp/out/fox.ma" -a -s "$tmp/out/fox_dae.ma" -a -s "$tmp/out/torus.ma" \
  -a ! -e "$tmp/out/misc_telep.ma" -a ! -e "$tmp/out/assimp_md3_segv.ma" -a ! -e "$tmp/out/assimp_md3_hang.ma" -a ! -e "$tmp/out/assimp_ac_abort.ma"
check "batch: fox.dae's skeleton is the single run's" cmp -s "$tmp/out/fox_dae.ma" "$tmp/fox_dae.ma"

# 6. no core files and no reader processes left behind
check "no core file written" test -z "$(find "$tmp" . -maxdepth 1 -name 'core*' -newer "$tmp/fox.ma" 2>/dev/null)"
check "no reader process left" test -z "$(pgrep -f -- "--internal-read $h" 2>/dev/null)"

finish hostile_readers
