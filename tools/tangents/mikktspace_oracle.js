// Runs the npm `mikktspace` package (a WebAssembly build of the reference MikkTSpace) over
// meshes in a binary file and writes its tangents, for comparison with ours.
// Usage: node mikktspace_oracle.js MODULE_DIR IN.bin OUT.bin [--time REPEATS]
// IN:  u32 mesh count, then per mesh: u32 corner count, f32 positions (3/corner),
//      normals (3/corner), uvs (2/corner); unindexed triangles, uvs as stored in glTF.
// OUT: per mesh, f32 tangents (4/corner) exactly as the package returns them (w in the
//      reference's v-up convention; negate for glTF). With --time, also prints the
//      wall and CPU seconds spent inside generateTangents (each the best of REPEATS runs
//      over all meshes).
'use strict';
const fs = require('fs');
const path = require('path');

const [moduleDir, inPath, outPath, timeFlag, repeatsArg] = process.argv.slice(2);
if (!moduleDir || !inPath || !outPath) {
    console.error('usage: node mikktspace_oracle.js MODULE_DIR IN.bin OUT.bin [--time N]');
    process.exit(2);
}
let generateTangents;
try {
    ({ generateTangents } = require(path.join(moduleDir, 'node_modules', 'mikktspace')));
} catch (e) {
    console.error(`mikktspace oracle: package not installed under ${moduleDir}: ${e.message}`);
    process.exit(3);
}

const input = fs.readFileSync(inPath);
const data = new DataView(input.buffer, input.byteOffset, input.byteLength);
let offset = 0;
const u32 = () => { const v = data.getUint32(offset, true); offset += 4; return v; };
const f32s = (n) => {
    const out = new Float32Array(n);
    for (let i = 0; i < n; ++i) out[i] = data.getFloat32(offset + 4 * i, true);
    offset += 4 * n;
    return out;
};
const meshes = [];
for (let m = u32(); m > 0; --m) {
    const corners = u32();
    meshes.push({ positions: f32s(3 * corners), normals: f32s(3 * corners), uvs: f32s(2 * corners) });
}

const run = () => meshes.map((m) => generateTangents(m.positions, m.normals, m.uvs));
let results = run();
if (timeFlag === '--time') {
    const repeats = Math.max(1, parseInt(repeatsArg || '3', 10));
    let best = Infinity, bestCpu = Infinity;
    for (let r = 0; r < repeats; ++r) {
        const start = process.hrtime.bigint();
        const cpu = process.cpuUsage();
        results = run();
        const used = process.cpuUsage(cpu);
        best = Math.min(best, Number(process.hrtime.bigint() - start) / 1e9);
        bestCpu = Math.min(bestCpu, (used.user + used.system) / 1e6);
    }
    console.log(`oracle_seconds ${best}`);
    console.log(`oracle_cpu_seconds ${bestCpu}`);
}
const total = results.reduce((n, r) => n + r.length, 0);
const out = Buffer.alloc(4 * total);
let o = 0;
for (const r of results) for (const v of r) { out.writeFloatLE(v, o); o += 4; }
fs.writeFileSync(outPath, out);
