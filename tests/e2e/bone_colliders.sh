#!/usr/bin/env bash
# bone_colliders.sh: end-to-end tests of --bone-colliders, a collider per bone on the joint nodes
# (docs/bone_colliders.md). On the three rigged characters (tests/data/rigged, glb and fbx) and on
# a --rig skin of the fox, each written file
#  - passes the Khronos glTF validator with 0 errors (npm gltf-validator);
#  - reads back through @gltf-transform/core (read_bone_colliders.mjs): one collider node per
#    collider of --bone-colliders-json, a child of its joint node with its shape and placement;
#    every joint dominating twice the minimum share of the area (from the file's own weights) has
#    one and none that dominates nothing does; in the rest pose skinned there, every vertex lies in
#    its heaviest joint's collider (conservative);
#  - a glTF input reads back through the project's reader (collider_check bones) with the input's
#    skin and the colliders on their joints' nodes.
# The snake with its armature moved, turned and scaled above the root joint (rest matrices no longer
# inverse(IBM)) still has its rest pose held.
# A VRM 1.0 made here from the humanoid (VRMC_vrm with a humanoid, one spring) gets
# VRMC_springBone colliders that @pixiv/three-vrm (npm, in Node) loads on the joint nodes, in both
# modes, its spring kept. --skip-bones leaves a joint out; an input without a skin (and no --rig), an
# unknown bone name and the bone options without an output are usage errors. The npm packages are
# installed under the build folder on first use; without npm the test fails, saying so.
# usage: bone_colliders.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"
driver="$(dirname "$tool")/collider_check"

npm_packages bone_colliders gltf-validator@2.0.0-dev.3.10 @gltf-transform/core@4.5.1 three@0.169.0 @pixiv/three-vrm@3.5.5
[ -x "$driver" ] || { echo "bone_colliders: $driver is missing (built with the tests)"; exit 1; }
min_share=0.005   # passed to the tool, so the read-back knows the rule

bones() {  # bones NAME INPUT [options...]: NAME.glb, NAME.json and NAME.report.json
  local name=$1 input=$2
  shift 2
  "$tool" "$input" -o "$tmp/$name.ma" --bone-colliders "$tmp/$name.glb" --bone-colliders-json "$tmp/$name.json" \
    --bone-min-share "$min_share" --json "$@" > "$tmp/$name.report.json"
}
read_back() {  # read_back NAME MODE [SKIPPED]
  node "$here/read_bone_colliders.mjs" "$modules" "$tmp/$1.glb" "$tmp/$1.json" "$2" "${3:-}" "$min_share" 2> /dev/null
}

files=()
for c in humanoid quadruped snake; do
  for e in glb fbx; do
    bones "${c}_$e" "$data/rigged/$c.$e"
    check "--bone-colliders on $c.$e exits 0" test $? -eq 0
    check "... from the input's skin" py "j['bone_colliders']['skin'] == 'input' and j['outputs']['bone_colliders'].endswith('.glb')" \
      "$tmp/${c}_$e.report.json"
    check "gltf-transform reads $c.$e's colliders back on their joints, one per dominating bone, holding the rest pose" \
      read_back "${c}_$e" conservative
    files+=("$tmp/${c}_$e.glb")
  done
  check "the $c glb is written back (the input's document)" py "j['input_rewritten']" "$tmp/${c}_glb.json"
  check "the project's reader reads the $c back with the input's skin and the colliders on its joints" \
    "$driver" bones "$tmp/${c}_glb.glb" "$tmp/${c}_glb.json" "$data/rigged/$c.glb"
  check "the $c glb and fbx give a collider to the same joints" \
    python3 -c "import json,sys; a,b=(json.load(open(f)) for f in sys.argv[1:]); sys.exit(sorted(c['joint_name'] for c in a['colliders']) != sorted(c['joint_name'] for c in b['colliders']))" \
    "$tmp/${c}_glb.json" "$tmp/${c}_fbx.json"
