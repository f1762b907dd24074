#!/usr/bin/env bash
# colliders.sh: end-to-end tests of --colliders, the proxies as glTF physics (docs/proxies.md):
# conservative proxies of a sphere, a tapered capsule (meshes made here), the fox and a desk
# (capsules), a rotated box (--proxies all), and the same box written from a given box primitive
# (collider_check write), each
#  - passes the Khronos glTF validator with 0 errors (npm gltf-validator);
#  - reads back through @gltf-transform/core with small extension classes (read_colliders.mjs):
#    one collider per proxy of --proxies-json, its type, parameters and world placement;
#  - loads into Jolt Physics from the .glb alone (npm jolt-physics; jolt_colliders.mjs): its ray hits
#    lie on the library's proxies within 1e-4 of the diagonal (collider_check: the library's exact
#    hits and distances) and the surface tests inside its shapes.
# The skeleton's glTF and the rig with proxies pass the validator too; --colliders without
# --proxies and a bad path fail clearly. The npm packages are installed under the build folder on
# first use; without npm the test fails, saying so.
# usage: colliders.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"
driver="$(dirname "$tool")/collider_check"

npm_packages colliders gltf-validator@2.0.0-dev.3.10 @gltf-transform/core@4.5.1 jolt-physics@1.1.0
[ -x "$driver" ] || { echo "colliders: $driver is missing (built with the tests)"; exit 1; }

# a sphere (radius 5) and a tapered capsule (balls of radius 4 at y = 0 and 2 at y = 10) as closed
# surfaces of revolution whose vertices lie on the shape; a box 4 x 1 x 2 turned about (1, 2, 3)
# with its primitive 1 % larger
python3 - "$tmp" <<'EOF'
import json, math, sys
out = sys.argv[1]

def write_obj(path, vertices, faces, inside):
    with open(path, "w") as f:
        for v in vertices:
            f.write("v %.17g %.17g %.17g\n" % tuple(v))
        for a, b, c in faces:
            u = [vertices[b][k] - vertices[a][k] for k in range(3)]
            w = [vertices[c][k] - vertices[a][k] for k in range(3)]
            n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            g = [(vertices[a][k] + vertices[b][k] + vertices[c][k]) / 3 - inside[k] for k in range(3)]
            if sum(n[k] * g[k] for k in range(3)) < 0:
                b, c = c, b   # outward, as seen from a point inside the convex shape
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))

def revolved(path, y1, r1, y2, r2, rings=48, segments=48):
    # the hull of the balls: the point of the ball that reaches farthest along each normal
    profile = []
    for j in range(1, rings):
        t = -math.pi / 2 + math.pi * j / rings
        n = (math.cos(t), math.sin(t))
        y, r = (y1, r1) if y1 * n[1] + r1 >= y2 * n[1] + r2 else (y2, r2)
        profile.append((r * n[0], y + r * n[1]))
    vertices = [[0.0, min(y1 - r1, y2 - r2), 0.0]]
    for rho, y in profile:
        for s in range(segments):
            p = 2 * math.pi * s / segments
            vertices.append([rho * math.cos(p), y, rho * math.sin(p)])
    vertices.append([0.0, max(y1 + r1, y2 + r2), 0.0])
    top, faces = len(vertices) - 1, []
    ring = lambda j, s: 1 + j * segments + s % segments
    for s in range(segments):
        faces.append((0, ring(0, s), ring(0, s + 1)))
        faces.append((top, ring(len(profile) - 1, s), ring(len(profile) - 1, s + 1)))
        for j in range(len(profile) - 1):
            faces.append((ring(j, s), ring(j + 1, s), ring(j + 1, s + 1)))
            faces.append((ring(j, s), ring(j + 1, s + 1), ring(j, s + 1)))
    write_obj(path, vertices, faces, [0.0, (y1 + y2) / 2, 0.0])

revolved(out + "/sphere.obj", 0, 5, 0, 5)
revolved(out + "/tapered.obj", 0, 4, 10, 2)

axis = [1 / math.sqrt(14), 2 / math.sqrt(14), 3 / math.sqrt(14)]
angle = 0.9
q = [axis[0] * math.sin(angle / 2), axis[1] * math.sin(angle / 2), axis[2] * math.sin(angle / 2), math.cos(angle / 2)]
def rotate(v):
    x, y, z, w = q
    t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])]
    return [v[0] + w * t[0] + y * t[2] - z * t[1], v[1] + w * t[1] + z * t[0] - x * t[2], v[2] + w * t[2] + x * t[1] - y * t[0]]
