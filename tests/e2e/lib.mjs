// Shared helpers for the browser suite and the page benchmark: Chromium launch flags per GPU path,
// opening the app, synthetic pen and touch input over CDP, and screenshot pixel checks.
//
// Flags: /work/shared/toolchain.md §5. With the base flags Chromium has WebGL2 (SwiftShader) and no
// WebGPU adapter, so eframe falls back to WebGL2. The WebGPU set gives a SwiftShader WebGPU adapter
// whose canvas shows up in screenshots; all five flags are needed, and WebGL2 is gone with them.

import { mkdirSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import { dirname, extname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

import { chromium } from 'playwright-core';
import pngjs from 'pngjs';

export const CHROMIUM = '/usr/bin/chromium';
export const BASE_FLAGS = [
  '--no-sandbox',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];
export const GPU_FLAGS = {
  webgl2: [],
  webgpu: [
    '--enable-unsafe-webgpu',
    '--enable-features=Vulkan',
    '--use-angle=vulkan',
    '--use-vulkan=swiftshader',
    '--disable-vulkan-fallback-to-gl-for-testing',
  ],
};
// What `window.sketchmesh.backend()` must say on each path.
export const EXPECTED_BACKEND = { webgl2: /^WebGL/i, webgpu: /^WebGPU/i };

export const OUT_DIR = join(dirname(fileURLToPath(import.meta.url)), '..', 'out');

/** The run's settings from the environment: SKETCHMESH_URL and SKETCHMESH_GPU (webgl2|webgpu). */
export function settings() {
  const url = process.env.SKETCHMESH_URL ?? 'http://127.0.0.1:8080/';
  const gpu = process.env.SKETCHMESH_GPU ?? 'webgl2';
  if (!(gpu in GPU_FLAGS)) {
    throw new Error(`SKETCHMESH_GPU must be one of ${Object.keys(GPU_FLAGS).join(', ')}, got ${gpu}`);
  }
  mkdirSync(OUT_DIR, { recursive: true });
  return { url, gpu };
}

/**
 * Launches headless Chromium for `gpu`. `deviceScaleFactor` > 1 also forces it on the browser:
 * with only Playwright's emulated scale factor, headless Chromium reports `devicePixelRatio` 2 but a
 * `devicePixelContentBoxSize` in CSS px, which eframe trusts for the canvas size.
 */
export async function launch(gpu, { deviceScaleFactor = 1 } = {}) {
  const scale = deviceScaleFactor === 1 ? [] : [`--force-device-scale-factor=${deviceScaleFactor}`];
  return chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: [...BASE_FLAGS, ...GPU_FLAGS[gpu], ...scale],
  });
}

/** Console messages that are expected and harmless. */
function isHarmless(gpu, text, url) {
  // eframe asks for WebGPU first and logs this before falling back to WebGL2.
  if (gpu === 'webgl2' && text.includes('No available adapters.')) return true;
  if (/favicon/.test(url) && /404|Failed to load resource/.test(text)) return true;
  return false;
}

/**
 * Opens the app in a new context and waits until `window.sketchmesh` exists and a frame has been
 * drawn. Returns `{ context, page, cdp, errors }`; `errors` collects console errors and uncaught
 * exceptions (harmless ones filtered out) for the whole life of the page. A page that does not
 * start has its context closed. The first visit's introduction is marked seen unless `intro`.
 * The Symmetry switch, on for a new visitor, is left off unless `symmetry`: the cases written
 * before it change one side only.
 */
