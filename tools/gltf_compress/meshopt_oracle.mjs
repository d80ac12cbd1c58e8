// The npm meshoptimizer package's decoder as the oracle of Sherpa's meshopt decoders
// (vertex bitstream version 1 above all, which Debian's libmeshoptimizer 0.18 lacks).
// Writes one binary file of streams with the oracle's decoded bytes:
//  - every compressed bufferView of the given glTF/GLB files (gltfpack's corpus);
//  - synthetic version 1 streams from the package's own encoder: every stride from 4 to
//    256, several counts and data kinds, each encoder level, and the filters (OCTAHEDRAL,
//    QUATERNION, EXPONENTIAL, COLOR) on their encodings.
// Usage: node meshopt_oracle.mjs NODE_MODULES OUT_FILE GLTF_OR_GLB_OR_DIR... (a folder:
// its .glb/.gltf files whose names contain "meshopt").
// Record: u32 mode (0 ATTRIBUTES, 1 TRIANGLES, 2 INDICES), u32 filter (0 NONE, 1
// OCTAHEDRAL, 2 QUATERNION, 3 EXPONENTIAL, 4 COLOR), u32 count, u32 stride, u32 n + n
// encoded bytes, u32 m + m decoded bytes, u32 k + k bytes of a name (little endian).
import fs from 'node:fs';
import path from 'node:path';

const [modules, outFile, ...inputs] = process.argv.slice(2);
const files = inputs.flatMap((p) =>
	fs.statSync(p).isDirectory()
		? fs.readdirSync(p).filter((f) => /meshopt.*\.(glb|gltf)$/.test(f)).sort().map((f) => path.join(p, f))
		: [p]);
if (!modules || !outFile) {
	console.error('usage: node meshopt_oracle.mjs NODE_MODULES OUT_FILE GLTF_OR_GLB...');
	process.exit(2);
}
const pkg = path.join(modules, 'meshoptimizer');
const { MeshoptDecoder } = await import(path.join(pkg, 'meshopt_decoder.mjs'));
const { MeshoptEncoder } = await import(path.join(pkg, 'meshopt_encoder.js'));
await MeshoptDecoder.ready;
await MeshoptEncoder.ready;

const MODES = ['ATTRIBUTES', 'TRIANGLES', 'INDICES'];
const FILTERS = ['NONE', 'OCTAHEDRAL', 'QUATERNION', 'EXPONENTIAL', 'COLOR'];
const chunks = [];
const counts = { files: 0, views: 0, synthetic: 0, v1: 0 };
const u32 = (v) => {
	const b = Buffer.alloc(4);
	b.writeUInt32LE(v >>> 0);
	return b;
};
function record(mode, filter, count, stride, encoded, name) {
	const decoded = new Uint8Array(count * stride);
	MeshoptDecoder.decodeGltfBuffer(decoded, count, stride, encoded, mode, filter);
	if (mode === 'ATTRIBUTES' && (encoded[0] & 15) === 1) counts.v1++;
	chunks.push(u32(MODES.indexOf(mode)), u32(FILTERS.indexOf(filter)), u32(count), u32(stride));
	chunks.push(u32(encoded.length), Buffer.from(encoded), u32(decoded.length), Buffer.from(decoded));
	const n = Buffer.from(name);
	chunks.push(u32(n.length), n);
}

// --- the corpus files' compressed views ------------------------------------------------
function readGltf(file) {
	const bytes = fs.readFileSync(file);
	if (bytes.readUInt32LE(0) === 0x46546c67) { // "glTF"
		const jsonLength = bytes.readUInt32LE(12);
		const json = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString());
		const binAt = 20 + jsonLength;
		const bin = binAt + 8 <= bytes.length ? bytes.subarray(binAt + 8, binAt + 8 + bytes.readUInt32LE(binAt)) : null;
		return { json, buffer: (i) => (i === 0 && !json.buffers[0].uri ? bin : fs.readFileSync(path.join(path.dirname(file), json.buffers[i].uri))) };
	}
	const json = JSON.parse(bytes.toString());
	return { json, buffer: (i) => fs.readFileSync(path.join(path.dirname(file), json.buffers[i].uri)) };
}
for (const file of files) {
	const { json, buffer } = readGltf(file);
	counts.files++;
	(json.bufferViews || []).forEach((view, v) => {
		for (const codec of ['EXT_meshopt_compression', 'KHR_meshopt_compression']) {
			const e = view.extensions && view.extensions[codec];
			if (!e) continue;
			const source = buffer(e.buffer);
			const encoded = new Uint8Array(source.buffer, source.byteOffset + (e.byteOffset || 0), e.byteLength);
			record(e.mode, e.filter || 'NONE', e.count, e.byteStride, encoded, `${path.basename(file)} bufferViews[${v}] ${codec}`);
			counts.views++;
		}
	});
}

