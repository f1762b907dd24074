#!/usr/bin/env bash
# dropped_parts.sh: end-to-end tests of reading files that assimp's validation refuses whole for a
# part the tool never uses (tests/data/dropped: an animation whose keys run past its duration, an
# empty mesh among good ones, a camera and a light at fault). Each gives the skeleton of its sound
# twin (the same geometry without the faulty part, which assimp accepts), byte for byte; the JSON
# report names what was dropped, the text summary warns in one line, and a batch line carries the
# list too. Variants whose geometry itself is broken (an index out of range, a NaN vertex, a face
# of no vertices beside the dropped camera) are still refused with one line naming the file.
# usage: dropped_parts.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"
# pyjson 'expression over the object J' FILE: the first line of FILE as JSON
pyjson() { python3 -c "import json,sys; J=json.loads(open(sys.argv[1]).readline()); sys.exit(0 if ($1) else 1)" "$2"; }
# pylines 'expression over the list of line objects L' FILE
d=$data/dropped
fast=(--samples 400 --voronoi-samples 1000)
mkdir -p "$tmp/twins" "$tmp/broken"
python3 "$d/make_dropped.py" --twins "$tmp/twins"
python3 "$d/make_dropped.py" --broken "$tmp/broken"
check "the bundled files are what make_dropped.py writes" python3 -c "
import sys; sys.path.insert(0, '$d'); import make_dropped as m
ok = open('$d/keys_past_duration.b3d', 'rb').read() == m.keys_past_duration_b3d() and \
     open('$d/empty_mesh.b3d', 'rb').read() == m.empty_mesh_b3d() and open('$d/camera_light.dae').read() == m.camera_light_dae()
sys.exit(0 if ok else 1)"

# 1. each file: a skeleton, the twin's byte for byte, and the JSON names exactly what was dropped
declare -A expect=(
  [keys_past_duration.b3d]='["animation 0: keys past its duration"]'
  [empty_mesh.b3d]='["mesh '"'"'Box.003'"'"': no vertices"]'
  [camera_light.dae]='["camera '"'"'Camera-node'"'"': its far clip plane is not beyond its near one", "light '"'"'Spot-node'"'"': its inner cone is wider than its outer one"]'
)
for f in keys_past_duration.b3d empty_mesh.b3d camera_light.dae; do
  "$tool" "$d/$f" -o "$tmp/$f.ma" --json "${fast[@]}" > "$tmp/$f.json" 2> "$tmp/err"
  check "$f: exit 0 (got $?; $(head -c 300 "$tmp/$f.json"))" test -s "$tmp/$f.ma"
  check "$f: a skeleton" pyjson "J['selected'] > 0 and 'error' not in J" "$tmp/$f.json"
  check "$f: dropped is ${expect[$f]}" pyjson "J['dropped'] == ${expect[$f]}" "$tmp/$f.json"
  check "$f: nothing on stderr with --json" test ! -s "$tmp/err"
  "$tool" "$tmp/twins/$f" -o "$tmp/twin_$f.ma" --json "${fast[@]}" > "$tmp/twin_$f.json"
  check "$f: its twin drops nothing" pyjson "J['dropped'] == []" "$tmp/twin_$f.json"
  check "$f: the twin's input counts" python3 -c "import json,sys; a=json.load(open('$tmp/$f.json')); b=json.load(open('$tmp/twin_$f.json'))
sys.exit(0 if (a['input_vertices'], a['input_triangles']) == (b['input_vertices'], b['input_triangles']) else 1)"
  check "$f: the twin's skeleton, byte for byte" cmp -s "$tmp/$f.ma" "$tmp/twin_$f.ma"
done
check "keys_past_duration.b3d: one ellipsoid of 86 vertices and 168 triangles" \
  pyjson "(J['input_vertices'], J['input_triangles']) == (86, 168)" "$tmp/keys_past_duration.b3d.json"
