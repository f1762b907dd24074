#!/usr/bin/env bash
# rig.sh: end-to-end tests of --rig and --correspondence: the skinned fox passes the Khronos glTF
# validator (npm's gltf-validator, installed under the build folder on first use) with 0 errors;
# the correspondence JSON has one entry per input vertex, in order, with at most four balls whose
# weights sum to 1; the files are the same on one thread and on several; bad rig options and
# paths fail clearly.
# usage: rig.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"

npm_packages rig gltf-validator@2.0.0-dev.3.10

"$tool" "$data/fox.obj" -o "$tmp/fox.ma" --rig "$tmp/fox.glb" --correspondence "$tmp/fox.json" --json > "$tmp/report.json"
check "--rig and --correspondence exit 0" test $? -eq 0
check "the report gives the rig's joints and branches" py "j['rig']['joints'] >= 7 and j['rig']['branches'] >= 6 and j['outputs']['rig'].endswith('fox.glb')" "$tmp/report.json"
nv=$(grep -c '^v ' "$data/fox.obj")
check "one correspondence entry per input vertex" py "len(j['vertices']) == $nv" "$tmp/fox.json"
check "at most 4 balls per vertex, in range, weights summing to 1" py "all(0 < len(v['balls']) <= 4 and len(v['balls']) == len(v['weights']) and abs(sum(v['weights']) - 1) < 1e-9 and all(0 <= b < j['balls'] for b in v['balls']) for v in j['vertices'])" "$tmp/fox.json"
check "nearest primitives and branches named" py "all(v['nearest']['kind'] in ('ball', 'edge', 'face') and 0 <= v['branch'] < j['branches'] for v in j['vertices'])" "$tmp/fox.json"
"$tool" "$data/fox.obj" -o "$tmp/fox1.ma" --rig "$tmp/fox1.glb" --correspondence "$tmp/fox1.json" --threads 1 --quiet
check "the same rig on one thread" cmp -s "$tmp/fox.glb" "$tmp/fox1.glb"
check "the same correspondence on one thread" cmp -s "$tmp/fox.json" "$tmp/fox1.json"

# other shapes: a point cloud is skinned as points, and still valid
"$tool" "$data/fish_points.xyz" -o "$tmp/fish.ma" --rig "$tmp/fish.glb" --quiet
"$tool" "$data/torus.obj" -o "$tmp/torus.ma" --rig "$tmp/torus.glb" --max-joints 5 --json > "$tmp/torus.json"
check "--max-joints caps the joints" py "1 <= j['rig']['joints'] <= 5" "$tmp/torus.json"
check "the skinned fox, point cloud (fish) and capped torus pass the glTF validator with 0 errors" \
  validate_gltf "$tmp/fox.glb" "$tmp/fish.glb" "$tmp/torus.glb"

# failures
"$tool" "$data/fox.obj" -o "$tmp/f.ma" --rig "$tmp/f.glb" --max-joints 0 --json > "$tmp/e1.json"
check "--max-joints 0 is refused by the library (exit 1)" test $? -eq 1
check "... as CA_ERROR_INVALID_ARGUMENT naming max_joints" py "j['error']['status'] == 'CA_ERROR_INVALID_ARGUMENT' and 'max_joints' in j['error']['message']" "$tmp/e1.json"
"$tool" "$data/fox.obj" -o "$tmp/f.ma" --rig "$tmp/f.gltf" --json > "$tmp/e2.json"
check "--rig to a non-.glb path is a file error (exit 3)" test $? -eq 3
"$tool" "$data/fox.obj" -o "$tmp/f.ma" --rig "$tmp/f.glb" --rig-root 100000 --json > "$tmp/e3.json"
check "--rig-root past the balls is refused (exit 1)" test $? -eq 1
finish rig
