// The three.js render oracle: renders a glTF with an equirectangular environment in
// headless Chromium (WebGL through SwiftShader) and writes the canvas as a PNG, with
// the same camera, environment and tone mapping Sherpa's `render` takes.
//   node three_render.mjs --cache DIR --gltf FILE --out OUT.png [--environment FILE.exr|none]
//        [--camera eye=x,y,z:target=x,y,z[:up=x,y,z][:fov=DEG][:near=N][:far=F]]
//        [--width W] [--height H] [--tone-map neutral|aces|agx|linear] [--exposure EV]
//        [--background R,G,B|environment] [--environment-rotation DEG] [--timeout SECONDS]
//        [--variant NAME]
// --variant shows a KHR_materials_variants variant as three.js's own example
// (webgl_loader_gltf_variants) does: GLTFLoader keeps the extension it does not know in
// userData.gltfExtensions (root: the names; each primitive's mesh: its mappings), and
// the mapped material replaces the mesh's (parser.getDependency('material', i)).
// Files are served to the page from 127.0.0.1 by a server in this process; Chromium is
// started asynchronously so that the server keeps answering; the page sets
// window.__sherpaDone (or window.__sherpaError) once it has drawn.
import { createServer } from 'node:http';
import { readFile, writeFile, stat } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => {
  if (a.startsWith('--')) acc.push([a.slice(2), all[i + 1]]);
  return acc;
}, []));
const need = (k) => { if (!args[k]) { console.error(`three_render: --${k} is required`); process.exit(2); } return args[k]; };
const cache = path.resolve(need('cache'));
const gltf = path.resolve(need('gltf'));
const out = path.resolve(need('out'));
const width = Number(args.width ?? 320), height = Number(args.height ?? 240);
// SwiftShader on a shared 2-core machine can take minutes: the test's own timeout bounds it.
const timeoutMs = Number(args.timeout ?? 900) * 1000;
const require = createRequire(path.join(cache, 'node_modules', 'x.js'));
const puppeteer = require('puppeteer-core');
const threeDir = path.join(cache, 'node_modules', 'three');

// Our camera spec -> PerspectiveCamera + lookAt.
const camera = { eye: [0, 0, 3], target: [0, 0, 0], up: [0, 1, 0], fov: 45, near: 0.01, far: 1000 };
for (const part of (args.camera ?? '').split(':').filter(Boolean)) {
  const [k, v] = part.split('=');
  const nums = v.split(',').map(Number);
  camera[k] = nums.length === 1 ? nums[0] : nums;
}

const files = {
  '/model/': path.dirname(gltf),
  '/three/': threeDir,
};
const environment = args.environment && args.environment !== 'none' ? path.resolve(args.environment) : null;
const types = { '.js': 'text/javascript', '.html': 'text/html', '.gltf': 'model/gltf+json',
  '.bin': 'application/octet-stream', '.png': 'image/png', '.jpg': 'image/jpeg', '.exr': 'application/octet-stream' };

