// The independent animation oracle of issue #16: three.js (GLTFLoader + AnimationMixer)
// poses a glTF file and prints, per requested time, every node's TRS and the world
// positions of every mesh primitive's vertices (skinned and morphed by three.js'
// SkinnedMesh/Mesh.getVertexPosition) as one JSON object on stdout.
// Usage: node three_oracle.mjs CACHE_DIR SCENE.gltf ANIMATION TIME...
//   CACHE_DIR holds node_modules/three (install_three.sh); ANIMATION -1: none.
// Node has no image decoding and no file fetch: buffers are inlined as data URIs and
// images, textures and materials are dropped (they do not move vertices).
import { cacheModule, readGltfJson } from './node_gltf.mjs';

const [cache, scenePath, animArg, ...timeArgs] = process.argv.slice(2);
const THREE = await cacheModule(cache, 'three/build/three.module.js');
const { GLTFLoader } = await cacheModule(cache, 'three/examples/jsm/loaders/GLTFLoader.js');

const json = readGltfJson(scenePath);
delete json.images; delete json.textures; delete json.samplers; delete json.materials;
for (const m of json.meshes ?? []) for (const p of m.primitives) delete p.material;
json.extensionsUsed = (json.extensionsUsed ?? []).filter((e) => e === 'KHR_mesh_quantization');
delete json.extensionsRequired;

const loader = new GLTFLoader();
const gltf = await new Promise((resolve, reject) =>
  loader.parse(JSON.stringify(json), '', resolve, reject));
const assoc = gltf.parser.associations;
// Node objects by glTF index from the parser's node cache: `associations` shares one
// mapping between the clones of a mesh used by several nodes (three r170), so its
// `nodes` field names only the last of them.
const nodeIndex = new Map();
for (let i = 0; i < (json.nodes ?? []).length; ++i)
  nodeIndex.set(await gltf.parser.getDependency('node', i), i);
const nodeOf = (o) => {
  for (let x = o; x; x = x.parent) if (nodeIndex.has(x)) return nodeIndex.get(x);
  return -1;
};

// glTF requires unit rotation keys; three.js slerps the stored values as they are, so a
// file's slightly non-unit keys (AnimatedTriangle: |q| = 0.99985) come out as a scaled
// rotation matrix. Normalise them first, as Sherpa does on import: both sides then
// evaluate the same (valid) animation.
for (const clip of gltf.animations)
  for (const track of clip.tracks) {
    if (!track.name.endsWith('.quaternion')) continue;
    const v = track.values;
    const stride = track.getValueSize(); // 4, or 12 for cubic (in, value, out)
    const at = stride === 12 ? 4 : 0;
    for (let i = 0; i < v.length; i += stride) {
      const len = Math.hypot(v[i + at], v[i + at + 1], v[i + at + 2], v[i + at + 3]);
      if (len > 0) for (let c = 0; c < 4; ++c) v[i + at + c] /= len;
    }
  }

const anim = Number(animArg);
const mixer = new THREE.AnimationMixer(gltf.scene);
let action = null;
if (anim >= 0) {
  action = mixer.clipAction(gltf.animations[anim]);
  action.setLoop(THREE.LoopOnce, 1); // past the end: hold the last keys, as glTF clamps
  action.clampWhenFinished = true;
}
const out = { duration: anim >= 0 ? gltf.animations[anim].duration : 0, frames: [] };
const v = new THREE.Vector3();
for (const t of timeArgs.map(Number)) {
  // A finished (clamped) action stays paused: restart it for every time asked.
  if (action) {
    action.reset().play();
    mixer.setTime(t);
  }
  gltf.scene.updateMatrixWorld(true);
  const frame = { time: t, nodes: [], primitives: [] };
  gltf.scene.traverse((o) => {
    const a = assoc.get(o);
    if (nodeIndex.has(o))
      frame.nodes.push({ node: nodeIndex.get(o), t: o.position.toArray(), r: o.quaternion.toArray(),
                         s: o.scale.toArray() });
    if (!o.isMesh || !a || a.meshes === undefined) return;
    const count = o.geometry.attributes.position.count;
    const positions = new Array(count * 3);
    for (let i = 0; i < count; ++i) {
      o.getVertexPosition(i, v);
      v.applyMatrix4(o.matrixWorld);
      positions[3 * i] = v.x; positions[3 * i + 1] = v.y; positions[3 * i + 2] = v.z;
    }
    frame.primitives.push({ node: nodeOf(o), mesh: a.meshes, primitive: a.primitives ?? 0,
                            positions });
  });
  out.frames.push(frame);
}
process.stdout.write(JSON.stringify(out));
