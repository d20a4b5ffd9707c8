// Reads Sketchmesh's STL and OBJ exports with three.js's own loaders (STLLoader, OBJLoader),
// readers other than ours, and checks each against the glTF it was made from (read with
// GLTFLoader): the same number of triangles, the same bounding box in the file's unit, and
// (when expected) watertight: after welding equal positions, every undirected edge is shared
// by exactly two triangles.
//
//   node tests/check-exports.mjs CASES.json
//
// CASES.json (written by `cargo xtask test` beside the files) is a list of
//   { "source": "x.glb", "watertight": true,
//     "files": [{ "path": "x.stl", "per_metre": 1000 }, { "path": "x.obj", "per_metre": 1 }] }
// with paths relative to the working directory. Exit code 1 on a mismatch, 2 on bad usage.

import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { extname } from 'node:path';

import { Box3, Mesh, Vector3 } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';

const [casesFile] = process.argv.slice(2);
if (!casesFile) {
  console.error('usage: node tests/check-exports.mjs CASES.json');
  process.exit(2);
}
const cases = JSON.parse(readFileSync(casesFile, 'utf8'));

function arrayBuffer(path) {
  const bytes = readFileSync(path);
  return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
}

// Every triangle of an object tree as world-space corner triples [x, y, z] (9 numbers each).
function triangles(root) {
  root.updateMatrixWorld(true);
  const out = [];
  const p = new Vector3();
  root.traverse((object) => {
    if (!object.isMesh) return;
    const geometry = object.geometry;
    const position = geometry.attributes.position;
    const index = geometry.index;
    const count = index ? index.count : position.count;
    for (let k = 0; k < count; k++) {
      p.fromBufferAttribute(position, index ? index.getX(k) : k).applyMatrix4(object.matrixWorld);
      out.push(p.x, p.y, p.z);
    }
  });
  return out;
}

function bounds(corners) {
  const box = new Box3();
  const p = new Vector3();
  for (let i = 0; i < corners.length; i += 3) box.expandByPoint(p.set(corners[i], corners[i + 1], corners[i + 2]));
  return box;
}

// Edges not shared by exactly two triangles, after welding equal positions.
function openEdges(corners) {
  const ids = new Map();
  const id = (i) => {
    const key = `${corners[i]},${corners[i + 1]},${corners[i + 2]}`;
    if (!ids.has(key)) ids.set(key, ids.size);
    return ids.get(key);
  };
  const edges = new Map();
  for (let t = 0; t < corners.length; t += 9) {
    const v = [id(t), id(t + 3), id(t + 6)];
    for (let k = 0; k < 3; k++) {
      const [a, b] = [v[k], v[(k + 1) % 3]];
      const key = a < b ? `${a}-${b}` : `${b}-${a}`;
      edges.set(key, (edges.get(key) ?? 0) + 1);
    }
  }
  let bad = 0;
  for (const n of edges.values()) if (n !== 2) bad++;
  return { bad, edges: edges.size };
}

function read(path) {
  switch (extname(path).toLowerCase()) {
    case '.stl':
      return triangles(new Mesh(new STLLoader().parse(arrayBuffer(path))));
    case '.obj':
      return triangles(new OBJLoader().parse(readFileSync(path, 'utf8')));
    default:
      throw new Error(`no reader for ${path}`);
  }
}

let bad = 0;
for (const c of cases) {
  const gltf = await new GLTFLoader().parseAsync(arrayBuffer(c.source), '');
  const source = triangles(gltf.scene);
  const expected = bounds(source);
  for (const file of c.files) {
    try {
      const corners = read(file.path);
      const n = corners.length / 9;
      assert.equal(n, source.length / 9, `${file.path}: triangles`);
      const box = bounds(corners);
      const size = expected.getSize(new Vector3()).length() * file.per_metre;
      // f32 corners (STL) and six decimals (OBJ): far under a millionth of the size.
      const tolerance = 1e-5 * size;
      for (const [got, want] of [
        [box.min, expected.min],
        [box.max, expected.max],
      ]) {
        const scaled = want.clone().multiplyScalar(file.per_metre);
        assert.ok(got.distanceTo(scaled) <= tolerance, `${file.path}: bound ${got.toArray()} against ${scaled.toArray()}`);
      }
      const { bad: open, edges } = openEdges(corners);
      if (c.watertight) assert.equal(open, 0, `${file.path}: ${open} of ${edges} edges not shared by two triangles`);
      const dims = box.getSize(new Vector3()).toArray().map((x) => x.toPrecision(4)).join(' × ');
      console.log(`ok   ${file.path}: ${n} triangles, ${dims}, ${open} open edges of ${edges}`);
    } catch (error) {
      console.log(`FAIL ${error.message}`);
      bad++;
    }
  }
}
process.exit(bad === 0 ? 0 : 1);