export async function openApp(
  browser, url, gpu,
  { width = 1280, height = 720, deviceScaleFactor = 1, intro = false, isMobile = false, symmetry = false } = {},
) {
  const context = await browser.newContext({
    viewport: { width, height },
    deviceScaleFactor,
    hasTouch: true,
    isMobile,
  });
  // On every document the context opens; one without storage (about:blank, a data: URL a
  // case navigates to) has none to mark.
  if (!intro) {
    await context.addInitScript(() => {
      try {
        localStorage.setItem('sketchmesh.intro', 'seen');
      } catch {
        // No storage here: nothing to introduce either.
      }
    });
  }
  if (!symmetry) {
    await context.addInitScript(() => {
      try {
        localStorage.setItem('sketchmesh.symmetry', 'off');
      } catch {
        // No storage here: no app either.
      }
    });
  }
  const page = await context.newPage();
  const errors = [];
  page.on('console', (msg) => {
    if (msg.type() !== 'error') return;
    const where = msg.location()?.url ?? '';
    if (!isHarmless(gpu, msg.text(), where)) errors.push(`console.error: ${msg.text()} (${where})`);
  });
  page.on('pageerror', (err) => errors.push(`uncaught: ${err.message}`));
  page.on('crash', () => errors.push('the page crashed'));
  try {
    const cdp = await context.newCDPSession(page);
    const started = Date.now();
    await page.goto(url, { waitUntil: 'load' });
    try {
      await page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
    } catch {
      const loading = await page.locator('#loading').textContent().catch(() => null);
      throw new Error(
        `window.sketchmesh did not appear within 15 s; page says ${JSON.stringify(loading)}; ` +
          `errors: ${JSON.stringify(errors)}`,
      );
    }
    await frames(page, 2);
    return { context, page, cdp, errors, startupMs: Date.now() - started };
  } catch (err) {
    await context.close();
    throw err;
  }
}

/** Content types of the page's files, for `serveDirectory`. */
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.wasm': 'application/wasm',
  '.json': 'application/json', '.webmanifest': 'application/manifest+json', '.svg': 'image/svg+xml',
  '.png': 'image/png',
};

/**
 * Serves the files of `dir` on a free port of 127.0.0.1 (a server a test can stop, as the
 * offline case does). Returns `{ url, close }`; `close` drops open connections too.
 */