const page = `<!doctype html><html><body style="margin:0">
<script type="importmap">{"imports":{"three":"/three/build/three.module.js","three/addons/":"/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';
const cfg = ${JSON.stringify({ width, height, camera, toneMap: args['tone-map'] ?? 'neutral',
    exposure: Number(args.exposure ?? 0), background: args.background ?? 'environment',
    rotation: Number(args['environment-rotation'] ?? 0), environment: !!environment,
    variant: args.variant ?? null,
    model: '/model/' + encodeURIComponent(path.basename(gltf)) })};
try {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(cfg.width, cfg.height);
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.toneMapping = { neutral: THREE.NeutralToneMapping, aces: THREE.ACESFilmicToneMapping,
    agx: THREE.AgXToneMapping, linear: THREE.LinearToneMapping }[cfg.toneMap];
  renderer.toneMappingExposure = Math.pow(2, cfg.exposure);
  document.body.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  if (cfg.environment) {
    const tex = await new EXRLoader().loadAsync('/environment.exr');
    tex.mapping = THREE.EquirectangularReflectionMapping;
    scene.environment = tex;
    scene.environmentRotation.y = cfg.rotation * Math.PI / 180;
    scene.backgroundRotation.y = cfg.rotation * Math.PI / 180;
    if (cfg.background === 'environment') scene.background = tex;
  }
  if (cfg.background !== 'environment') {
    const [r, g, b] = cfg.background.split(',').map(Number);
    scene.background = new THREE.Color().setRGB(r, g, b, THREE.LinearSRGBColorSpace);
  }
  const gltf = await new GLTFLoader().loadAsync(cfg.model);
  if (cfg.variant !== null) {
    const names = (gltf.userData.gltfExtensions?.KHR_materials_variants?.variants ?? []).map((v) => v.name);
    const index = names.indexOf(cfg.variant);
    if (index < 0) throw new Error('no variant ' + cfg.variant + ' (file has ' + names.join(', ') + ')');
    const meshes = [];
    gltf.scene.traverse((o) => { if (o.isMesh && o.userData.gltfExtensions?.KHR_materials_variants) meshes.push(o); });
    for (const o of meshes) {
      const mapping = o.userData.gltfExtensions.KHR_materials_variants.mappings
        .find((m) => m.variants.includes(index));
      if (mapping) o.material = await gltf.parser.getDependency('material', mapping.material);
    }
  }
  scene.add(gltf.scene);
  const c = cfg.camera;
  const cam = new THREE.PerspectiveCamera(c.fov, cfg.width / cfg.height, c.near, c.far);
  cam.up.set(...c.up);
  cam.position.set(...c.eye);
  cam.lookAt(...c.target);
  renderer.render(scene, cam);
  window.__sherpaDone = true;
} catch (e) {
  window.__sherpaError = String(e && e.stack || e);
}
</script></body></html>`;

const server = createServer(async (req, res) => {
  try {
    const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    let file = null;
    if (url === '/') { res.writeHead(200, { 'content-type': 'text/html' }); res.end(page); return; }
    if (url === '/environment.exr' && environment) file = environment;
    for (const [prefix, dir] of Object.entries(files))
      if (url.startsWith(prefix)) {
        file = path.join(dir, path.normalize(url.slice(prefix.length)));
        if (!file.startsWith(dir)) file = null; // no escaping the served folders
      }
    if (!file || !(await stat(file)).isFile()) throw new Error('not found');
    res.writeHead(200, { 'content-type': types[path.extname(file)] ?? 'application/octet-stream' });
    res.end(await readFile(file));
  } catch {
    res.writeHead(404); res.end();
  }
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const port = server.address().port;
let browser;
try {
  browser = await puppeteer.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    protocolTimeout: timeoutMs,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--headless', '--no-sandbox',
      '--disable-gpu', '--disable-background-networking', '--disable-component-update',
      '--disable-sync', '--no-first-run'],
  });
  const tab = await browser.newPage();
  await tab.setViewport({ width, height });
  const logs = [];
  tab.on('console', (m) => logs.push(m.text()));
  tab.on('pageerror', (e) => { logs.push(String(e)); console.error(`three_render: page error: ${e}`); });
  // A file the page cannot get ends the run at once (a missing module never signals).
  let missing = null;
  const ours = (url) => /\/(three|model)\/|\/environment\.exr$/.test(new URL(url).pathname);
  tab.on('requestfailed', (r) => { if (ours(r.url())) missing = r.url(); });
  tab.on('response', (r) => { if (r.status() >= 400 && ours(r.url())) missing = r.url(); });
  await tab.goto(`http://127.0.0.1:${port}/`);
  const drawn = tab.waitForFunction('window.__sherpaDone || window.__sherpaError',
    { timeout: timeoutMs, polling: 500 });
  const failed = new Promise((_, no) => {
    const t = setInterval(() => { if (missing) { clearInterval(t); no(new Error(`cannot load ${missing}`)); } }, 200);
    drawn.finally(() => clearInterval(t)).catch(() => {});
  });
  await Promise.race([drawn, failed]);
  const error = await tab.evaluate(() => window.__sherpaError);
  if (error) throw new Error(`page: ${error}\n${logs.join('\n')}`);
  const data = await tab.evaluate(() => document.querySelector('canvas').toDataURL('image/png'));
  await writeFile(out, Buffer.from(data.split(',')[1], 'base64'));
  for (const l of logs) if (/error|warn/i.test(l)) console.error(`three_render: page: ${l}`);
} catch (e) {
  console.error(`three_render: ${e.message ?? e}`);
  process.exitCode = 1;
} finally {
  if (browser) await browser.close();
  server.close();
}
