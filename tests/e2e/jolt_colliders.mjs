// jolt_colliders.mjs: loads a colliders file into Jolt Physics (npm jolt-physics, WebAssembly) from
// the glTF alone and checks that the engine means what the library meant:
//  - every node with KHR_physics_rigid_bodies' collider becomes a static body at the node's world
//    placement, its KHR_implicit_shapes shape built as Jolt's SphereShape, CapsuleShape,
//    TaperedCapsuleShape (Jolt's is the hull of two balls, the radiusTop one at +halfHeight on Y, as
//    glTF's) or BoxShape (no convex radius, so its corners stay sharp);
//  - rays from outside the mesh's bounding box, most aimed at points of the mesh, the rest in random
//    directions: Jolt and the library (collider_check, on the tool's --proxies-json) hit or miss
//    together, and for every hit the library's own signed distance to its proxies at Jolt's hit
//    point is within 1e-4 of the mesh's bounding-box diagonal of 0. The distance along the ray to
//    the library's exact first hit is reported too; it is that residual over the cosine of the
//    ray's incidence, so a ray grazing the surface stretches it (the check there is on the
//    difference times the cosine, within the same 1e-4);
//  - with `conservative`: every one of this script's own samples of the mesh's surface (read from
//    the file) tests inside the engine's shapes (Jolt's point collision).
// usage: node jolt_colliders.mjs NODE_MODULES COLLIDER_CHECK FILE.glb PROXIES.json [conservative]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [modules, driver, file, proxiesJson, mode] = process.argv.slice(2);
const initJolt = (await import(pathToFileURL(path.join(modules, 'jolt-physics/dist/jolt-physics.wasm-compat.js')).href)).default;
const Jolt = await initJolt();

// ---- the .glb: its JSON and binary chunks ----
const bytes = fs.readFileSync(file);
const jsonLength = bytes.readUInt32LE(12);
const doc = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
const binStart = 20 + jsonLength + 8;
const bin = bytes.subarray(binStart, binStart + bytes.readUInt32LE(20 + jsonLength));

// ---- node world transforms (column-major 4x4), from the default scene's roots ----
function local(node) {
  if (node.matrix) return node.matrix.slice();
  const [x, y, z, w] = node.rotation || [0, 0, 0, 1];
  const [sx, sy, sz] = node.scale || [1, 1, 1];
  const t = node.translation || [0, 0, 0];
  return [
    (1 - 2 * (y * y + z * z)) * sx, 2 * (x * y + z * w) * sx, 2 * (x * z - y * w) * sx, 0,
    2 * (x * y - z * w) * sy, (1 - 2 * (x * x + z * z)) * sy, 2 * (y * z + x * w) * sy, 0,
    2 * (x * z + y * w) * sz, 2 * (y * z - x * w) * sz, (1 - 2 * (x * x + y * y)) * sz, 0,
    t[0], t[1], t[2], 1];
}
function multiply(a, b) {
  const out = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c) for (let r = 0; r < 4; ++r) for (let k = 0; k < 4; ++k) out[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return out;
}
const world = new Map();
(function walk(indices, parent) {
  for (const i of indices) {
    world.set(i, multiply(parent, local(doc.nodes[i])));
    walk(doc.nodes[i].children || [], world.get(i));
  }
})(doc.scenes[doc.scene || 0].nodes, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
const apply = (m, p) => [0, 1, 2].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);