centre, half = [3.0, -1.0, 2.0], [2.0, 0.5, 1.0]
corners = [[(1 if c & 1 else -1) * half[0], (1 if c & 2 else -1) * half[1], (1 if c & 4 else -1) * half[2]] for c in range(8)]
vertices = [[rotate(v)[k] + centre[k] for k in range(3)] for v in corners]
quads = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5)]
faces = [f for a, b, c, d in quads for f in ((a, b, c), (a, c, d))]
write_obj(out + "/box.obj", vertices, faces, centre)
json.dump({"proxies": [{"kind": "box", "center": centre, "rotation": q, "half_extents": [1.01 * h for h in half]}]},
          open(out + "/box.json", "w"))
EOF
check "the test meshes are written" test -s "$tmp/tapered.obj" -a -s "$tmp/box.json"

colliders() {  # colliders NAME MESH [SHAPES]: conservative proxies (capsules) as NAME.glb and NAME.json
  "$tool" "$2" -o "$tmp/$1.ma" --proxies "${3:-capsules}" --proxy-mode conservative --colliders "$tmp/$1.glb" \
    --proxies-json "$tmp/$1.json" --json > "$tmp/$1.report.json"
}
for m in sphere tapered; do
  colliders "$m" "$tmp/$m.obj"
  check "--colliders on the $m exits 0" test $? -eq 0
done
colliders fox "$data/fox.obj"
check "--colliders on the fox exits 0" test $? -eq 0
check "the report names the colliders file" py "j['outputs']['colliders'].endswith('fox.glb')" "$tmp/fox.report.json"
colliders desk "$data/desk_table.obj"
check "--colliders on the desk exits 0" test $? -eq 0
colliders boxes "$tmp/box.obj" all
check "--colliders with --proxies all on the rotated box exits 0" test $? -eq 0
check "... and holds a box" py "any(p['kind'] == 'box' for p in j['proxies'])" "$tmp/boxes.json"
"$driver" write "$tmp/box.glb" "$tmp/box.obj" "$tmp/box.json"
check "a colliders file from a given rotated box is written" test $? -eq 0
check "the tapered capsule's proxies hold a tapered capsule" \
  py "any(p['kind'] == 'capsule' and abs(p['radius_a'] - p['radius_b']) > 0.5 for p in j['proxies'])" "$tmp/tapered.json"

files=()
for m in sphere tapered box boxes fox desk; do files+=("$tmp/$m.glb"); done
check "the colliders files pass the glTF validator with 0 errors" \
  validate_gltf "${files[@]}"
for m in sphere tapered box boxes fox desk; do
  check "gltf-transform reads the $m's colliders back as its proxies" \
    node "$here/read_colliders.mjs" "$modules" "$tmp/$m.glb" "$tmp/$m.json"
  check "Jolt loads the $m's colliders: rays agree with the library, the surface is inside" \
    node "$here/jolt_colliders.mjs" "$modules" "$driver" "$tmp/$m.glb" "$tmp/$m.json" conservative
done

# the same writer in the skeleton's glTF and the rig
"$tool" "$data/fox.obj" -o "$tmp/fr.ma" --proxies capsules --gltf "$tmp/skeleton.glb" --rig "$tmp/rig.glb" --quiet
check "--gltf and --rig with --proxies exit 0" test $? -eq 0
check "the skeleton's glTF and the rig with colliders pass the validator with 0 errors" \
  validate_gltf "$tmp/skeleton.glb" "$tmp/rig.glb"
check "the rig carries the proxies as colliders" grep -q KHR_physics_rigid_bodies "$tmp/rig.glb"

# failures
"$tool" "$data/fox.obj" -o "$tmp/e.ma" --colliders "$tmp/e.glb" --json > "$tmp/e1.json"
check "--colliders without --proxies is a usage error (exit 2)" test $? -eq 2
check "... naming --proxies" py "'--proxies' in j['error']['message']" "$tmp/e1.json"
"$tool" "$data/fox.obj" -o "$tmp/e.ma" --proxies spheres --colliders "$tmp/e.obj" --json > "$tmp/e2.json"
check "--colliders to a path that is not .glb or .gltf is a file error (exit 3)" test $? -eq 3
finish colliders
