// Makes the examples the documents panel offers (web/examples/): each one drawn with a pen in
// the real page, its session (every stroke with the samples the page recorded) and a
// thumbnail written beside the page. Run against a built page:
//
//   SKETCHMESH_URL=http://127.0.0.1:8080/ node tests/e2e/make-examples.mjs [name ...]
//
// The strokes are a person's: each wobbles a little and its pressure rises and falls. The
// scan is made here too (a noisy, bumpy capsule standing in for a 3D scan: no scan of a real
// object is shipped), imported as a `.glb`, so its session carries it.

import { writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { api, frames, launch, line, openApp, penStroke, screenshot, settings, sleep } from './lib.mjs';

const EXAMPLES = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'web', 'examples');

/** A deterministic pseudo-random number in [-1, 1) (the same examples every run). */
function noise(seed) {
  let state = seed >>> 0;
  return () => {
    state = (state * 1664525 + 1013904223) >>> 0;
    return state / 2 ** 31 - 1;
  };
}

/** `points` drawn by hand: a wobble of about a pixel, pressure rising then falling. */
function byHand(points, seed) {
  const wobble = noise(seed);
  let dx = 0;
  let dy = 0;
  return points.map((p, i) => {
    dx = 0.7 * dx + 0.6 * wobble();
    dy = 0.7 * dy + 0.6 * wobble();
    const t = i / Math.max(1, points.length - 1);
    return { x: p.x + dx, y: p.y + dy, force: 0.35 + 0.4 * Math.sin(Math.PI * Math.min(1, 0.15 + t)) };
  });
}

/** An arc of the ellipse at `c` with radii `rx`, `ry`, from angle `a0` to `a1` (radians, y down). */
function arc(c, rx, ry, a0, a1, n) {
  return Array.from({ length: n + 1 }, (_, i) => {
    const a = a0 + ((a1 - a0) * i) / n;
    return { x: c.x + rx * Math.cos(a), y: c.y + ry * Math.sin(a) };
  });
}

/** The last op of the session. */
const lastOp = (page) => api(page, 'session').then((json) => JSON.parse(json).ops.at(-1) ?? {});

/** Waits until the session's last op is `name` and nothing is computing. */
async function landed(page, name, count) {
  const until = Date.now() + 30_000;
  for (;;) {
    const ops = JSON.parse(await api(page, 'session')).ops;
    if (ops.length === count && ops.at(-1)?.op === name && (await api(page, 'progress')) === null) return;
    if (Date.now() > until) await screenshot(page, '/tmp/example-failed.png');
    if (Date.now() > until) throw new Error(`no ${name} op landed as op ${count}: ${ops.map((o) => o.op).join(', ')}`);
    await sleep(100);
  }
}

/** A pen drag from `from` to `to` over `n` steps (a dot, a region), held down throughout. */
async function drag(cdp, points) {
  await penStroke(cdp, points.map((p) => ({ ...p, force: 0.5 })), 30);
}

/** The bounds of the light pixels (the lit models) of a screenshot, between the hint line and
 * the status line. */
function modelBounds(image, top = 150) {
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let y = top; y < image.height - 70; y++) {
    for (let x = 0; x < image.width; x++) {
      const k = (y * image.width + x) * 4;
      const [r, g, b] = image.data.slice(k, k + 3);
      if (r > 150 && g > 150 && b > 140) {
        x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
      }
    }
  }
  return { x0, y0, x1, y1, cx: (x0 + x1) / 2, cy: (y0 + y1) / 2 };
}

// The pose tool's Key button, in the toolbar's second row at 1280 px (as run.mjs has it).
const POSE_KEY = { x: 206, y: 71 };

/** A gingerbread figure: a body and a head from two outlines, two arms and two legs extruded,
 * the right hand pulled up to wave. */
