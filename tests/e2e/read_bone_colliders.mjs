// read_bone_colliders.mjs: reads a --bone-colliders file back with @gltf-transform/core (npm),
// which knows no physics (the two small Extension classes of physics_extensions.mjs read
// KHR_implicit_shapes and KHR_physics_rigid_bodies), and checks it against the tool's
// --bone-colliders-json and against the skin the file itself carries:
//  - one collider node per collider of the JSON, in the file's node `node`, whose parent is the
//    skin's joint `joint` (by index in the skin and by name), kinematic, of the JSON's shape with
//    its parameters and its local placement, to 1e-6 of the mesh's diagonal;
//  - the joints with a collider against the file's own skin (JOINTS_n/WEIGHTS_n read here): every
//    joint dominating at least twice MIN_SHARE of the area has one, none that dominates nothing or
//    is in SKIPPED (comma-separated names; "" for none) has one;
//  - the rest pose, skinned here (each vertex by its weights, joint world matrices from
//    gltf-transform and the inverse bind matrices): with MODE conservative, every vertex lies in
//    the collider of its heaviest joint placed by gltf-transform's world matrices (to 1e-6 of the
//    diagonal); the share held is printed for either mode.
// usage: node read_bone_colliders.mjs NODE_MODULES FILE.glb BONES.json MODE SKIPPED MIN_SHARE
import fs from 'node:fs';
import path from 'node:path';
import { readPhysics } from './physics_extensions.mjs';

const [modules, file, bonesJson, mode, skippedList, minShareArg] = process.argv.slice(2);
const { root, shapes, bodies, failures } = await readPhysics(modules, file);
const fail = (what) => failures.push(what);
const bones = JSON.parse(fs.readFileSync(bonesJson, 'utf8'));
const nodes = root.listNodes();
const skins = root.listSkins();
if (skins.length < 1) fail('no skin');
const skin = skins[0];
const joints = skin.listJoints();

// 4x4 column-major helpers
const mul = (a, b) => {
  const o = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c) for (let r = 0; r < 4; ++r) for (let k = 0; k < 4; ++k) o[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return o;
};
const apply = (m, v) => [0, 1, 2].map((r) => m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r]);
const invert = (m) => {   // general 4x4 inverse (Gauss-Jordan)
  const a = [...Array(4)].map((_, r) => [...Array(8)].map((_, c) => (c < 4 ? m[4 * c + r] : (c - 4 === r ? 1 : 0))));
  for (let c = 0; c < 4; ++c) {
    let p = c;
    for (let r = c + 1; r < 4; ++r) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    [a[c], a[p]] = [a[p], a[c]];
    const d = a[c][c];
    for (let k = 0; k < 8; ++k) a[c][k] /= d;
    for (let r = 0; r < 4; ++r) if (r !== c) { const f = a[r][c]; for (let k = 0; k < 8; ++k) a[r][k] -= f * a[c][k]; }
  }
  const o = new Array(16);
  for (let r = 0; r < 4; ++r) for (let c = 0; c < 4; ++c) o[4 * c + r] = a[r][4 + c];
  return o;
};
const rotate = (q, v) => {
  const [x, y, z, w] = q;
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + y * t[2] - z * t[1], v[1] + w * t[1] + z * t[0] - x * t[2], v[2] + w * t[2] + x * t[1] - y * t[0]];
};

