#!/usr/bin/env node
// Runs the Khronos glTF-Validator (npm gltf-validator) over files and prints one
// JSON object per line: {"file", "ms", "messages": [{code, severity, pointer}]}.
// The oracle for Sherpa's own validator (tools/gltf_validator/compare.py).
// Usage: NODE_PATH=CACHE/node_modules khronos_validate.js FILE...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const t0 = process.hrtime.bigint();
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0, // all of them
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        const p = path.resolve(path.dirname(file), decodeURIComponent(uri));
        fs.readFile(p, (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
      }),
  });
  const ms = Number(process.hrtime.bigint() - t0) / 1e6;
  const severities = ['error', 'warning', 'info', 'hint'];
  return {
    file,
    ms,
    messages: report.issues.messages.map((m) => ({
      code: m.code,
      severity: severities[m.severity],
      pointer: m.pointer || '',
      message: m.message,
    })),
  };
}

(async () => {
  for (const file of process.argv.slice(2)) {
    try {
      console.log(JSON.stringify(await validate(file)));
    } catch (e) {
      console.log(JSON.stringify({ file, error: String(e), messages: [] }));
    }
  }
})();