done
bones humanoid_inscribed "$data/rigged/humanoid.glb" --bone-mode inscribed
check "--bone-mode inscribed exits 0" test $? -eq 0
check "gltf-transform reads the inscribed colliders back" read_back humanoid_inscribed inscribed
files+=("$tmp/humanoid_inscribed.glb")

# the snake's armature moved, turned and scaled (1.5) above its root joint: every joint's rest
# matrix now differs from its inverse bind, the mesh's vertices and IBMs unchanged; the colliders
# must still hold the rest pose as skinning places it
python3 - "$data/rigged/snake.glb" "$tmp/snake_moved_in.glb" <<'EOF'
import json, struct, sys
src, out = sys.argv[1], sys.argv[2]
b = open(src, 'rb').read()
n = struct.unpack('<I', b[12:16])[0]
doc = json.loads(b[20:20 + n])
joints = set(doc['skins'][0]['joints'])
parent = {c: i for i, node in enumerate(doc['nodes']) for c in node.get('children', [])}
root = next(j for j in joints if parent.get(j) not in joints)
doc['nodes'][parent[root]].update({'rotation': [0.2, 0.3, -0.1, 0.9273618495495703], 'translation': [0.5, 0.2, -0.3],
                                   'scale': [1.5, 1.5, 1.5]})
text = json.dumps(doc).encode()
text += b' ' * (-len(text) % 4)
body = struct.pack('<II', len(text), 0x4E4F534A) + text + b[20 + n:]
open(out, 'wb').write(struct.pack('<III', 0x46546C67, 2, 12 + len(body)) + body)
EOF
bones snake_moved "$tmp/snake_moved_in.glb"
check "--bone-colliders on the snake with its armature moved exits 0" test $? -eq 0
check "... and its colliders follow the skinned rest pose" read_back snake_moved conservative
files+=("$tmp/snake_moved.glb")

# a skin of the skeleton's rig, for an input without one
bones fox_rig "$data/fox.obj" --rig "$tmp/fox_rig_skin.glb"
check "--bone-colliders with --rig on an unskinned input exits 0" test $? -eq 0
check "... on the rig's skin" py "j['bone_colliders']['skin'] == 'rig'" "$tmp/fox_rig.report.json"
check "gltf-transform reads the rig's colliders back" read_back fox_rig conservative
files+=("$tmp/fox_rig.glb")

# --skip-bones: the snake's second segment gets none
skip=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['colliders'][1]['joint_name'])" "$tmp/snake_glb.json")
bones snake_skip "$data/rigged/snake.glb" --skip-bones "$skip"
check "--skip-bones exits 0" test $? -eq 0
check "... and the skipped joint has no collider" read_back snake_skip conservative "$skip"
check "... one collider fewer" python3 -c "import json,sys; a,b=(json.load(open(f)) for f in sys.argv[1:]); sys.exit(len(a['colliders']) != len(b['colliders']) + 1)" \
  "$tmp/snake_glb.json" "$tmp/snake_skip.json"

check "the written files pass the glTF validator with 0 errors" validate_gltf "${files[@]}"

# VRM: the humanoid with a minimal VRMC_vrm (hands added, as VRM requires them) and one spring
python3 - "$data/rigged/humanoid.glb" "$tmp/humanoid_vrm.glb" <<'EOF'
import json, struct, sys
src, out = sys.argv[1], sys.argv[2]
b = open(src, 'rb').read()
n = struct.unpack('<I', b[12:16])[0]
doc = json.loads(b[20:20 + n])
rest = b[20 + n:]
nodes = doc['nodes']
index = {node.get('name'): i for i, node in enumerate(nodes)}
for side in 'LR':
    nodes.append({'name': 'hand.' + side, 'translation': [0, 0.25, 0]})
    nodes[index['forearm.' + side]].setdefault('children', []).append(len(nodes) - 1)
    index['hand.' + side] = len(nodes) - 1