// the skinned primitive's positions, joints and weights
let prim = null;
for (const n of nodes) if (n.getSkin() === skin && n.getMesh()) prim = n.getMesh().listPrimitives()[0];
if (!prim) fail('no skinned mesh');
const positions = [], heaviest = [], vertexJoints = [], vertexWeights = [];
const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
if (prim) {
  const P = prim.getAttribute('POSITION');
  const sets = [];
  for (let s = 0; prim.getAttribute(`JOINTS_${s}`); ++s) sets.push([prim.getAttribute(`JOINTS_${s}`), prim.getAttribute(`WEIGHTS_${s}`)]);
  for (let i = 0; i < P.getCount(); ++i) {
    const p = P.getElement(i, []);
    positions.push(p);
    p.forEach((v, k) => { lo[k] = Math.min(lo[k], v); hi[k] = Math.max(hi[k], v); });
    const js = [], ws = [];
    for (const [J, W] of sets) { js.push(...J.getElement(i, [])); ws.push(...W.getElement(i, [])); }
    let best = -1, bw = 0;
    ws.forEach((w, k) => { if (w > bw) { bw = w; best = js[k]; } });
    heaviest.push(best);
    vertexJoints.push(js);
    vertexWeights.push(ws);
  }
}
const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
const tolerance = 1e-6 * diagonal;

// the joints with a collider, from the file's own skin: each joint's share of the surface's area
// where its interpolated weight is the heaviest (200 000 area-uniform samples drawn here). A joint
// with twice MIN_SHARE has one, a joint that dominates no sample (nor vertex) or is skipped has
// none; between the two the library's exact areas and its minimum size decide.
const skipped = new Set((skippedList || '').split(',').filter((s) => s));
const share = new Array(joints.length).fill(0);
if (prim) {
  const I = prim.getIndices();
  const tri = [];
  for (let t = 0; I && t < I.getCount(); t += 3) tri.push([I.getScalar(t), I.getScalar(t + 1), I.getScalar(t + 2)]);
  const area = tri.map(([a, b, c]) => {
    const u = positions[b].map((v, k) => v - positions[a][k]), w = positions[c].map((v, k) => v - positions[a][k]);
    return 0.5 * Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]);
  });
  const cumulative = [];
  area.reduce((s, a, i) => (cumulative[i] = s + a), 0);
  const total = cumulative[cumulative.length - 1];
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const samples = 200000;
  for (let n = 0; n < samples; ++n) {
    const x = random() * total;
    let lo = 0, hi = cumulative.length - 1;
    while (lo < hi) { const m = (lo + hi) >> 1; if (cumulative[m] < x) lo = m + 1; else hi = m; }
    let a = random(), b = random();
    if (a + b > 1) { a = 1 - a; b = 1 - b; }
    const corner = [1 - a - b, a, b], w = new Map();
    tri[lo].forEach((v, c) => vertexWeights[v].forEach((x, k) => { if (x > 0) w.set(vertexJoints[v][k], (w.get(vertexJoints[v][k]) || 0) + corner[c] * x); }));
    let best = -1, bw = 0;
    for (const [j, x] of w) if (x > bw) { bw = x; best = j; }
    if (best >= 0) share[best] += 1 / samples;
  }
}
const minShare = Number(minShareArg);
const got = new Set(bones.colliders.map((c) => c.joint));
let must = 0;
if (got.size !== bones.colliders.length) fail('a joint has more than one collider');
joints.forEach((joint, j) => {
  const name = joint.getName(), dominant = share[j] > 0 || heaviest.includes(j);
  if (skipped.has(name) && got.has(j)) fail(`joint ${j} (${name}) is skipped but has a collider`);
  if (!dominant && got.has(j)) fail(`joint ${j} (${name}) has a collider but dominates no part of the surface`);
  if (!skipped.has(name) && share[j] >= 2 * minShare) {
    ++must;
    if (!got.has(j)) fail(`joint ${j} (${name}) dominates ${(100 * share[j]).toFixed(2)} % of the area but has no collider`);
  }
});
const expected = { size: must };

