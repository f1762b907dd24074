#!/usr/bin/env bash
# skin_read.sh: end-to-end tests of the skin the tool reads. A rigged FBX is read in the tool's
# reader process (examples/cli/isolated_read.cpp): the frame that process writes
# (examples/cli/read_frame.cpp) carries the skin (its joints by name, parents, matrices and
# weights, checked here against make_rigged.py's humanoid), and the report names the skin, as for
# the same character's glTF read in process. The
# tool's own --rig output is a skinned glTF that reads back with its joints; an input without a
# skin reports none.
# usage: skin_read.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"
fast=(--samples 400 --voronoi-samples 1000)
r=$data/rigged

# 1. the frame of the reader process: the humanoid's 15 joints and their weights
"$tool" --internal-read "$r/humanoid.fbx" "" 60 0 > "$tmp/frame" 2> "$tmp/frame_err"
check "--internal-read exits 0" test $? -eq 0
check "the frame carries the humanoid's joints, a hierarchy with one root, finite matrices, rows of 4 weights summing to 1" python3 - "$tmp/frame" <<'EOF'
import math, struct, sys
b = open(sys.argv[1], "rb").read()
magic = b[:8]
ok, input_bytes, nv, nt, nn, msg, dropped, nj, infl, gnodes, name_bytes = struct.unpack_from("<11Q", b, 8)
at = 8 + 11 * 8
assert magic == b"CAMESH03" and ok == 1 and nj == 15 and infl == 4 and gnodes == 0, (magic, ok, nj, infl, gnodes)
at += nv * 24 + nt * 12 + nn * 24 + dropped
parents = struct.unpack_from("<%di" % nj, b, at); at += 4 * nj
mats = struct.unpack_from("<%dd" % (32 * nj), b, at); at += 8 * 32 * nj
at += 4 * gnodes
joints = struct.unpack_from("<%dI" % (nv * infl), b, at); at += 4 * nv * infl
weights = struct.unpack_from("<%dd" % (nv * infl), b, at); at += 8 * nv * infl
lengths = struct.unpack_from("<%dI" % nj, b, at); at += 4 * nj
blob = b[at:at + name_bytes]; at += name_bytes
assert at == len(b), (at, len(b))
names, k = [], 0
for n in lengths:
    names.append(blob[k:k + n].decode()); k += n
want = {"hips", "spine", "chest", "neck", "head", "upper_arm.L", "forearm.L", "upper_arm.R", "forearm.R",
        "thigh.L", "shin.L", "foot.L", "thigh.R", "shin.R", "foot.R"}
assert set(names) == want, names
assert [names[p] if p >= 0 else "" for p in parents][names.index("forearm.L")] == "upper_arm.L"
assert sum(1 for p in parents if p < 0) == 1
assert all(math.isfinite(x) for x in mats)
assert all(j < nj for j in joints)
assert all(abs(sum(weights[v * infl:(v + 1) * infl]) - 1) < 1e-9 for v in range(nv))
EOF

# 2. the report names the skin: the FBX through the reader process, the glTF in process
"$tool" "$r/humanoid.fbx" -o "$tmp/h.ma" --json "${fast[@]}" > "$tmp/fbx.json"
check "humanoid.fbx: skin of 15 joints, 4 weights per vertex" py "j['skin'] == {'joints': 15, 'influences': 4} and j['selected'] > 0" "$tmp/fbx.json"
"$tool" "$r/humanoid.glb" -o "$tmp/g.ma" --json "${fast[@]}" > "$tmp/glb.json"
check "humanoid.glb: the same skin and vertex count" py "j['skin'] == {'joints': 15, 'influences': 4} and j['input_vertices'] == $(python3 -c "import json; print(json.load(open('$tmp/fbx.json'))['input_vertices'])")" "$tmp/glb.json"
"$tool" "$r/snake.fbx" -o "$tmp/s.ma" "${fast[@]}" > "$tmp/snake.txt"
check "the text summary names the skin" grep -q "^skin        8 joints, 4 weights per vertex" "$tmp/snake.txt"

# 3. the tool's own rig reads back with its joints; no skin, no report of one
"$tool" "$data/fox.obj" -o "$tmp/fox.ma" --rig "$tmp/fox_rig.glb" --json "${fast[@]}" > "$tmp/fox.json"
check "fox.obj: no skin" py "j['skin'] is None" "$tmp/fox.json"
joints=$(python3 -c "import json; print(json.load(open('$tmp/fox.json'))['rig']['joints'])")
"$tool" "$tmp/fox_rig.glb" -o "$tmp/back.ma" --json "${fast[@]}" > "$tmp/back.json"
check "the --rig glb reads back with its $joints joints" py "j['skin'] == {'joints': $joints, 'influences': 4}" "$tmp/back.json"
"$tool" evaluate "$tmp/fox_rig.glb" "$tmp/back.ma" --json > "$tmp/eval.json"
check "evaluate's report names the skin too" py "j['skin']['joints'] == $joints" "$tmp/eval.json"
finish skin_read
