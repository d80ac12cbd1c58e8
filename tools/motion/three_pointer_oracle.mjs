// The independent KHR_animation_pointer oracle: three.js 0.170 (GLTFLoader + AnimationMixer)
// with Needle's GLTFLoader plugin @needle-tools/three-animation-pointer (MIT), which turns
// each pointer channel into a three.js KeyframeTrack on the property of the loaded
// material, light, camera or node that it maps the pointer to. For each requested time it
// plays the animation and prints every animated value, converted back to the glTF value,
// keyed by the channel's glTF pointer, as one JSON object on stdout:
//   {"duration": D, "frames": [{"time": T, "values": {POINTER: [..]}}],
//    "compared": {POINTER: "three.js property"}, "unsupported": {POINTER: "why"}}
// Usage: node three_pointer_oracle.mjs CACHE_DIR SCENE.gltf ANIMATION TIME...
//   CACHE_DIR holds node_modules/three and the plugin (install_three_pointer.sh).
// Node has no image decoding: every texture is a 1x1 DataTexture stand-in (the transforms
// live on the texture object, its pixels do not matter); buffers are inlined as data URIs.
import { cacheModule, readGltfJson } from './node_gltf.mjs';

const [cache, scenePath, animArg, ...timeArgs] = process.argv.slice(2);
const mod = (p) => cacheModule(cache, p);
const THREE = await mod('three/build/three.module.js');
const { GLTFLoader } = await mod('three/examples/jsm/loaders/GLTFLoader.js');
const { GLTFAnimationPointerExtension } =
  await mod('@needle-tools/three-animation-pointer/src/GLTFLoaderAnimationPointer.js');

