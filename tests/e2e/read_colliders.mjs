// read_colliders.mjs: reads a colliders file back with @gltf-transform/core (npm), which knows no
// physics: the two small Extension classes of physics_extensions.mjs read KHR_implicit_shapes (the
// document's shapes) and KHR_physics_rigid_bodies (each node's collider). Checks, against the tool's
// --proxies-json: one collider per proxy, in order, each of the right type with the proxy's
// parameters at gltf-transform's world placement of its node (a sphere at its centre; a capsule's
// top ball on ball b and bottom ball on ball a, or, when one ball holds the other, a sphere; a box's
// centre, half extents and edge directions), to 1e-9 of the bounding-box diagonal.
// usage: node read_colliders.mjs NODE_MODULES FILE.glb PROXIES.json
import fs from 'node:fs';
import path from 'node:path';
import { readPhysics } from './physics_extensions.mjs';

const [modules, file, proxiesJson] = process.argv.slice(2);
const { root, shapes, bodies, failures } = await readPhysics(modules, file);
const colliders = new Map([...bodies].filter(([, b]) => b.collider).map(([n, b]) => [n, b.collider.geometry.shape]));
const nodes = root.listNodes().filter((n) => colliders.has(n));
const proxies = JSON.parse(fs.readFileSync(proxiesJson, 'utf8')).proxies;
if (nodes.length !== proxies.length) failures.push(`${nodes.length} collider nodes, ${proxies.length} proxies`);

// the mesh's diagonal, from gltf-transform's own accessors
const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
for (const mesh of root.listMeshes()) for (const prim of mesh.listPrimitives()) {
  const p = prim.getAttribute('POSITION');
  p.getMin([]).forEach((v, k) => (lo[k] = Math.min(lo[k], v)));
  p.getMax([]).forEach((v, k) => (hi[k] = Math.max(hi[k], v)));
}
const tolerance = 1e-9 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);

const rotate = (q, v) => {   // q (x y z w) applied to v
  const [x, y, z, w] = q;
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + y * t[2] - z * t[1], v[1] + w * t[1] + z * t[0] - x * t[2], v[2] + w * t[2] + x * t[1] - y * t[0]];
};
const gap = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const counts = {};
nodes.forEach((node, i) => {
  const shape = shapes[colliders.get(node)], p = proxies[i];
  if (!shape || !p) return;
  counts[shape.type] = (counts[shape.type] || 0) + 1;
  const t = node.getWorldTranslation(), q = node.getWorldRotation();
  const bad = (what) => failures.push(`collider ${i} (${p.kind} -> ${shape.type}): ${what}`);
  if (p.kind === 'sphere' || (p.kind === 'capsule' && gap(p.a, p.b) <= Math.abs(p.radius_a - p.radius_b))) {
    const big = p.kind === 'sphere' ? { c: p.center, r: p.radius }
      : p.radius_a >= p.radius_b ? { c: p.a, r: p.radius_a } : { c: p.b, r: p.radius_b };
    if (shape.type !== 'sphere') return bad('not a sphere');
    if (gap(t, big.c) > tolerance || Math.abs(shape.sphere.radius - big.r) > tolerance) bad('centre or radius differs');
  } else if (p.kind === 'capsule') {
    if (shape.type !== 'capsule') return bad('not a capsule');
    const c = shape.capsule;
    const top = rotate(q, [0, c.height / 2, 0]).map((v, k) => v + t[k]);
    const bottom = rotate(q, [0, -c.height / 2, 0]).map((v, k) => v + t[k]);
    if (gap(top, p.b) > tolerance || gap(bottom, p.a) > tolerance) bad('balls misplaced');
    if (Math.abs(c.radiusTop - p.radius_b) > tolerance || Math.abs(c.radiusBottom - p.radius_a) > tolerance) bad('radii differ');
  } else if (p.kind === 'box') {
    if (shape.type !== 'box') return bad('not a box');
    if (gap(t, p.center) > tolerance) bad('centre differs');
    shape.box.size.forEach((s, k) => { if (Math.abs(s / 2 - p.half_extents[k]) > tolerance) bad('extents differ'); });
    for (let k = 0; k < 3; ++k) {
      const axis = [0, 0, 0];
      axis[k] = 1;
      if (gap(rotate(q, axis), rotate(p.rotation, axis)) > 1e-9) bad('edge directions differ');
    }
  } else {
    bad('unknown proxy kind');
  }
});
console.log(`gltf-transform: ${path.basename(file)}: ${nodes.length} colliders read back (${JSON.stringify(counts)}), ` +
  `${proxies.length} proxies compared`);
for (const f of failures) console.log(`  FAILED ${f}`);
process.exit(failures.length ? 1 : 0);
