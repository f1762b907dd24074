// read_vrm_colliders.mjs: loads a VRM 1.0 written by --bone-colliders with three.js's GLTFLoader and
// @pixiv/three-vrm's VRMLoaderPlugin (npm, in Node) and checks its spring-bone colliders against
// the tool's --bone-colliders-json: one VRMSpringBoneCollider per collider, attached to the
// collider's joint node, a sphere {offset = the placement's centre, radius} or a capsule {offset =
// the bottom ball's centre, tail = the top ball's centre, radius = the larger of the two radii
// (MODE conservative) or the smaller (inscribed)}, to 1e-6 of the largest radius; the humanoid
// loads; the input's springs are kept (SPRING_JOINTS joints in the spring-bone manager).
// usage: node read_vrm_colliders.mjs NODE_MODULES FILE.vrm BONES.json MODE SPRING_JOINTS
//        node read_vrm_colliders.mjs NODE_MODULES FILE.vrm -     (prints the spring joints' count)
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [modules, file, bonesJson, mode, springJoints] = process.argv.slice(2);
const load = (p) => import(pathToFileURL(path.join(modules, p)).href);
const { GLTFLoader } = await load('three/examples/jsm/loaders/GLTFLoader.js');
const { VRMLoaderPlugin, VRMSpringBoneCollider } = await load('@pixiv/three-vrm/lib/three-vrm.module.js');

const bytes = fs.readFileSync(file);
const loader = new GLTFLoader();
loader.register((parser) => new VRMLoaderPlugin(parser));
const gltf = await new Promise((resolve, reject) =>
  loader.parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), '', resolve, reject));
const vrm = gltf.userData.vrm;
const failures = [];
const fail = (what) => failures.push(what);
if (!vrm) fail('three-vrm found no VRM');
if (!vrm?.humanoid) fail('no humanoid');

// BONES.json "-": only print the spring joints' count (of the input, before the tool wrote it)
if (bonesJson === '-') {
  console.log(vrm?.springBoneManager ? vrm.springBoneManager.joints.size : 0);
  process.exit(vrm ? 0 : 1);
}
const read = [];
gltf.scene.traverse((o) => {
  if (o instanceof VRMSpringBoneCollider) read.push({ o, node: gltf.parser.associations.get(o.parent)?.nodes });
});
const bones = JSON.parse(fs.readFileSync(bonesJson, 'utf8'));
if (read.length !== bones.colliders.length) fail(`${read.length} spring-bone colliders, ${bones.colliders.length} bone colliders`);
const rotate = (q, v) => {
  const [x, y, z, w] = q;
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + y * t[2] - z * t[1], v[1] + w * t[1] + z * t[0] - x * t[2], v[2] + w * t[2] + x * t[1] - y * t[0]];
};
const used = new Set();
const counts = {};
bones.colliders.forEach((c, i) => {
  const scale = Math.max(c.radius_top, c.radius_bottom, 1e-12), near = (a, b) => Math.abs(a - b) <= 1e-6 * scale;
  const nearV = (a, b) => a.every((v, k) => near(v, b[k]));
  let want;
  if (c.kind === 'sphere') {
    want = { type: 'sphere', offset: c.translation, radius: c.radius_top };
  } else {
    const bottom = rotate(c.rotation, [0, -c.height / 2, 0]).map((v, k) => v + c.translation[k]);
    const top = rotate(c.rotation, [0, c.height / 2, 0]).map((v, k) => v + c.translation[k]);
    const radius = mode === 'conservative' ? Math.max(c.radius_top, c.radius_bottom) : Math.min(c.radius_top, c.radius_bottom);
    want = { type: 'capsule', offset: bottom, tail: top, radius };
  }
  const k = read.findIndex((r, j) => !used.has(j) && r.node === c.joint_node && r.o.shape.type === want.type &&
    near(r.o.shape.radius, want.radius) && nearV(r.o.shape.offset.toArray(), want.offset) &&
    (want.type === 'sphere' || nearV(r.o.shape.tail.toArray(), want.tail)));
  if (k < 0) return fail(`collider ${i} (joint ${c.joint_name}, ${want.type}): no spring-bone collider on node ${c.joint_node} matches`);
  used.add(k);
  counts[want.type] = (counts[want.type] || 0) + 1;
});
const joints = vrm?.springBoneManager ? vrm.springBoneManager.joints.size : 0;
if (String(joints) !== springJoints) fail(`${joints} spring joints, the input has ${springJoints}`);
console.log(`three-vrm: ${path.basename(file)}: ${read.length} spring-bone colliders read back (${JSON.stringify(counts)}), ` +
  `${joints} spring joints kept`);
for (const f of failures.slice(0, 20)) console.log(`  FAILED ${f}`);
process.exit(failures.length ? 1 : 0);