// What the plugin (1.0.7) writes for each glTF pointer, by three.js property (the track's
// path after the object), and how that property gives the glTF value back. Every one is
// the identity except yfov (the plugin converts radians to the degrees of
// PerspectiveCamera.fov), a baseColorFactor (color's r, g, b and opacity as alpha) and
// the normal scale (a scalar track bound to the Vector2 normalScale: its x is the value).
// RAW: the plugin stores the sampled glTF value as it is in a three.js property that
// means something else (three renders it wrong), so the sampled value is still compared:
// the spot's penumbra is 1 - inner/outer in three.js, and an orthographic camera's zoom
// is a magnification, not xmag/ymag (both write the one zoom).
// anisotropyRotation and dispersion are not in the plugin's table: it passes the glTF
// name through, and three.js' MeshPhysicalMaterial has properties of those names that
// hold the same quantities (GLTFLoader copies them unchanged).
// Any other pointer is reported as unsupported with the plugin's track path.
const RAD = (deg) => deg * Math.PI / 180;
const M = '/materials/N/', EXT = M + 'extensions/', TT = '/extensions/KHR_texture_transform/';
const L = '/extensions/KHR_lights_punctual/lights/N/';
const MAPPED = {
  [M + 'pbrMetallicRoughness/baseColorFactor']: ['color', 'opacity'],
  [M + 'pbrMetallicRoughness/metallicFactor']: ['metalness'],
  [M + 'pbrMetallicRoughness/roughnessFactor']: ['roughness'],
  [M + 'emissiveFactor']: ['emissive'],
  [M + 'alphaCutoff']: ['alphaTest'],
  [M + 'occlusionTexture/strength']: ['aoMapIntensity'],
  [M + 'normalTexture/scale']: ['normalScale'],
  [M + 'pbrMetallicRoughness/baseColorTexture' + TT + 'offset']: ['map.offset'],
  [M + 'pbrMetallicRoughness/baseColorTexture' + TT + 'scale']: ['map.repeat'],
  [M + 'emissiveTexture' + TT + 'offset']: ['emissiveMap.offset'],
  [M + 'emissiveTexture' + TT + 'scale']: ['emissiveMap.repeat'],
  [EXT + 'KHR_materials_emissive_strength/emissiveStrength']: ['emissiveIntensity'],
  [EXT + 'KHR_materials_transmission/transmissionFactor']: ['transmission'],
  [EXT + 'KHR_materials_ior/ior']: ['ior'],
  [EXT + 'KHR_materials_volume/thicknessFactor']: ['thickness'],
  [EXT + 'KHR_materials_volume/attenuationColor']: ['attenuationColor'],
  [EXT + 'KHR_materials_volume/attenuationDistance']: ['attenuationDistance'],
  [EXT + 'KHR_materials_iridescence/iridescenceFactor']: ['iridescence'],
  [EXT + 'KHR_materials_iridescence/iridescenceIor']: ['iridescenceIOR'],
  [EXT + 'KHR_materials_iridescence/iridescenceThicknessMinimum']: ['iridescenceThicknessRange[0]'],
  [EXT + 'KHR_materials_iridescence/iridescenceThicknessMaximum']: ['iridescenceThicknessRange[1]'],
  [EXT + 'KHR_materials_clearcoat/clearcoatFactor']: ['clearcoat'],
  [EXT + 'KHR_materials_clearcoat/clearcoatRoughnessFactor']: ['clearcoatRoughness'],
  [EXT + 'KHR_materials_sheen/sheenColorFactor']: ['sheenColor'],
  [EXT + 'KHR_materials_sheen/sheenRoughnessFactor']: ['sheenRoughness'],
  [EXT + 'KHR_materials_specular/specularFactor']: ['specularIntensity'],
  [EXT + 'KHR_materials_specular/specularColorFactor']: ['specularColor'],
  [EXT + 'KHR_materials_anisotropy/anisotropyRotation']: ['anisotropyRotation'],
  [EXT + 'KHR_materials_dispersion/dispersion']: ['dispersion'],
  [L + 'color']: ['color'],
  [L + 'intensity']: ['intensity'],
  [L + 'range']: ['distance'],
  [L + 'spot/outerConeAngle']: ['angle'],
  [L + 'spot/innerConeAngle']: ['penumbra', 'RAW'],
  '/cameras/N/perspective/yfov': ['fov', RAD],
  '/cameras/N/perspective/znear': ['near'],
  '/cameras/N/perspective/zfar': ['far'],
  '/cameras/N/orthographic/znear': ['near'],
  '/cameras/N/orthographic/zfar': ['far'],
  '/cameras/N/orthographic/xmag': ['zoom', 'RAW'],
  '/cameras/N/orthographic/ymag': ['zoom', 'RAW'],
  '/nodes/N/extensions/KHR_node_visibility/visible': ['visible'],
};
const template = (p) => p.replace(/^(\/materials|\/cameras|\/nodes|\/extensions\/KHR_lights_punctual\/lights)\/\d+\//, '$1/N/');

// The plugin, with the channel's own pointer kept for its tracks (the plugin overwrites
// the pointer in the JSON with its three.js path) and two fixes of its own, so that what
// is compared is three.js' sampling of the right keys:
// - CUBICSPLINE: its check `interpolation === 'CUBICSPLINE'` never holds (its table maps
//   CUBICSPLINE to undefined), so a cubic channel's track would lerp the (in-tangent,
//   value, out-tangent) triples; here the track gets three's own glTF cubic interpolant
//   (GLTFCubicSplineInterpolant), as GLTFLoader gives node channels.
// - Track paths name a light, camera or node by its uuid (the plugin's way for objects
//   without a name): by name, a light or camera that is its node's only content is
//   renamed by GLTFLoader after the plugin named the track, which then binds to nothing.
const pointerOfTrack = new Map();
class Plugin extends GLTFAnimationPointerExtension {
  loadAnimationTargetFromChannelWithAnimationPointer(channel) {
    const ext = channel.target.extensions?.KHR_animation_pointer;
    if (ext?.pointer !== undefined) channel.target.sherpaPointer ??= ext.pointer;
    return super.loadAnimationTargetFromChannelWithAnimationPointer(channel);
  }
  createAnimationTracksWithAnimationPointer(node, input, output, sampler, target) {
    const tracks = super.createAnimationTracksWithAnimationPointer(node, input, output, sampler, target);
    for (const track of tracks ?? []) {
      if (sampler.interpolation === 'CUBICSPLINE') this.parser._createCubicSplineTrackInterpolant(track);
      if (!track.name.startsWith('.materials.')) {
        const parts = track.name.split('.');
        parts[2] = node.uuid;
        track.name = parts.join('.');
      }
      pointerOfTrack.set(track, target.sherpaPointer);
    }
    return tracks;
  }
}
// Textures: a stand-in per glTF texture (no images in Node); GLTFLoader then applies
// KHR_texture_transform to a clone per slot as usual.
class StandInTextures {
  constructor(parser) { this.name = 'sherpa_stand_in_textures'; this.parser = parser; }
  loadTexture() {
    const t = new THREE.DataTexture(new Uint8Array([255, 255, 255, 255]), 1, 1);
    t.needsUpdate = true;
    return Promise.resolve(t);
  }
}

const json = readGltfJson(scenePath);
// Material tracks find their material by name on the scene's meshes (GLTFLoader clones
// materials per mesh variant, keeping the name): give each a unique one (glTF names
// need not be unique or present).
(json.materials ?? []).forEach((m, i) => { m.name = `${m.name ?? 'material'} #${i}`; });

const loader = new GLTFLoader();
loader.register((p) => new StandInTextures(p));
loader.register((p) => new Plugin(p));
const gltf = await new Promise((resolve, reject) => loader.parse(JSON.stringify(json), '', resolve, reject));
const anim = Number(animArg);
const clip = gltf.animations[anim];

// Each track's binding and the three.js property it writes: the property's name (with
// its array index), after the texture slot where it is a texture's. Bindings that find
// nothing print three's whole object to the console: kept quiet, they are reported.
const channels = new Map(); // pointer -> [{track, binding, property}]
const [warn, error] = [console.warn, console.error];
console.warn = console.error = () => {};
for (const track of clip.tracks) {
  const pointer = pointerOfTrack.get(track);
  if (pointer === undefined) continue; // a core node channel: the motion oracle's
  const binding = new THREE.PropertyBinding(gltf.scene, track.name);
  binding.bind();
  const { propertyName, propertyIndex } = binding.parsedPath;
  const segments = track.name.split('.');
  const property = !binding.targetObject ? segments.slice(3).join('.')
    : (binding.targetObject.isTexture ? segments.at(-2) + '.' : '') + propertyName +
      (propertyIndex !== undefined ? `[${propertyIndex}]` : '');
  if (!channels.has(pointer)) channels.set(pointer, []);
  channels.get(pointer).push({ track, binding, property });
}
[console.warn, console.error] = [warn, error];
const compared = {}, unsupported = {}, errors = [];
const source = json.animations[anim];
for (const ch of source.channels) {
  const pointer = ch.target.extensions?.KHR_animation_pointer?.pointer;
  if (pointer === undefined || /^\/nodes\/\d+\/(translation|rotation|scale|weights)$/.test(pointer)) continue;
  const entries = channels.get(pointer) ?? [];
  const want = MAPPED[template(pointer)];
  const props = entries.map((e) => e.property).join(' + ');
  if (!want) {
    unsupported[pointer] = entries.length === 0 ? 'the plugin makes no track for it'
      : `the plugin's track path ".${props}" ${entries.every((e) => e.binding.targetObject) ?
        'is not a three.js property known to hold this value' : 'binds to no three.js property'}`;
    channels.delete(pointer);
  } else if (entries.map((e) => e.property).join() !== want.filter((w) => typeof w === 'string' && w !== 'RAW').join() ||
             entries.some((e) => !e.binding.targetObject)) {
    errors.push(`${pointer}: expected three.js ${want[0]}, the plugin made ".${props}"` +
                `${entries.some((e) => !e.binding.targetObject) ? ' (unbound)' : ''}`);
    channels.delete(pointer);
  } else {
    compared[pointer] = props + (want.includes('RAW') ? ' (raw glTF value)' : '');
  }
}
const kept = new Set([...channels.values()].flat().map((e) => e.track));
clip.tracks = clip.tracks.filter((t) => kept.has(t) || !pointerOfTrack.has(t));

const WIDTH = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };
const widthOf = (pointer) => {
  const ch = source.channels.find((c) => c.target.extensions?.KHR_animation_pointer?.pointer === pointer);
  return WIDTH[json.accessors[source.samplers[ch.sampler].output].type];
};
// One property's value: a Color 3, a Vector2 2, a number or bool 1 (PropertyBinding's
// own getValue, as the mixer reads it).
const read = ({ binding }) => {
  const p = binding.resolvedProperty;
  const n = p?.isColor || p?.isVector3 ? 3 : p?.isVector2 ? 2 : 1;
  const buf = new Array(n);
  binding.getValue(buf, 0);
  return buf.map(Number);
};

const mixer = new THREE.AnimationMixer(gltf.scene);
const action = mixer.clipAction(clip);
action.setLoop(THREE.LoopOnce, 1); // past the end: hold the last keys, as glTF clamps
action.clampWhenFinished = true;
const out = { duration: clip.duration, frames: [], compared, unsupported, errors };
for (const t of timeArgs.map(Number)) {
  action.reset().play(); // a finished (clamped) action stays paused: restart it
  mixer.setTime(t);
  const values = {};
  for (const [pointer, entries] of channels) {
    let v = entries.flatMap(read).slice(0, widthOf(pointer));
    const back = MAPPED[template(pointer)].find((w) => typeof w === 'function');
    if (back) v = v.map(back);
    values[pointer] = v;
  }
  out.frames.push({ time: t, values });
}
process.stdout.write(JSON.stringify(out));