export async function serveDirectory(root) {
  const dir = resolve(root);
  const server = createServer(async (request, response) => {
    const path = new URL(request.url, 'http://x').pathname;
    const file = join(dir, path.endsWith('/') ? `${path}index.html` : path);
    if (!file.startsWith(dir)) return response.writeHead(404).end();
    try {
      const body = await readFile(file);
      response.writeHead(200, { 'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream', 'Cache-Control': 'no-cache' });
      response.end(body);
    } catch {
      response.writeHead(404).end();
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  let closed = false;
  return {
    url: `http://127.0.0.1:${server.address().port}/`,
    close: () => {
      if (closed) return Promise.resolve();
      closed = true;
      server.closeAllConnections();
      return new Promise((resolve) => server.close(() => resolve()));
    },
  };
}

/** Waits for `n` animation frames in the page, then a short pause for the compositor. */
export async function frames(page, n = 2, settleMs = 50) {
  await page.evaluate(
    (count) =>
      new Promise((resolve) => {
        const step = (left) => (left === 0 ? resolve() : requestAnimationFrame(() => step(left - 1)));
        step(count);
      }),
    n,
  );
  if (settleMs > 0) await page.waitForTimeout(settleMs);
}

export const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/**
 * Records every animation frame's interval in `page` (a frame the page could not draw shows
 * as a long one) in `window.__frames.list`; returns `record(on)`, which starts a fresh
 * recording (`true`) or stops it (`false`), and gives the longest interval so far.
 *
 * A recording also stops at the first frame in which `window.__frames.stopWhen()` holds: the
 * app landed a result in this frame or the last (its frame callback may run before or after
 * this one). The intervals of this frame and the next, one of which holds the landing, stay
 * out of the list; the longer is `window.__frames.landing`, and `window.__frames.stoppedAt`
 * is when the last of them began (the page's clock): what ended before it came before the
 * landing.
 */
export async function recordFrames(page) {
  await page.evaluate(() => {
    window.__frames = { on: false, list: [], stopWhen: null, landing: null };
    let last = performance.now();
    let landingTicks = 0;
    const tick = (t) => {
      const f = window.__frames;
      if (f.on && f.stopWhen?.()) {
        f.on = false;
        f.stopWhen = null;
        f.landing = 0;
        f.stoppedAt = last;
        landingTicks = 2;
      }
      if (landingTicks > 0) {
        f.landing = Math.max(f.landing, t - last);
        landingTicks--;
      }
      if (f.on) f.list.push(t - last);
      last = t;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  return (on) => page.evaluate((on) => {
    const f = window.__frames;
    f.on = on;
    if (on) f.list = [];
    return Math.max(0, ...f.list);
  }, on);
}

/** Calls a `window.sketchmesh` method in the page. */
export function api(page, method, ...args) {
  return page.evaluate(([m, a]) => window.sketchmesh[m](...a), [method, args]);
}

export async function camera(page) {
  return api(page, 'camera');
}

export function cameraDistance(cam) {
  const d = cam.eye.map((e, i) => e - cam.target[i]);
  return Math.hypot(...d);
}

/**
 * A function sending one pen event of `type` (mousePressed, mouseMoved, mouseReleased) at
 * (x, y) with `buttons` and half pressure via CDP: for drags paced by the test.
 */
export function penSender(cdp) {
  return (type, x, y, buttons) => cdp.send('Input.dispatchMouseEvent', {
    type, x, y, buttons, clickCount: 1, force: 0.5, pointerType: 'pen', button: 'left',
  });
}

/**
 * A pen stroke through `points` ([{x, y, force}] in CSS px) via CDP, one event per `gapMs` so that
 * the moves land in different frames (back-to-back events collapse into one egui frame).
 */
export async function penStroke(cdp, points, gapMs = 20) {
  const pen = { pointerType: 'pen', button: 'left', tiltX: 15, tiltY: -10 };
  const [first, ...rest] = points;
  await cdp.send('Input.dispatchMouseEvent', {
    type: 'mousePressed', x: first.x, y: first.y, buttons: 1, clickCount: 1, force: first.force, ...pen,
  });
  for (const p of rest) {
    await sleep(gapMs);
    await cdp.send('Input.dispatchMouseEvent', {
      type: 'mouseMoved', x: p.x, y: p.y, buttons: 1, force: p.force, ...pen,
    });
  }
  await sleep(gapMs);
  const last = points[points.length - 1];
  await cdp.send('Input.dispatchMouseEvent', {
    type: 'mouseReleased', x: last.x, y: last.y, buttons: 0, clickCount: 1, force: 0, ...pen,
  });
}

/**
 * A touch gesture via CDP: `tracks` is one array of {x, y} per finger, all the same length; the
 * fingers go down at their first points, move together step by step and lift at the end.
 */
export async function touchGesture(cdp, tracks, gapMs = 30) {
  const at = (step) =>
    tracks.map((track, id) => ({ x: track[step].x, y: track[step].y, id, radiusX: 8, radiusY: 8, force: 0.5 }));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  for (let step = 1; step < tracks[0].length; step++) {
    await sleep(gapMs);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(step) });
  }
  await sleep(gapMs);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

/**
 * A touch tap via CDP: every finger down at its point together, and up `ms` later, with the
 * events stamped at those times (as a touch screen stamps them), so a busy frame that delays
 * their delivery does not make the tap look long. `down` (seconds, `Date.now()` based) sets
 * when the fingers go down, for taps that must lie a given time apart.
 */
export async function touchTap(cdp, points, ms = 60, down = Date.now() / 1000) {
  const touchPoints = points.map((p, id) => ({ x: p.x, y: p.y, id, radiusX: 8, radiusY: 8, force: 0.5 }));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints, timestamp: down });
  await sleep(ms);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [], timestamp: down + ms / 1000 });
}

/** `n + 1` evenly spaced points from `a` to `b`. */
export function line(a, b, n) {
  return Array.from({ length: n + 1 }, (_, i) => ({
    x: a.x + ((b.x - a.x) * i) / n,
    y: a.y + ((b.y - a.y) * i) / n,
  }));
}

/** A page screenshot of the viewport in CSS pixels, decoded to `{ width, height, data }` (RGBA). */
export async function screenshot(page, file, { scale = 'css' } = {}) {
  const png = await page.screenshot({ path: file, scale });
  return pngjs.PNG.sync.read(png);
}

/** Number of distinct colours (each channel quantised to 5 bits) in `image`. */
export function distinctColours(image) {
  const seen = new Set();
  const { data } = image;
  for (let i = 0; i < data.length; i += 4) {
    seen.add(((data[i] >> 3) << 10) | ((data[i + 1] >> 3) << 5) | (data[i + 2] >> 3));
  }
  return seen.size;
}

/** The fraction of pixels that differ from the most common colour by more than `tolerance`. */
export function nonBackgroundFraction(image, tolerance = 24) {
  const counts = new Map();
  const { data } = image;
  for (let i = 0; i < data.length; i += 4) {
    const key = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    counts.set(key, (counts.get(key) ?? 0) + 1);
  }
  const background = [...counts.entries()].reduce((a, b) => (b[1] > a[1] ? b : a))[0];
  const bg = [(background >> 16) & 255, (background >> 8) & 255, background & 255];
  let other = 0;
  for (let i = 0; i < data.length; i += 4) {
    const diff = Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]);
    if (diff > tolerance) other++;
  }
  return other / (data.length / 4);
}