bones = {'hips': 'hips', 'spine': 'spine', 'chest': 'chest', 'neck': 'neck', 'head': 'head',
         'leftUpperArm': 'upper_arm.L', 'leftLowerArm': 'forearm.L', 'leftHand': 'hand.L',
         'rightUpperArm': 'upper_arm.R', 'rightLowerArm': 'forearm.R', 'rightHand': 'hand.R',
         'leftUpperLeg': 'thigh.L', 'leftLowerLeg': 'shin.L', 'leftFoot': 'foot.L',
         'rightUpperLeg': 'thigh.R', 'rightLowerLeg': 'shin.R', 'rightFoot': 'foot.R'}
doc.setdefault('extensions', {})['VRMC_vrm'] = {
    'specVersion': '1.0',
    'meta': {'name': 'humanoid test', 'version': '1', 'authors': ['coverage-axis tests'],
             'licenseUrl': 'https://vrm.dev/licenses/1.0/', 'avatarPermission': 'onlyAuthor',
             'commercialUsage': 'personalNonProfit', 'creditNotation': 'required', 'allowRedistribution': False,
             'modification': 'prohibited'},
    'humanoid': {'humanBones': {k: {'node': index[v]} for k, v in bones.items()}}}
doc['extensions']['VRMC_springBone'] = {'specVersion': '1.0', 'springs': [
    {'name': 'neck', 'joints': [{'node': index['neck'], 'hitRadius': 0.01}, {'node': index['head'], 'hitRadius': 0.01}]}]}
doc.setdefault('extensionsUsed', []).extend(['VRMC_vrm', 'VRMC_springBone'])
text = json.dumps(doc).encode()
text += b' ' * (-len(text) % 4)
body = struct.pack('<II', len(text), 0x4E4F534A) + text + rest
open(out, 'wb').write(struct.pack('<III', 0x46546C67, 2, 12 + len(body)) + body)
EOF
check "the test VRM is made" test -s "$tmp/humanoid_vrm.glb"
springs=$(node "$here/read_vrm_colliders.mjs" "$modules" "$tmp/humanoid_vrm.glb" - 2> /dev/null)
check "three-vrm loads the test VRM with its spring" test "${springs:-0}" -gt 0
for mode in conservative inscribed; do
  bones "vrm_$mode" "$tmp/humanoid_vrm.glb" --bone-mode "$mode"
  check "--bone-colliders on the VRM ($mode) exits 0" test $? -eq 0
  check "... and adds spring-bone colliders" py "j['vrm_spring_bone']" "$tmp/vrm_$mode.json"
  check "three-vrm reads the $mode spring-bone colliders back on their joints, the spring kept" \
    node "$here/read_vrm_colliders.mjs" "$modules" "$tmp/vrm_$mode.glb" "$tmp/vrm_$mode.json" "$mode" "$springs"
  check "gltf-transform reads the VRM's physics colliders back" read_back "vrm_$mode" "$mode"
done
check "the VRMs pass the glTF validator with 0 errors" \
  validate_gltf "$tmp/vrm_conservative.glb" "$tmp/vrm_inscribed.glb"

# failures
"$tool" "$data/fox.obj" -o "$tmp/e.ma" --bone-colliders "$tmp/e.glb" --json > "$tmp/e1.json"
check "--bone-colliders on an unskinned input without --rig is a usage error (exit 2)" test $? -eq 2
check "... naming --rig" py "'--rig' in j['error']['message']" "$tmp/e1.json"
"$tool" "$data/rigged/snake.glb" -o "$tmp/e.ma" --bone-colliders "$tmp/e.glb" --skip-bones no_such_bone --json > "$tmp/e2.json"
check "--skip-bones with an unknown name is a usage error (exit 2)" test $? -eq 2
check "... naming it" py "'no_such_bone' in j['error']['message']" "$tmp/e2.json"
"$tool" "$data/rigged/snake.glb" -o "$tmp/e.ma" --bone-mode inscribed --json > "$tmp/e3.json"
check "--bone-mode without --bone-colliders is a usage error (exit 2)" test $? -eq 2
"$tool" "$data/rigged/snake.glb" -o "$tmp/e.ma" --bone-colliders "$tmp/e.obj" --json > "$tmp/e4.json"
check "--bone-colliders to a path that is not .glb or .gltf is a file error (exit 3)" test $? -eq 3
finish bone_colliders
