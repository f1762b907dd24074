// physics_extensions.mjs: the glTF physics extensions as @gltf-transform/core (npm) reads them, for
// the e2e readers (read_colliders.mjs, read_bone_colliders.mjs): KHR_implicit_shapes keeps the
// document's shapes, KHR_physics_rigid_bodies each node's body object (its collider, motion).
// usage: const { root, shapes, bodies, failures } = await readPhysics(NODE_MODULES, FILE.glb);
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

// Reads a .glb with both extensions registered: the document's root, its shapes, its bodies (node
// -> body object), and a failures list that says when either extension was not read.
export async function readPhysics(modules, file) {
  const { NodeIO, Extension } = await import(pathToFileURL(path.join(modules, '@gltf-transform/core/dist/index.js')).href);
  const { ImplicitShapes, RigidBodies } = physicsExtensions(Extension);
  const io = new NodeIO().registerExtensions([ImplicitShapes, RigidBodies]);
  const root = (await io.readBinary(new Uint8Array(fs.readFileSync(file)))).getRoot();
  const used = Object.fromEntries(root.listExtensionsUsed().map((e) => [e.extensionName, e]));
  const failures = [];
  if (!used.KHR_implicit_shapes || !used.KHR_physics_rigid_bodies) failures.push('the physics extensions were not read');
  return { root, shapes: used.KHR_implicit_shapes?.shapes || [], bodies: used.KHR_physics_rigid_bodies?.bodies || new Map(), failures };
}

function physicsExtensions(Extension) {
  class ImplicitShapes extends Extension {
    static EXTENSION_NAME = 'KHR_implicit_shapes';
    extensionName = 'KHR_implicit_shapes';
    shapes = [];
    read(context) {
      this.shapes = context.jsonDoc.json.extensions?.[this.extensionName]?.shapes || [];
      return this;
    }
    write() { return this; }
  }
  class RigidBodies extends Extension {
    static EXTENSION_NAME = 'KHR_physics_rigid_bodies';
    extensionName = 'KHR_physics_rigid_bodies';
    bodies = new Map();   // gltf-transform Node -> its KHR_physics_rigid_bodies object
    read(context) {
      (context.jsonDoc.json.nodes || []).forEach((n, i) => {
        const body = n.extensions?.[this.extensionName];
        if (body) this.bodies.set(context.nodes[i], body);
      });
      return this;
    }
    write() { return this; }
  }
  return { ImplicitShapes, RigidBodies };
}