function pixelDiff(a, b, x, y) {
  const i = (y * a.width + x) * 4;
  return Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) + Math.abs(a.data[i + 2] - b.data[i + 2]);
}

/** The largest RGB difference (sum over channels) between `a` and `b` in a square around (x, y). */
export function maxDiffNear(a, b, x, y, radius) {
  let max = 0;
  const cx = Math.round(x);
  const cy = Math.round(y);
  for (let py = Math.max(0, cy - radius); py <= Math.min(a.height - 1, cy + radius); py++) {
    for (let px = Math.max(0, cx - radius); px <= Math.min(a.width - 1, cx + radius); px++) {
      max = Math.max(max, pixelDiff(a, b, px, py));
    }
  }
  return max;
}

/** The fraction of `points` near which `a` and `b` differ by more than `threshold`. */
export function changedFraction(a, b, points, { radius = 3, threshold = 60 } = {}) {
  const changed = points.filter((p) => maxDiffNear(a, b, p.x, p.y, radius) > threshold).length;
  return changed / points.length;
}

/**
 * The fraction of pixels in the image from row `fromY` down that differ by more than
 * `threshold` (from a row below the toolbar and the hint line, which say which tool is in use,
 * to compare only what the view shows).
 */
export function imageChangedFraction(a, b, threshold = 60, { fromY = 0 } = {}) {
  let changed = 0;
  for (let y = fromY; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) if (pixelDiff(a, b, x, y) > threshold) changed++;
  }
  return changed / (a.width * (a.height - fromY));
}

/**
 * Page script defining `window.gridGlb(n)`: a .glb of an n x n grid of squares (2 n² triangles,
 * positions and u32 indices; 708 gives a million triangles), built in the page so the test sends
 * no 24 MB file over CDP. Run it with `page.evaluate(GRID_GLB_SOURCE)`.
 */
export const GRID_GLB_SOURCE = `
window.gridGlb = (n) => {
  const nv = (n + 1) * (n + 1);
  const positions = new Float32Array(nv * 3);
  for (let j = 0; j <= n; j++) {
    for (let i = 0; i <= n; i++) {
      const k = 3 * (j * (n + 1) + i);
      positions[k] = i / n;
      positions[k + 1] = j / n;
      positions[k + 2] = 0.05 * Math.sin(10 * i / n) * Math.cos(7 * j / n);
    }
  }
  const indices = new Uint32Array(6 * n * n);
  let t = 0;
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i;
      indices.set([a, a + 1, a + n + 2, a, a + n + 2, a + n + 1], t);
      t += 6;
    }
  }
  const bin = new Uint8Array(positions.byteLength + indices.byteLength);
  bin.set(new Uint8Array(positions.buffer), 0);
  bin.set(new Uint8Array(indices.buffer), positions.byteLength);
  const json = JSON.stringify({
    asset: { version: '2.0' }, scene: 0, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: nv, type: 'VEC3', min: [0, 0, -0.05], max: [1, 1, 0.05] },
      { bufferView: 1, componentType: 5125, count: indices.length, type: 'SCALAR' },
    ],
    bufferViews: [
      { buffer: 0, byteLength: positions.byteLength },
      { buffer: 0, byteOffset: positions.byteLength, byteLength: indices.byteLength },
    ],
    buffers: [{ byteLength: bin.byteLength }],
  });
  let jsonBytes = new TextEncoder().encode(json);
  const padded = new Uint8Array(Math.ceil(jsonBytes.length / 4) * 4).fill(32);
  padded.set(jsonBytes);
  jsonBytes = padded;
  const total = 12 + 8 + jsonBytes.length + 8 + bin.length;
  const glb = new Uint8Array(total);
  const view = new DataView(glb.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonBytes.length, true);
  view.setUint32(16, 0x4e4f534a, true);
  glb.set(jsonBytes, 20);
  view.setUint32(20 + jsonBytes.length, bin.length, true);
  view.setUint32(24 + jsonBytes.length, 0x004e4942, true);
  glb.set(bin, 28 + jsonBytes.length);
  return glb;
};
`;