// --- synthetic version 1 streams from the package's encoder ---------------------------
let seed = 12345;
const random = () => ((seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) >>> 8) / 16777216;
function data(count, stride, kind) {
	const d = new Uint8Array(count * stride);
	const view = new DataView(d.buffer);
	for (let i = 0; i < count; ++i)
		for (let k = 0; k < stride; k += 4) {
			const at = i * stride + k;
			const column = kind === 4 ? (k / 4) % 4 : kind;
			if (column === 0) for (let j = 0; j < 4; ++j) d[at + j] = (random() * 256) | 0; // noise
			else if (column === 1) view.setUint16(at, (i * 37 + k) & 0xffff, true), view.setUint16(at + 2, (i * 3) & 0xffff, true); // 16-bit ramps
			else if (column === 2) view.setFloat32(at, Math.sin(i * 0.01 + k) * 100, true); // floats
			else view.setUint32(at, k * 1000, true); // constant
		}
	return d;
}
const synthetic = (mode, filter, count, stride, encoded, name) => {
	record(mode, filter, count, stride, encoded, name);
	counts.synthetic++;
};
for (let stride = 4; stride <= 256; stride += 4)
	for (const count of [0, 1, 16, 17, 100, 257, 1000])
		for (let kind = 0; kind < 5; ++kind) {
			if (count > 100 && stride > 64 && kind !== 4) continue; // keep the file small
			const level = (stride / 4 + count + kind) % 4;
			const encoded = MeshoptEncoder.encodeVertexBufferLevel(data(count, stride, kind), count, stride, level, 1);
			synthetic('ATTRIBUTES', 'NONE', count, stride, encoded, `v1 stride ${stride} count ${count} kind ${kind} level ${level}`);
		}
const unit = (count, w) => {
	const f = new Float32Array(count * 4);
	for (let i = 0; i < count; ++i) {
		const v = [random() - 0.5, random() - 0.5, random() - 0.5, random() - 0.5];
		const l = Math.hypot(...(w ? v : v.slice(0, 3)));
		for (let c = 0; c < 4; ++c) f[i * 4 + c] = c < 3 || w ? v[c] / l : v[3] > 0 ? 1 : -1;
	}
	return f;
};
const count = 1000;
for (const [stride, bits] of [[4, 8], [8, 12], [8, 16]]) {
	const oct = MeshoptEncoder.encodeFilterOct(unit(count, false), count, stride, bits);
	synthetic('ATTRIBUTES', 'OCTAHEDRAL', count, stride, MeshoptEncoder.encodeVertexBufferLevel(oct, count, stride, 2, 1), `octahedral ${stride} ${bits}`);
}
for (const bits of [8, 12, 16]) {
	const quat = MeshoptEncoder.encodeFilterQuat(unit(count, true), count, 8, bits);
	synthetic('ATTRIBUTES', 'QUATERNION', count, 8, MeshoptEncoder.encodeVertexBufferLevel(quat, count, 8, 2, 1), `quaternion ${bits}`);
}
for (const bits of [10, 16, 24]) {
	const f = new Float32Array(count * 3).map(() => (random() - 0.5) * 1000);
	const exp = MeshoptEncoder.encodeFilterExp(f, count, 12, bits);
	synthetic('ATTRIBUTES', 'EXPONENTIAL', count, 12, MeshoptEncoder.encodeVertexBufferLevel(exp, count, 12, 2, 1), `exponential ${bits}`);
}
for (const [stride, bits] of [[4, 6], [4, 8], [8, 10], [8, 16]]) {
	const colors = new Float32Array(count * 4).map(() => random());
	const col = MeshoptEncoder.encodeFilterColor(colors, count, stride, bits);
	synthetic('ATTRIBUTES', 'COLOR', count, stride, MeshoptEncoder.encodeVertexBufferLevel(col, count, stride, 2, 1), `color ${stride} ${bits}`);
}
fs.writeFileSync(outFile, Buffer.concat(chunks));
console.log(`meshopt oracle: ${counts.views} views of ${counts.files} files, ${counts.synthetic} synthetic streams, ${counts.v1} vertex streams of version 1 -> ${outFile}`);