async function character({ page, cdp }) {
  const body = { x: 640, y: 450 };
  let ops = 0;
  await penStroke(cdp, byHand(arc(body, 95, 125, -Math.PI / 2, 1.5 * Math.PI + 0.08, 64), 1));
  await landed(page, 'create', ++ops);
  // Each limb: a loop on the body near its outline, then its outline from near one side of
  // the loop out and back to near the other.
  const limb = async (base, radius, out, seed) => {
    await penStroke(cdp, byHand(arc(base, radius, radius, 0, 2 * Math.PI, 36), seed));
    await frames(page, 2);
    await penStroke(cdp, byHand(out, seed + 1));
    await landed(page, 'extrude', ++ops);
  };
  // The head: a second outline above the body, begun off it (so it makes a shape).
  await penStroke(cdp, byHand(arc({ x: 640, y: 272 }, 56, 54, -Math.PI / 2, 1.5 * Math.PI + 0.08, 48), 10));
  await landed(page, 'create', ++ops);
  const side = (sign, seed) => {
    const base = { x: 640 + sign * 68, y: 420 };
    const out = Array.from({ length: 41 }, (_, i) => {
      const a = Math.PI * (i / 40 - 0.5);
      return { x: base.x + sign * 170 * Math.cos(a), y: base.y + 22 * Math.sin(a) * sign + 40 * Math.cos(a) };
    });
    return limb(base, 22, out, seed);
  };
  await side(1, 20);
  await side(-1, 30);
  const leg = (dx, seed) => {
    const base = { x: 640 + dx, y: 530 };
    const out = Array.from({ length: 41 }, (_, i) => {
      const a = Math.PI * (i / 40);
      return { x: base.x - 24 * Math.cos(a) + dx * 0.3 * Math.sin(a), y: base.y + 150 * Math.sin(a) };
    });
    return limb(base, 24, out, seed);
  };
  await leg(-38, 40);
  await leg(38, 50);
  await page.keyboard.press('p');
  // The right hand, raised: it waves.
  await drag(cdp, line({ x: 876, y: 459 }, { x: 880, y: 418 }, 14));
  await landed(page, 'pull', ++ops);
}

/** A tail made of one outline, posed with Pose and keyed three times: it wags when played. */
async function tail({ page, cdp }) {
  const c = { x: 640, y: 420 };
  let ops = 0;
  await penStroke(cdp, byHand(arc(c, 240, 48, Math.PI, 3 * Math.PI + 0.06, 72), 60));
  await landed(page, 'create', ++ops);
  await page.keyboard.press('q');
  await frames(page, 3);
  await page.mouse.click(POSE_KEY.x, POSE_KEY.y);
  await landed(page, 'keyframe', ++ops);
  await penStroke(cdp, byHand(line({ x: c.x - 215, y: c.y }, { x: c.x + 215, y: c.y }, 50), 61));
  await sleep(1500);
  await frames(page, 3);
  const pose = async (lift, seed) => {
    const bent = Array.from({ length: 51 }, (_, k) => {
      const s = k / 50;
      return { x: c.x - 200 + 400 * s, y: c.y - 80 - lift * Math.max(0, s - 0.4) ** 2 * 500 };
    });
    await penStroke(cdp, byHand(bent, seed));
    await landed(page, 'curve_deform', ++ops);
    await frames(page, 3);
    await page.mouse.click(POSE_KEY.x, POSE_KEY.y);
    await landed(page, 'keyframe', ++ops);
  };
  await pose(1, 62);
  await pose(-1, 63);
}

/** A noisy capsule standing in for a 3D scan, as a `.glb`: rings of vertices along x with
 * bumps of a few sizes, as a scanner leaves them. */
function scanGlb() {
  const rings = 30;
  const around = 22;
  const bumps = noise(7);
  const phases = Array.from({ length: 6 }, () => Math.PI * bumps());
  const positions = [[-1.75, 0, 0]];
  for (let i = 1; i < rings; i++) {
    const theta = (Math.PI * i) / rings;
    const x = -1.75 * Math.cos(theta);
    for (let j = 0; j < around; j++) {
      const phi = (2 * Math.PI * j) / around;
      const wave = 0.04 * Math.sin(3 * x + phases[0]) * Math.cos(2 * phi + phases[1]) + 0.025 * Math.sin(7 * x + 3 * phi + phases[2]);
      const rho = 0.42 * Math.sin(theta) ** 0.55 * (1 + wave + 0.025 * bumps());
      positions.push([x, rho * Math.cos(phi), rho * Math.sin(phi)]);
    }
  }
  positions.push([1.75, 0, 0]);
  const ring = (i, j) => 1 + (i - 1) * around + (((j % around) + around) % around);
  const last = positions.length - 1;
  const triangles = [];
  for (let j = 0; j < around; j++) {
    triangles.push([0, ring(1, j), ring(1, j + 1)]);
    for (let i = 1; i < rings - 1; i++) {
      triangles.push([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)], [ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)]);
    }
    triangles.push([last, ring(rings - 1, j + 1), ring(rings - 1, j)]);
  }
  // Outward: the normal points away from the axis.
  const sub = (a, b) => a.map((v, k) => v - b[k]);
  for (const t of triangles) {
    const [a, b, c] = t.map((v) => positions[v]);
    const [u, v] = [sub(b, a), sub(c, a)];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const mid = [(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3];
    const out = [mid[0] * 0.2, mid[1], mid[2]];
    if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) [t[1], t[2]] = [t[2], t[1]];
  }
  const floats = new Float32Array(positions.flat());
  const indices = new Uint16Array(triangles.flat());
  const pad = (n) => (n + 3) & ~3;
  const bin = new Uint8Array(pad(floats.byteLength) + pad(indices.byteLength));
  bin.set(new Uint8Array(floats.buffer), 0);
  bin.set(new Uint8Array(indices.buffer), pad(floats.byteLength));
  const min = [0, 1, 2].map((k) => Math.min(...positions.map((p) => Math.fround(p[k]))));
  const max = [0, 1, 2].map((k) => Math.max(...positions.map((p) => Math.fround(p[k]))));
  const json = {
    asset: { version: '2.0', generator: 'Sketchmesh examples (tests/e2e/make-examples.mjs)' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, name: 'scan' }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    buffers: [{ byteLength: bin.byteLength }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: floats.byteLength, target: 34962 },
      { buffer: 0, byteOffset: pad(floats.byteLength), byteLength: indices.byteLength, target: 34963 },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: positions.length, type: 'VEC3', min, max },
      { bufferView: 1, componentType: 5123, count: indices.length, type: 'SCALAR' },
    ],
  };
  let text = JSON.stringify(json);
  while (text.length % 4) text += ' ';
  const header = new DataView(new ArrayBuffer(12));
  const total = 12 + 8 + text.length + 8 + bin.byteLength;
  header.setUint32(0, 0x46546c67, true);
  header.setUint32(4, 2, true);
  header.setUint32(8, total, true);
  const chunk = (type, bytes) => {
    const head = new DataView(new ArrayBuffer(8));
    head.setUint32(0, bytes.byteLength, true);
    head.setUint32(4, type, true);
    return [new Uint8Array(head.buffer), bytes];
  };
  const parts = [new Uint8Array(header.buffer), ...chunk(0x4e4f534a, new TextEncoder().encode(text)), ...chunk(0x004e4942, bin)];
  return Buffer.concat(parts);
}

