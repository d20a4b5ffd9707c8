// Runs the Khronos glTF validator (npm gltf-validator) on each file given; prints the issues and
// exits 1 if any file has an error or a warning (infos and hints are printed, not failures).
//
//   node tests/validate-gltf.mjs tests/out/*.glb

import { readFileSync } from 'node:fs';
import { basename } from 'node:path';

import validator from 'gltf-validator';

const SEVERITY = ['error', 'warning', 'info', 'hint'];

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node tests/validate-gltf.mjs <file.glb>...');
  process.exit(2);
}

let bad = 0;
for (const file of files) {
  let report;
  try {
    report = await validator.validateBytes(new Uint8Array(readFileSync(file)), {
      uri: basename(file),
      maxIssues: 100,
      // A .glb must be self-contained.
      externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri} in ${file}`)),
    });
  } catch (err) {
    console.log(`FAIL ${file}: the validator could not read it: ${err}`);
    bad++;
    continue;
  }
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  const info = report.info ?? {};
  const ok = numErrors === 0 && numWarnings === 0;
  if (!ok) bad++;
  console.log(
    `${ok ? 'ok  ' : 'FAIL'} ${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ` +
      `${numHints} hints; ${info.drawCallCount ?? 0} draw calls, ${info.totalVertexCount ?? 0} vertices, ` +
      `${info.totalTriangleCount ?? 0} triangles (generator: ${info.generator ?? 'none'})`,
  );
  for (const m of messages) {
    console.log(`       ${SEVERITY[m.severity] ?? m.severity} ${m.code} at ${m.pointer ?? m.offset ?? '?'}: ${m.message}`);
  }
}
process.exit(bad === 0 ? 0 : 1);