check "empty_mesh.b3d: three ellipsoids" pyjson "(J['input_vertices'], J['input_triangles']) == (258, 504)" "$tmp/empty_mesh.b3d.json"

# 2. the text summary: one warning line naming the dropped part; a sound file has none
"$tool" "$d/keys_past_duration.b3d" -o "$tmp/k.ma" "${fast[@]}" > "$tmp/summary" 2> "$tmp/err"
check "summary: exit 0 (got $?)" test -s "$tmp/k.ma"
check "summary: one warning line" test "$(grep -c '^warning' "$tmp/summary")" -eq 1
check "summary: it names the animation and its fault" grep -q "^warning .*animation 0: keys past its duration" "$tmp/summary"
"$tool" "$tmp/twins/keys_past_duration.b3d" -o "$tmp/t.ma" "${fast[@]}" > "$tmp/summary"
check "summary of the twin: no warning" test "$(grep -c '^warning' "$tmp/summary")" -eq 0

# 3. batch: every line carries its list (empty for a sound file)
cp "$data/torus.obj" "$tmp/"
"$tool" batch -O "$tmp/out" -j 2 "${fast[@]}" "$d/keys_past_duration.b3d" "$tmp/torus.obj" "$d/camera_light.dae" \
  "$d/empty_mesh.b3d" > "$tmp/b.jsonl"
check "batch: exit 0 (got $?)" test -s "$tmp/out/empty_mesh.ma"
check "batch: the dropped lists" pylines "[len(l['dropped']) for l in L] == [1, 0, 2, 1] and all(l['selected'] > 0 for l in L)" "$tmp/b.jsonl"
check "batch: empty_mesh.b3d names Box.003" pylines "L[3]['dropped'] == [\"mesh 'Box.003': no vertices\"]" "$tmp/b.jsonl"
check "batch: the single run's skeleton" cmp -s "$tmp/out/keys_past_duration.ma" "$tmp/keys_past_duration.b3d.ma"
"$tool" batch -O "$tmp/out" "${fast[@]}" "$d/keys_past_duration.b3d" > "$tmp/b2.jsonl"
check "batch rerun: skipped, the stored report keeps the list" \
  pylines "L[0]['skipped'] and L[0]['dropped'] == ['animation 0: keys past its duration']" "$tmp/b2.jsonl"

# 4. broken geometry is still refused: exit 3, one line naming the file and the fault, no .ma
declare -A fault=(
  [bad_index.b3d]='Bad triangle index'
  [nan_vertex.b3d]='assimp scene: mesh 0 vertex [0-9]* is not finite'
  [empty_face.dae]='Validation failed: aiMesh::mFaces\[0\]'
)
for f in bad_index.b3d nan_vertex.b3d empty_face.dae; do
  "$tool" "$tmp/broken/$f" -o "$tmp/$f.ma" --quiet "${fast[@]}" 2> "$tmp/err"
  code=$?
  check "$f: exit 3 (got $code)" test "$code" -eq 3
  check "$f: one line naming the file ($(head -c 300 "$tmp/err"))" test "$(wc -l < "$tmp/err")" -eq 1 -a -n "$(grep -F "$tmp/broken/$f: " "$tmp/err")"
  check "$f: the fault is named" grep -q "${fault[$f]}" "$tmp/err"
  check "$f: no .ma" test ! -e "$tmp/$f.ma"
done
check "empty_face.dae: the message says what was dropped first" grep -q "after dropping 2 unused parts at fault: camera 'Camera-node'" "$tmp/err"
"$tool" "$tmp/broken/empty_face.dae" -o "$tmp/e.ma" --json "${fast[@]}" > "$tmp/e.json"
check "empty_face.dae --json: a FILE_ERROR" pyjson "J['error']['status'] == 'FILE_ERROR' and 'mNumIndices is 0' in J['error']['message']" "$tmp/e.json"

finish dropped_parts