/** A scan bent with Bend (a curve handle along it, its end dot dragged up) and a region of it
 * lifted with Region. */
async function scan({ page, cdp }) {
  const glb = scanGlb();
  await page.evaluate((bytes) => window.sketchmesh.loadGlb(new Uint8Array(bytes), 'scan.glb'), Array.from(glb));
  let ops = 1;
  await frames(page, 6);
  const seen = modelBounds(await screenshot(page, '/tmp/scan-imported.png'));
  const { cx, cy, x0, x1 } = seen;
  await page.keyboard.press('j');
  await frames(page, 2);
  const from = { x: x0 + 30, y: cy };
  const to = { x: x1 - 30, y: cy };
  await penStroke(cdp, byHand(line(from, to, 50), 70));
  await landed(page, 'curve_handle', ++ops);
  await frames(page, 3);
  await drag(cdp, line(to, { x: to.x - 20, y: to.y - 110 }, 16));
  await landed(page, 'handle_edit', ++ops);
  await frames(page, 3);
  const bent = modelBounds(await screenshot(page, '/tmp/scan-bent.png'));
  await page.keyboard.press('l');
  await frames(page, 2);
  const mid = { x: cx - 40, y: bent.y1 - (cy - seen.y0) };
  await penStroke(cdp, byHand(line({ x: mid.x - 55, y: mid.y }, { x: mid.x + 55, y: mid.y }, 24), 71));
  await penStroke(cdp, byHand(arc(mid, 105, 70, 0, 2 * Math.PI, 48), 72));
  await frames(page, 3);
  await drag(cdp, line({ x: mid.x, y: mid.y - 5 }, { x: mid.x, y: mid.y - 45 }, 12));
  await landed(page, 'region_edit', ++ops);
}

const MAKERS = { character, tail, scan };

const { url, gpu } = settings();
const wanted = process.argv.slice(2).length ? process.argv.slice(2) : Object.keys(MAKERS);
const browser = await launch(gpu);
try {
  for (const name of wanted) {
    const fresh = await openApp(browser, url, gpu);
    try {
      await MAKERS[name](fresh);
      await frames(fresh.page, 6);
      await screenshot(fresh.page, `/tmp/example-${name}.png`);
      const session = await api(fresh.page, 'session');
      writeFileSync(join(EXAMPLES, `${name}.json`), session);
      const png = await fresh.page.evaluate(async () => {
        const { width, height, pixels } = await window.sketchmesh.thumbnail();
        const canvas = document.createElement('canvas');
        canvas.width = width;
        canvas.height = height;
        canvas.getContext('2d').putImageData(new ImageData(pixels, width, height), 0, 0);
        return canvas.toDataURL('image/png');
      });
      writeFileSync(join(EXAMPLES, `${name}.png`), Buffer.from(png.split(',')[1], 'base64'));
      console.log(`${name}: ${JSON.parse(session).ops.map((o) => o.op).join(', ')} (${session.length} bytes)`);
      if (fresh.errors.length) console.log(`  errors: ${fresh.errors.join('; ')}`);
    } finally {
      await fresh.context.close();
    }
  }
} finally {
  await browser.close();
}
