// What the three.js oracles (three_oracle.mjs, three_pointer_oracle.mjs) need to load a
// glTF file in Node, which has no DOM and no file fetch.
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

// three's FileLoader (used for the data URIs) reports progress with a DOM event class.
globalThis.ProgressEvent ??= class ProgressEvent {
  constructor(type, init = {}) { Object.assign(this, init, { type }); }
};

// A module of the npm cache CACHE_DIR/node_modules (install_three*.sh).
export const cacheModule = (cache, p) => import(pathToFileURL(path.join(cache, 'node_modules', p)).href);

// The file's JSON with its buffers inlined as data URIs.
export function readGltfJson(scenePath) {
  const json = JSON.parse(fs.readFileSync(scenePath, 'utf8'));
  const dir = path.dirname(scenePath);
  for (const b of json.buffers ?? [])
    if (b.uri && !b.uri.startsWith('data:'))
      b.uri = 'data:application/octet-stream;base64,' +
              fs.readFileSync(path.join(dir, decodeURIComponent(b.uri))).toString('base64');
  return json;
}