// each collider node: parent, shape, local placement
const colliderOf = new Map();   // joint -> {node, c}
const counts = {};
bones.colliders.forEach((c, i) => {
  const bad = (what) => fail(`collider ${i} (joint ${c.joint_name}): ${what}`);
  const node = nodes[c.node], joint = joints[c.joint];
  if (!node || !joint) return bad('its node or joint is missing');
  if (joint.getName() !== c.joint_name) bad(`the skin's joint ${c.joint} is ${joint.getName()}`);
  if (node.getParentNode() !== joint) return bad('its node is not a child of its joint node');
  if (nodes.indexOf(joint) !== c.joint_node) bad('joint_node differs from the skin\'s joint');
  const body = bodies.get(node);
  if (!body) return bad('its node has no KHR_physics_rigid_bodies');
  if (body.motion?.isKinematic !== true) bad('not kinematic');
  const shape = shapes[body.collider?.geometry?.shape];
  if (!shape || shape.type !== c.kind) return bad(`shape ${shape?.type} is not a ${c.kind}`);
  counts[shape.type] = (counts[shape.type] || 0) + 1;
  const near = (a, b) => Math.abs(a - b) <= tolerance;
  if (c.kind === 'sphere' && !near(shape.sphere.radius, c.radius_top)) bad('radius differs');
  if (c.kind === 'capsule' && !(near(shape.capsule.radiusTop, c.radius_top) && near(shape.capsule.radiusBottom, c.radius_bottom) &&
                                near(shape.capsule.height, c.height))) bad('capsule parameters differ');
  const t = node.getTranslation(), q = node.getRotation();
  if (t.some((v, k) => !near(v, c.translation[k]))) bad('local translation differs');
  const axis = rotate(q, [0, 1, 0]), want = rotate(c.rotation, [0, 1, 0]);
  if (axis.some((v, k) => Math.abs(v - want[k]) > 1e-6)) bad('local axis differs');
  colliderOf.set(c.joint, { node, c });
});

// the rest pose skinned here; each vertex in its heaviest joint's collider
const ibm = skin.getInverseBindMatrices();
const jointMatrix = joints.map((j, k) => mul(j.getWorldMatrix(), ibm ? ibm.getElement(k, []) : [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]));
let held = 0, total = 0, worst = 0;
positions.forEach((p, i) => {
  const entry = colliderOf.get(heaviest[i]);
  if (!entry) return;
  const x = [0, 0, 0];
  vertexWeights[i].forEach((w, k) => { if (w > 0) apply(jointMatrix[vertexJoints[i][k]], p).forEach((v, d) => (x[d] += w * v)); });
  const local = apply(invert(entry.node.getWorldMatrix()), x);
  const c = entry.c;
  let d;
  if (c.kind === 'sphere') d = Math.hypot(...local) - c.radius_top;
  else {
    // the capsule is the union of the balls interpolated between its two (radius_bottom at
    // y = -height/2, radius_top at +height/2), so min over t of |x - c(t)| - r(t) <= 0 exactly
    // inside; that function of t is convex: a golden-section search finds its minimum
    const f = (t) => Math.hypot(local[0], local[1] - (t - 0.5) * c.height, local[2]) - ((1 - t) * c.radius_bottom + t * c.radius_top);
    let a = 0, b = 1;
    const g = (Math.sqrt(5) - 1) / 2;
    for (let k = 0; k < 80; ++k) {
      const m1 = b - g * (b - a), m2 = a + g * (b - a);
      if (f(m1) <= f(m2)) b = m2; else a = m1;
    }
    d = Math.min(f(0), f(1), f((a + b) / 2));
  }
  worst = Math.max(worst, d);
  ++total;
  if (d <= tolerance) ++held;
});
const heldShare = total ? held / total : 0;
if (mode === 'conservative' && held !== total) fail(`${total - held} of ${total} vertices outside their joint's collider (worst ${worst / diagonal} of the diagonal)`);
console.log(`gltf-transform: ${path.basename(file)}: ${bones.colliders.length} colliders read back (${JSON.stringify(counts)}) ` +
  `on ${joints.length} joints, ${expected.size} that dominate twice the minimum share; rest pose: ${(100 * heldShare).toFixed(3)} % of ${total} vertices ` +
  `in their joint's collider`);
for (const f of failures.slice(0, 20)) console.log(`  FAILED ${f}`);
process.exit(failures.length ? 1 : 0);
