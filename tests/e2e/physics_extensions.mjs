// physics_extensions.mjs: the glTF physics extensions as @gltf-transform/core (npm) reads them, for
// the e2e readers (read_colliders.mjs, read_bone_colliders.mjs): KHR_implicit_shapes keeps the
// document's shapes, KHR_physics_rigid_bodies each node's body object (its collider, motion).
// usage: const { ImplicitShapes, RigidBodies } = physicsExtensions(Extension);
export function physicsExtensions(Extension) {
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