// A rotation matrix's quaternion (x y z w); the matrix's columns must be unit (no scale).
function quaternion(m) {
  const [m00, m10, m20, , m01, m11, m21, , m02, m12, m22] = m;
  const tr = m00 + m11 + m22;
  if (tr > 0) {
    const s = Math.sqrt(tr + 1) * 2;
    return [(m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s];
  } else if (m00 > m11 && m00 > m22) {
    const s = Math.sqrt(1 + m00 - m11 - m22) * 2;
    return [0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s];
  } else if (m11 > m22) {
    const s = Math.sqrt(1 + m11 - m00 - m22) * 2;
    return [(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s];
  }
  const s = Math.sqrt(1 + m22 - m00 - m11) * 2;
  return [(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s];
}

// ---- the mesh: every node with a triangle mesh, in world coordinates ----
function accessor(index) {
  const a = doc.accessors[index], v = doc.bufferViews[a.bufferView];
  const offset = (v.byteOffset || 0) + (a.byteOffset || 0);
  const n = a.count * { SCALAR: 1, VEC3: 3 }[a.type];
  const Type = { 5126: Float32Array, 5125: Uint32Array, 5123: Uint16Array, 5121: Uint8Array }[a.componentType];
  return new Type(bin.buffer.slice(bin.byteOffset + offset, bin.byteOffset + offset + n * Type.BYTES_PER_ELEMENT));
}
const triangles = [];
for (const [i, m] of world) {
  const node = doc.nodes[i];
  if (node.mesh === undefined) continue;
  for (const prim of doc.meshes[node.mesh].primitives) {
    if ((prim.mode ?? 4) !== 4) continue;
    const p = accessor(prim.attributes.POSITION), idx = accessor(prim.indices);
    const vertex = (k) => apply(m, [p[3 * k], p[3 * k + 1], p[3 * k + 2]]);
    for (let t = 0; t < idx.length; t += 3) triangles.push([vertex(idx[t]), vertex(idx[t + 1]), vertex(idx[t + 2])]);
  }
}
const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
for (const tri of triangles) for (const v of tri) for (let k = 0; k < 3; ++k) lo[k] = Math.min(lo[k], v[k]), hi[k] = Math.max(hi[k], v[k]);
const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
const centre = [0, 1, 2].map((k) => (lo[k] + hi[k]) / 2);

// ---- a seeded generator, unit vectors and area-weighted surface samples ----
let seed = 12345;
const random = () => {
  seed = (seed + 0x6d2b79f5) | 0;
  let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const unit = (a) => { const n = norm(a); return [a[0] / n, a[1] / n, a[2] / n]; };
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
function direction() {
  for (;;) {
    const v = [2 * random() - 1, 2 * random() - 1, 2 * random() - 1];
    const n = norm(v);
    if (n > 1e-3 && n <= 1) return [v[0] / n, v[1] / n, v[2] / n];
  }
}
const cumulative = [];
let area = 0;
for (const [a, b, c] of triangles) cumulative.push((area += norm(cross(sub(b, a), sub(c, a))) / 2));
function surfacePoint() {
  const r = random() * area;
  let l = 0, h = cumulative.length - 1;
  while (l < h) { const m = (l + h) >> 1; if (cumulative[m] < r) l = m + 1; else h = m; }
  const [a, b, c] = triangles[l];
  const s = Math.sqrt(random()), t = random();
  return [0, 1, 2].map((k) => (1 - s) * a[k] + s * (1 - t) * b[k] + s * t * c[k]);
}

// ---- the engine's bodies, one per collider node ----
const settings = new Jolt.JoltSettings();
const layers = new Jolt.ObjectLayerPairFilterTable(1);
layers.EnableCollision(0, 0);
const broad = new Jolt.BroadPhaseLayerInterfaceTable(1, 1);
broad.MapObjectToBroadPhaseLayer(0, new Jolt.BroadPhaseLayer(0));
settings.mObjectLayerPairFilter = layers;
settings.mBroadPhaseLayerInterface = broad;
settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(broad, 1, layers, 1);
const system = new Jolt.JoltInterface(settings).GetPhysicsSystem();
const bodies = system.GetBodyInterface();
const shapes = doc.extensions?.KHR_implicit_shapes?.shapes || [];
const counts = { sphere: 0, capsule: 0, tapered: 0, box: 0 };
const failures = [];
for (const [i, m] of world) {
  const collider = doc.nodes[i].extensions?.KHR_physics_rigid_bodies?.collider;
  if (!collider) continue;
  const shape = shapes[collider.geometry.shape];
  let settingsOf;
  if (shape.type === 'sphere') {
    settingsOf = new Jolt.SphereShapeSettings(shape.sphere.radius);
    counts.sphere++;
  } else if (shape.type === 'capsule') {
    const c = shape.capsule;
    if (c.radiusTop === c.radiusBottom) settingsOf = new Jolt.CapsuleShapeSettings(c.height / 2, c.radiusTop);
    else settingsOf = new Jolt.TaperedCapsuleShapeSettings(c.height / 2, c.radiusTop, c.radiusBottom);
    counts[c.radiusTop === c.radiusBottom ? 'capsule' : 'tapered']++;
  } else if (shape.type === 'box') {
    const [x, y, z] = shape.box.size;
    settingsOf = new Jolt.BoxShapeSettings(new Jolt.Vec3(x / 2, y / 2, z / 2), 0);
    counts.box++;
  } else {
    failures.push(`node ${i}: unknown shape type ${shape.type}`);
    continue;
  }
  const result = settingsOf.Create();
  if (result.HasError()) {
    failures.push(`node ${i}: Jolt refused its ${shape.type}: ${result.GetError().c_str()}`);
    continue;
  }
  for (let c = 0; c < 3; ++c) {
    const s = Math.hypot(m[4 * c], m[4 * c + 1], m[4 * c + 2]);
    if (Math.abs(s - 1) > 1e-9) failures.push(`node ${i}: a collider's world transform is scaled (${s})`);
  }
  const q = quaternion(m);
  const creation = new Jolt.BodyCreationSettings(result.Get(), new Jolt.RVec3(m[12], m[13], m[14]),
    new Jolt.Quat(q[0], q[1], q[2], q[3]).Normalized(), Jolt.EMotionType_Static, 0);
  bodies.AddBody(bodies.CreateBody(creation).GetID(), Jolt.EActivation_DontActivate);
}
system.OptimizeBroadPhase();
const query = system.GetNarrowPhaseQuery();
const filters = [new Jolt.BroadPhaseLayerFilter(), new Jolt.ObjectLayerFilter(), new Jolt.BodyFilter(), new Jolt.ShapeFilter()];
const colliders = counts.sphere + counts.capsule + counts.tapered + counts.box;
const proxies = JSON.parse(fs.readFileSync(proxiesJson, 'utf8')).proxies;
if (colliders !== proxies.length) failures.push(`${colliders} colliders in the file, ${proxies.length} proxies in ${proxiesJson}`);

// ---- rays: Jolt against the library ----
const rays = [];
const length = 4 * diagonal;
for (let r = 0; r < 2000; ++r) {
  const away = direction();
  const o = centre.map((c, k) => c + diagonal * away[k]);   // outside the bounding box
  const d = r % 5 === 0 ? direction() : unit(sub(surfacePoint(), o));
  rays.push([o, d]);
}
const run = (args, lines) => {
  const r = spawnSync(driver, args, { input: lines.map((l) => l.join(' ')).join('\n') + '\n', maxBuffer: 1 << 28 });
  if (r.status !== 0) throw new Error(`collider_check ${args[0]} failed: ${r.stderr}`);
  return r.stdout.toString().trim().split('\n').map(Number);
};
const library = run(['hits', proxiesJson], rays.map(([o, d]) => [...o, ...d]));
const joltHits = rays.map(([o, d]) => {
  const ray = new Jolt.RRayCast(new Jolt.RVec3(o[0], o[1], o[2]), new Jolt.Vec3(d[0] * length, d[1] * length, d[2] * length));
  const collector = new Jolt.CastRayClosestHitCollisionCollector();
  query.CastRay(ray, new Jolt.RayCastSettings(), collector, ...filters);
  const t = collector.HadHit() ? collector.get_mHit().mFraction * length : -1;
  Jolt.destroy(ray);
  Jolt.destroy(collector);
  return t;
});
// the library's signed distance at Jolt's hit point (how far it is from the library's surface),
// and the ray's incidence at the library's hit (the distance's gradient by central differences)
const at = (r, t) => rays[r][0].map((v, k) => v + t * rays[r][1][k]);
const h = 1e-6 * diagonal, probes = [];
rays.forEach(([, d], r) => {
  probes.push(joltHits[r] >= 0 ? at(r, joltHits[r]) : at(r, 0));
  const p = at(r, Math.max(library[r], 0));
  for (let k = 0; k < 3; ++k) for (const s of [h, -h]) probes.push(p.map((v, j) => v + (j === k ? s : 0)));
});
const values = run(['distance', proxiesJson], probes);
let worst = 0, worstScaled = 0, worstResidual = 0, worstIncidence = 1, hits = 0, disagree = 0;
for (let r = 0; r < rays.length; ++r) {
  const jolt = joltHits[r], lib = library[r];
  if ((jolt < 0) !== (lib < 0)) {
    if (++disagree <= 5) failures.push(`ray ${r}: Jolt ${jolt < 0 ? 'misses' : 'hits at ' + jolt}, the library ${lib < 0 ? 'misses' : 'hits at ' + lib}`);
    continue;
  }
  if (lib < 0) continue;
  ++hits;
  const v = values.slice(7 * r, 7 * r + 7);
  const gradient = unit([v[1] - v[2], v[3] - v[4], v[5] - v[6]]);
  const incidence = Math.abs(gradient[0] * rays[r][1][0] + gradient[1] * rays[r][1][1] + gradient[2] * rays[r][1][2]);
  worstResidual = Math.max(worstResidual, Math.abs(v[0]) / diagonal);
  const gap = Math.abs(jolt - lib) / diagonal;
  if (gap > worst) [worst, worstIncidence] = [gap, incidence];
  worstScaled = Math.max(worstScaled, gap * incidence);
}
if (disagree > 5) failures.push(`... ${disagree} rays hit in one and miss in the other`);
if (!(worstResidual <= 1e-4)) failures.push(`a Jolt hit lies ${worstResidual.toExponential(3)} of the diagonal off the library's surface (limit 1e-4)`);
if (!(worstScaled <= 1e-4)) failures.push(`a ray's hit distance times its incidence differs by ${worstScaled.toExponential(3)} of the diagonal (limit 1e-4)`);
// ---- conservative: the surface inside the engine's shapes ----
let outside = 0;
const samples = mode === 'conservative' ? 5000 : 0;
for (let s = 0; s < samples; ++s) {
  const p = surfacePoint();
  const collector = new Jolt.CollidePointAnyHitCollisionCollector();
  query.CollidePoint(new Jolt.RVec3(p[0], p[1], p[2]), collector, ...filters);
  if (!collector.HadHit()) outside++;
  Jolt.destroy(collector);
}
if (outside) failures.push(`${outside} of ${samples} surface samples outside the engine's shapes`);

console.log(`jolt: ${path.basename(file)}: ${colliders} colliders (${counts.sphere} spheres, ${counts.capsule} capsules, ` +
  `${counts.tapered} tapered capsules, ${counts.box} boxes); ${rays.length} rays, ${hits} hits, ${rays.length - hits - disagree} misses: ` +
  `max |Jolt - library| along the ray = ${worst.toExponential(3)} of the diagonal (that ray meets the surface at ` +
  `cos ${worstIncidence.toFixed(3)}; times the cosine at most ${worstScaled.toExponential(3)}), ` +
  `Jolt's hits at most ${worstResidual.toExponential(3)} off the library's surface; ` +
  (samples ? `${samples - outside} of ${samples} surface samples inside` : 'surface not checked (not conservative)'));
for (const f of failures) console.log(`  FAILED ${f}`);
process.exit(failures.length ? 1 : 0);
