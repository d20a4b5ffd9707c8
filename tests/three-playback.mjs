// Plays a Sketchmesh animation export in three.js, as a web page would: GLTFLoader reads the
// .glb, AnimationMixer drives it, and the morph-target influences must follow the key
// frames. Checks the clip's duration and frame count and which pose shows at each key.
//
//   node tests/three-playback.mjs FILE.glb DURATION FRAMES
//
// `cargo xtask test` runs it on the CLI replay of tests/fixtures/animation-three-keys.json
// (keys at 0, 1 and 2 s; 12 in-betweens a second: 25 frames). Exit code 1 on a mismatch.

import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

import { AnimationMixer, LoopOnce } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const [file, duration, frames] = process.argv.slice(2);
if (!file || !duration || !frames) {
  console.error('usage: node tests/three-playback.mjs FILE.glb DURATION FRAMES');
  process.exit(2);
}
const bytes = readFileSync(file);
const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
const gltf = await new GLTFLoader().parseAsync(buffer, '');

assert.equal(gltf.animations.length, 1, 'one animation');
const clip = gltf.animations[0];
assert.ok(Math.abs(clip.duration - Number(duration)) < 1e-6, `duration ${clip.duration}`);
const track = clip.tracks.find((t) => t.name.endsWith('.morphTargetInfluences'));
assert.ok(track, `a morph-target track among ${clip.tracks.map((t) => t.name)}`);
assert.equal(track.times.length, Number(frames), 'frame count');

let mesh;
gltf.scene.traverse((object) => {
  if (object.isMesh && object.morphTargetInfluences) mesh = object;
});
assert.ok(mesh, 'a morphed mesh');
assert.equal(mesh.morphTargetInfluences.length, Number(frames), 'one target per frame');

// Played through the mixer: at each frame's time, that frame's target alone shows.
const mixer = new AnimationMixer(gltf.scene);
const action = mixer.clipAction(clip);
// Played once and held at the end, so the last frame shows at the clip's end, not the first.
action.setLoop(LoopOnce, 1);
action.clampWhenFinished = true;
action.play();
let elapsed = 0;
for (const [k, time] of track.times.entries()) {
  mixer.update(time - elapsed);
  elapsed = time;
  const influences = mesh.morphTargetInfluences;
  const shown = influences.indexOf(Math.max(...influences));
  assert.equal(shown, k, `at ${time} s target ${shown} shows, not ${k}`);
  assert.ok(Math.abs(influences[k] - 1) < 1e-4, `target ${k} at ${influences[k]}`);
}
console.log(`ok   ${file}: three.js plays ${clip.duration} s, ${track.times.length} frames`);
