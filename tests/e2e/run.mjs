// The Sketchmesh browser suite: drives the real page in headless Chromium with synthetic pen,
// touch and keyboard input and checks outcomes through `window.sketchmesh` and screenshots.
//
//   SKETCHMESH_URL=http://127.0.0.1:8080/ SKETCHMESH_GPU=webgl2 node tests/e2e/run.mjs
//
// `cargo xtask test` runs it once per GPU path against its own server: WebGL2 runs every case,
// WebGPU only the cases whose outcome can differ between the paths (`gpu: true`, below).
// Screenshots and the exported .glb go to tests/out/<gpu>-*.{png,glb}. Cases run in order; most
// open a page of their own, the first ten share one as a user session would. A failure is
// reported and the later cases still run. Each case has a time limit of its own; one that
// overruns fails with its name, and the pages it may still drive are closed. Exit code 1 if any
// case failed.

import assert from 'node:assert/strict';
import { cpSync, existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

import {
  EXPECTED_BACKEND, GRID_GLB_SOURCE, OUT_DIR, api, camera, cameraDistance, changedFraction, distinctColours, frames,
  imageChangedFraction, launch, line, maxDiffNear, nonBackgroundFraction, openApp, penSender, penStroke, recordFrames,
  screenshot, serveDirectory, settings, sleep, touchGesture, touchTap,
} from './lib.mjs';

const { url, gpu } = settings();
const out = (name) => join(OUT_DIR, `${gpu}-${name}`);
/** The built page that `cargo xtask test` serves (the offline case serves it itself). */
const DIST = process.env.SKETCHMESH_DIST ?? join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'dist');

// ---------------------------------------------------------------------------------------------
// A tiny sequential runner.

/**
 * The GPU path that runs every case. The other runs only the cases declared `gpu: true`: those
 * that look at what the GPU path draws (pixels of the canvas, a thumbnail read back from it),
 * its device or adapter, or the frames it takes to draw and upload. A case that checks only
 * the document, the session, the camera, the store or the DOM has the same outcome on both:
 * the input, the core and the page's worker are the same wasm whatever draws.
 */
const EVERY_CASE_PATH = 'webgl2';
/**
 * A case's time limit unless it names its own. On this 2-core machine, loaded by other builds,
 * a case takes up to 25 s, the long ones below excepted: a machine three times as slow passes,
 * and a hung case still ends.
 */
const CASE_LIMIT_MS = 90_000;
/**
 * The limit of the cases that legitimately take long: a 40k-vertex shape or a million triangles
 * computed in the page's worker (each result waited for up to 60 s, the import tried up to three
 * times), the gesture-heavy curve tools and merge by touch, and the pose tool's (two worker
 * previews and an animation played); 30–65 s each on this machine loaded.
 */
const LONG_CASE_LIMIT_MS = 180_000;

const cases = [];
/**
 * Declares a case: `gpu` says whether its outcome can differ between the GPU paths (each case
 * says so, with a comment why), `limitMs` (optional) is its time limit.
 */
function test(name, { gpu: differs, limitMs = CASE_LIMIT_MS }, body) {
  if (typeof differs !== 'boolean') throw new Error(`the case "${name}" must say whether it runs on both GPU paths ({ gpu: true | false })`);
  cases.push({ name, differs, limitMs, body });
}

/** `SKETCHMESH_ONLY=text` runs only the cases whose names hold it (while working on them). */
const ONLY = process.env.SKETCHMESH_ONLY;

/** A case that ran past its time limit. */
class OverLimit extends Error {}

/**
 * Runs `body` within `limitMs`. Past it, rejects with an error naming the case and closes every
 * browser context then open (the case's own and any page it shares), so that nothing it still
 * does reaches the cases after it.
 */
async function withinLimit(name, limitMs, body) {
  const running = body();
  running.catch(() => {}); // Once over its limit, its own failure is no longer reported.
  let timer;
  const overrun = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new OverLimit(`the case "${name}" took longer than its limit of ${limitMs / 1000} s`)), limitMs);
  });
  try {
    await Promise.race([running, overrun]);
  } catch (err) {
    if (err instanceof OverLimit) await closeAllContexts();
    throw err;
  } finally {
    clearTimeout(timer);
  }
}

async function runAll() {
  const chosen = cases
    .map((c, index) => ({ ...c, number: index + 1 }))
    .filter((c) => (gpu === EVERY_CASE_PATH || c.differs) && (!ONLY || c.name.includes(ONLY)));
  const skipped = cases.length - cases.filter((c) => gpu === EVERY_CASE_PATH || c.differs).length;
  console.log(`# Sketchmesh browser suite: ${gpu} against ${url}: ${chosen.length} cases` +
    (skipped ? ` (${skipped} whose outcome cannot differ between the GPU paths run on ${EVERY_CASE_PATH} only)` : ''));
  const started = Date.now();
  const times = [];
  let failed = 0;
  for (const { number, name, limitMs, body } of chosen) {
    const caseStarted = Date.now();
    try {
      await withinLimit(name, limitMs, body);
      console.log(`ok ${number} - ${name} (${Date.now() - caseStarted} ms)`);
    } catch (err) {
      failed++;
      console.log(`not ok ${number} - ${name} (${Date.now() - caseStarted} ms)`);
      // An overrun's stack is the runner's timer's: its message, naming the case, says it all.
      console.log(String(err instanceof OverLimit ? err.message : err?.stack ?? err).replace(/^/gm, '    '));
    }
    times.push({ number, ms: Date.now() - caseStarted, limitMs });
  }
  const slowest = times.sort((a, b) => b.ms - a.ms).slice(0, 5)
    .map(({ number, ms, limitMs }) => `${number} ${(ms / 1000).toFixed(1)} s of ${limitMs / 1000}`);
  console.log(`# slowest cases (number, time, limit): ${slowest.join('; ')}`);
  console.log(`# ${gpu}: ${chosen.length - failed} passed, ${failed} failed in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  return failed;
}

// ---------------------------------------------------------------------------------------------
// Geometry of the gestures, in CSS px of the 1280x720 viewport (the toolbar is at the top; the
// 3D view fills the rest).

const CENTRE = { x: 660, y: 380 };

/** The toolbar's File menu button, and its Documents item once it is open. */
const FILE_MENU = { x: 28, y: 24 };
const MERGE_BUTTON = { x: 186, y: 71 };
const DOCUMENTS_ITEM = { x: 56, y: 122 };
/** The pose tool's Key, Play and Spline buttons, in the toolbar's second row; its ⋯ menu and
 * that menu's Backdrop… and No backdrop items. */
const POSE_KEY = { x: 206, y: 71 };
const POSE_PLAY = { x: 424, y: 71 };
const POSE_SPLINE = { x: 704, y: 71 };
const POSE_MORE = { x: 822, y: 71 };
const POSE_BACKDROP = { x: 850, y: 169 };
const POSE_NO_BACKDROP = { x: 850, y: 216 };
/** The sketch tool's 40k detail button, in the toolbar's second row. */
const DETAIL_40K = { x: 176, y: 71 };
/** The region tool's Handles button, in the toolbar's second row. */
const HANDLES_BUTTON = { x: 213, y: 71 };

/** The ellipse the shape tests draw: centre, radii. */
const ELLIPSE = { c: { x: 640, y: 400 }, rx: 170, ry: 120 };

/**
 * Points on the ellipse from angle `a0` to `a1` (radians, y down), `n` steps, pushed out by
 * `push(a)` px; a full turn is the closed outline that creates the shape.
 */
function onEllipse(a0 = 0, a1 = 2 * Math.PI, n = 60, push = () => 0, force = 0.6) {
  const { c, rx, ry } = ELLIPSE;
  return Array.from({ length: n + 1 }, (_, i) => {
    const a = a0 + ((a1 - a0) * i) / n;
    return { x: c.x + (rx + push(a)) * Math.cos(a), y: c.y + (ry + push(a)) * Math.sin(a), force };
  });
}

/** The last op of `page`'s session (`{}` when there is none). */
const lastOpOf = (page) => api(page, 'session').then((json) => JSON.parse(json).ops.at(-1) ?? {});

/** `page`'s document as .glb bytes. */
const glbOf = (page) => page.evaluate(() => Array.from(window.sketchmesh.exportGlb()));

/** Points every 3 px inside the shape that the ELLIPSE outline creates, as first seen. */
function insideShape() {
  const { c } = ELLIPSE;
  const inside = [];
  for (let x = c.x - 150; x <= c.x + 150; x += 3) {
    for (let y = c.y - 100; y <= c.y + 100; y += 3) {
      if (((x - c.x) / 160) ** 2 + ((y - c.y) / 110) ** 2 < 1) inside.push({ x, y });
    }
  }
  return inside;
}

/** A pen loop around the centre (most of a circle), pressure rising and falling. */
function penLoop() {
  const n = 40;
  return Array.from({ length: n + 1 }, (_, i) => {
    const t = i / n;
    const angle = 2 * Math.PI * 0.85 * t;
    return {
      x: CENTRE.x + 120 * Math.cos(angle),
      y: CENTRE.y + 100 * Math.sin(angle),
      force: 0.2 + 0.7 * Math.sin(Math.PI * t),
    };
  });
}

/** Pressures recorded for stroke `op` (samples are `[x, y, pressure]`). */
function pressures(op) {
  assert.ok(Array.isArray(op.stroke), `a stroke op has a "stroke" array: ${JSON.stringify(op).slice(0, 200)}`);
  return op.stroke.map((sample) => sample[2]);
}

function lastStrokeOp(page) {
  return page.evaluate(() => {
    const session = JSON.parse(window.sketchmesh.session());
    return { session, op: session.ops.filter((o) => o.op === 'stroke').at(-1) };
  });
}

async function expectStats(page, expected, what) {
  const stats = await api(page, 'stats');
  assert.deepEqual(stats, expected, what);
}

/** The shape that `withShape` gives, once a case has drawn it: `{ session, created }`. */
let drawnShape;

/**
 * A fresh page with the shape of the ellipse outline: runs `body({ fresh, created })` (`created`
 * the stats after the creation) and closes the page whatever happens. The first call draws the
 * outline with the pen; later ones replay the session it made, which gives the same document
 * (checked) several seconds sooner: each of the pen's 61 samples waits for a frame. A replay
 * shows no pen to the page, so a case whose touches must be those of a pen user (a finger then
 * navigates) asks for the outline drawn (`{ pen: true }`).
 */
async function withShape(body, { pen = false } = {}) {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page } = fresh;
    const replayed = drawnShape !== undefined && !pen;
    if (replayed) await page.evaluate((s) => window.sketchmesh.replay(s), drawnShape.session);
    else await penStroke(fresh.cdp, onEllipse());
    const created = await until(() => api(page, 'stats'), (s) => s.models === 1, 15_000);
    assert.equal(created.models, 1, 'the outline made a shape');
    const session = await until(() => api(page, 'session'), (s) => JSON.parse(s).ops.at(-1)?.op === 'create', 15_000);
    drawnShape ??= { session, created };
    if (replayed) assert.deepEqual(created, drawnShape.created, 'the replayed session makes the shape drawn');
    await body({ fresh, created });
  } finally {
    await fresh.context.close();
  }
}

/** The session of the autosave record of the document shown, or `null` before it is written. */
async function storedSession(page) {
  const record = await storedRecord(page);
  if (record === null) return null;
  const text = record.parts.map((part) => (typeof part === 'string' ? part : record.pieces[part.piece])).join('');
  return JSON.parse(text).session;
}

// The shown document's record as IndexedDB holds it (web/store.js): its parts, and the long
// pieces kept apart that they name; null when nothing is stored.
async function storedRecord(page) {
  const shown = (await api(page, 'documents')).find((d) => d.shown);
  if (!shown) return null;
  return page.evaluate((id) => new Promise((resolve, reject) => {
    const request = indexedDB.open('sketchmesh');
    request.onsuccess = () => {
      const transaction = request.result.transaction(['records', 'pieces']);
      const read = transaction.objectStore('records').get(id);
      const keys = transaction.objectStore('pieces').getAllKeys();
      const values = transaction.objectStore('pieces').getAll();
      transaction.oncomplete = () => {
        if (read.result == null) return resolve(null);
        const parts = typeof read.result === 'string' ? [read.result] : read.result;
        resolve({ parts, pieces: Object.fromEntries(keys.result.map((key, i) => [key, values.result[i]])) });
      };
      transaction.onerror = () => reject(transaction.error);
    };
    request.onerror = () => reject(request.error);
  }), shown.id);
}

// Counts, from now on, the strings of at least `length` characters the page writes to
// IndexedDB (read with `longWrites`).
// Opens the app in a fresh profile whose store is as version 2 of web/store.js left it, with
// `record` (a JSON text) the document shown, and checks that it restores `session`.
async function restoresFromVersion2(record, session) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  try {
    const page = await context.newPage();
    await page.goto(new URL('favicon.svg', url).href);
    await page.evaluate((record) => new Promise((resolve, reject) => {
      const request = indexedDB.open('sketchmesh', 2);
      request.onupgradeneeded = () => {
        const db = request.result;
        db.createObjectStore('autosave');
        db.createObjectStore('records');
        db.createObjectStore('documents', { keyPath: 'id' });
      };
      request.onsuccess = () => {
        const db = request.result;
        const transaction = db.transaction(['autosave', 'records', 'documents'], 'readwrite');
        transaction.objectStore('records').put(record, 'kept');
        transaction.objectStore('documents').put({ id: 'kept', name: 'Kept', created: 1, updated: 1, thumbnail: null });
        transaction.objectStore('autosave').put('kept', 'open');
        transaction.oncomplete = () => {
          db.close();
          resolve();
        };
        transaction.onerror = () => reject(transaction.error);
      };
      request.onerror = () => reject(request.error);
    }), record);
    await page.goto(url, { waitUntil: 'load' });
    await page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
    const restored = await until(() => api(page, 'session'), (s) => JSON.parse(s).ops.length > 0, 15_000);
    assert.equal(restored, session, 'a version 2 store\'s document restores');
  } finally {
    await context.close();
  }
}

async function countLongWrites(page, length) {
  await page.evaluate((length) => {
    window.longWrites = 0;
    const put = IDBObjectStore.prototype.put;
    IDBObjectStore.prototype.put = function (value, key) {
      if (typeof value === 'string' && value.length >= length) window.longWrites += 1;
      return put.call(this, value, key);
    };
  }, length);
}

/** Polls `probe` until `accept(value)` holds or `ms` pass; returns the last value. */
async function until(probe, accept, ms = 3000) {
  const deadline = Date.now() + ms;
  let value = await probe();
  while (!accept(value) && Date.now() < deadline) {
    await new Promise((resolve) => setTimeout(resolve, 50));
    value = await probe();
  }
  return value;
}

/**
 * How far the box `[lo, hi]` reaches across the view of `cam` (`{eye, target, up, fov_y_deg}`)
 * with the width/height `aspect`: the largest |x| or |y| of its corners in normalized device
 * coordinates, at most 1 when all of it is in view (Infinity when a corner is behind the eye).
 */
function viewExtent(cam, [lo, hi], aspect) {
  const sub = (a, b) => a.map((v, k) => v - b[k]);
  const dot = (a, b) => a.reduce((s, v, k) => s + v * b[k], 0);
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const unit = (a) => a.map((v) => v / Math.hypot(...a));
  const forward = unit(sub(cam.target, cam.eye));
  const right = unit(cross(forward, cam.up));
  const up = cross(right, forward);
  const tan = Math.tan((cam.fov_y_deg * Math.PI) / 360);
  let worst = 0;
  for (let corner = 0; corner < 8; corner++) {
    const p = [0, 1, 2].map((k) => ((corner >> k) & 1 ? hi[k] : lo[k]));
    const d = sub(p, cam.eye);
    const depth = dot(d, forward);
    if (depth <= 0) return Infinity;
    worst = Math.max(worst, Math.abs(dot(d, right)) / (depth * tan * aspect), Math.abs(dot(d, up)) / (depth * tan));
  }
  return worst;
}

// ---------------------------------------------------------------------------------------------

const browser = await launch(gpu);
/** The browser of the high-DPI cases (device scale factor 2, see `launch`), started by the first. */
let hiDpi;
const hiDpiBrowser = async () => {
  hiDpi ??= await launch(gpu, { deviceScaleFactor: 2 });
  return hiDpi;
};

/** Closes every open page of the suite's browsers (each within 10 s, for a hung one). */
async function closeAllContexts() {
  const contexts = [browser, hiDpi].filter(Boolean).flatMap((b) => b.contexts());
  await Promise.all(contexts.map((context) => Promise.race([context.close().catch(() => {}), sleep(10_000)])));
}

let app; // { page, cdp, errors, context }
const penPath = penLoop();
let beforePen;
let statsBeforePen;

// Both paths: the backend the page got is the path's.
test('loads without console errors; window.sketchmesh within 15 s; backend matches the GPU path', { gpu: true }, async () => {
  app = await openApp(browser, url, gpu);
  const backend = await api(app.page, 'backend');
  console.log(`    backend ${backend}, started in ${app.startupMs} ms`);
  assert.match(backend, EXPECTED_BACKEND[gpu], `backend() on the ${gpu} path`);
  const stats = await api(app.page, 'stats');
  assert.deepEqual(Object.keys(stats).sort(), ['curves', 'models', 'triangles', 'vertices']);
  assert.equal(stats.curves, 0, 'a fresh page has no curves');
  const session = JSON.parse(await api(app.page, 'session'));
  assert.equal(session.format, 'sketchmesh-session');
  assert.equal(session.version, 1);
  assert.deepEqual(session.ops, []);
  assert.deepEqual(app.errors, [], 'console errors while loading');
});

// Both paths: the pixels drawn.
test('canvas is not blank: the view and the UI render', { gpu: true }, async () => {
  const shot = await screenshot(app.page, out('load.png'));
  const colours = distinctColours(shot);
  const foreground = nonBackgroundFraction(shot);
  console.log(`    ${colours} distinct colours, ${(foreground * 100).toFixed(1)}% non-background pixels`);
  assert.ok(colours >= 24, `only ${colours} distinct colours: the canvas looks blank`);
  assert.ok(foreground > 0.005, `only ${(foreground * 100).toFixed(2)}% of pixels differ from the background`);
  const box = await app.page.evaluate(() => {
    const c = document.getElementById('sketchmesh_canvas').getBoundingClientRect();
    return { x: c.x, y: c.y, width: c.width, height: c.height };
  });
  assert.deepEqual(box, { x: 0, y: 0, width: 1280, height: 720 }, 'the canvas fills the window');
});

// WebGL2 only: a file the page serves, the same on both paths.
test('the user guide the help opens is served beside the page, with every tool', { gpu: false }, async () => {
  const guide = await app.page.evaluate(async () => {
    const response = await fetch('guide.html');
    return { status: response.status, text: await response.text() };
  });
  assert.equal(guide.status, 200, 'guide.html is served');
  assert.match(guide.text, /<title>Sketchmesh user guide<\/title>/);
  for (const tool of ['Sketch', 'Pull', 'Erase', 'Over-sketch', 'Feature', 'Region', 'Bend', 'Pose', 'Optimize', 'Arrange']) {
    assert.ok(guide.text.includes(tool), `the guide names the ${tool} tool`);
  }
});

// WebGL2 only: the camera and the document, whatever draws them.
test('touch pinch (two fingers moving apart) zooms in and draws nothing', { gpu: false }, async () => {
  const before = await camera(app.page);
  const statsBefore = await api(app.page, 'stats');
  await touchGesture(app.cdp, [
    line({ x: CENTRE.x - 60, y: CENTRE.y }, { x: CENTRE.x - 220, y: CENTRE.y }, 10),
    line({ x: CENTRE.x + 60, y: CENTRE.y }, { x: CENTRE.x + 220, y: CENTRE.y }, 10),
  ]);
  await frames(app.page, 3);
  const after = await camera(app.page);
  const [d0, d1] = [cameraDistance(before), cameraDistance(after)];
  console.log(`    camera distance ${d0.toFixed(3)} -> ${d1.toFixed(3)}`);
  assert.ok(d1 < d0 * 0.95, `camera distance went ${d0} -> ${d1}; a pinch apart must zoom in`);
  await expectStats(app.page, statsBefore, 'a pinch must not add a curve');
});

// WebGL2 only: the document.
test('before any pen, a one-finger touch drag draws a curve', { gpu: false }, async () => {
  const before = await api(app.page, 'stats');
  const track = line({ x: CENTRE.x - 250, y: CENTRE.y + 180 }, { x: CENTRE.x + 250, y: CENTRE.y + 150 }, 16);
  await touchGesture(app.cdp, [track]);
  const after = await until(() => api(app.page, 'stats'), (s) => s.curves === before.curves + 1);
  assert.equal(after.curves, before.curves + 1, 'one-finger touch with no pen seen adds one curve');
  await screenshot(app.page, out('touch-draw.png'));
});

// Both paths: the ink on screen.
test('a pen stroke with pressure leaves ink, adds one curve and logs pressures', { gpu: true }, async () => {
  await frames(app.page, 2);
  statsBeforePen = await api(app.page, 'stats');
  beforePen = await screenshot(app.page, out('pen-before.png'));
  await penStroke(app.cdp, penPath);
  const stats = await until(() => api(app.page, 'stats'), (s) => s.curves === statsBeforePen.curves + 1);
  assert.equal(stats.curves, statsBeforePen.curves + 1, 'a pen stroke adds exactly one curve');
  await frames(app.page, 3);
  const afterPen = await screenshot(app.page, out('pen-after.png'));
  const inked = changedFraction(beforePen, afterPen, penPath);
  console.log(`    ${(inked * 100).toFixed(0)}% of the path shows ink; stats ${JSON.stringify(stats)}`);
  assert.ok(inked >= 0.6, `only ${(inked * 100).toFixed(0)}% of the stroke path changed on screen`);

  const { op } = await lastStrokeOp(app.page);
  assert.ok(op, 'session() has a stroke op');
  const p = pressures(op);
  assert.ok(p.length >= 10, `the stroke op has ${p.length} samples`);
  const [lo, hi] = [Math.min(...p), Math.max(...p)];
  console.log(`    ${p.length} samples, pressure ${lo.toFixed(2)}..${hi.toFixed(2)}`);
  assert.ok(hi - lo > 0.2, `pen pressures should vary (sent 0.2..0.9), got ${lo}..${hi}`);
  assert.ok(p.every((x) => x >= 0 && x <= 1), 'pressures lie in 0..1');
});

// Both paths: the pixels after an undo and a redo.
test('Ctrl+Z undoes the stroke (curves and pixels revert); Ctrl+Shift+Z redoes it', { gpu: true }, async () => {
  await app.page.keyboard.press('Control+z');
  let stats = await until(() => api(app.page, 'stats'), (s) => s.curves === statsBeforePen.curves);
  const focused = await app.page.evaluate(() => document.activeElement?.id || document.activeElement?.tagName);
  assert.deepEqual(stats, statsBeforePen, `Ctrl+Z restores the stats (focused element: ${focused})`);
  await frames(app.page, 3);
  const undone = await screenshot(app.page, out('undo.png'));
  // Along the path, the undone frame matches the frame before the stroke (small tolerance for
  // anti-aliasing), and differs from the inked one.
  const reverted = penPath.filter((p) => maxDiffNear(beforePen, undone, p.x, p.y, 2) <= 30).length / penPath.length;
  console.log(`    ${(reverted * 100).toFixed(0)}% of the path reverted`);
  assert.ok(reverted >= 0.9, `only ${(reverted * 100).toFixed(0)}% of the stroke path reverted after undo`);
  const whole = imageChangedFraction(beforePen, undone);
  assert.ok(whole < 0.01, `${(whole * 100).toFixed(2)}% of the image differs from before the stroke`);

  await app.page.keyboard.press('Control+Shift+Z');
  stats = await until(() => api(app.page, 'stats'), (s) => s.curves === statsBeforePen.curves + 1);
  assert.equal(stats.curves, statsBeforePen.curves + 1, 'Ctrl+Shift+Z redoes the stroke');
  await frames(app.page, 3);
  const redone = await screenshot(app.page, out('redo.png'));
  const inked = changedFraction(beforePen, redone, penPath);
  assert.ok(inked >= 0.6, `after redo only ${(inked * 100).toFixed(0)}% of the path shows ink`);
});

// WebGL2 only: the camera and the document.
test('after a pen was seen, a one-finger touch drag orbits and does not draw (palm rejection)', { gpu: false }, async () => {
  const before = await api(app.page, 'stats');
  const cam0 = await camera(app.page);
  await touchGesture(app.cdp, [line({ x: CENTRE.x - 150, y: CENTRE.y + 40 }, { x: CENTRE.x + 150, y: CENTRE.y }, 12)]);
  await frames(app.page, 3);
  await expectStats(app.page, before, 'a touch after a pen must not draw');
  const cam1 = await camera(app.page);
  const moved = Math.hypot(...cam1.eye.map((e, i) => e - cam0.eye[i]));
  console.log(`    eye moved by ${moved.toFixed(3)}`);
  assert.ok(moved > 1e-3, `the one-finger drag should orbit: eye ${cam0.eye} -> ${cam1.eye}`);
  await screenshot(app.page, out('orbit.png'));
});

// WebGL2 only: the core writes the file from the document, not from what is drawn.
test('exportGlb() returns a GLB (glTF magic, version 2, consistent length)', { gpu: false }, async () => {
  const bytes = Buffer.from(await app.page.evaluate(() => Array.from(window.sketchmesh.exportGlb())));
  assert.ok(bytes.length >= 12, `only ${bytes.length} bytes`);
  assert.equal(bytes.subarray(0, 4).toString('latin1'), 'glTF');
  assert.equal(bytes.readUInt32LE(4), 2, 'GLB version');
  assert.equal(bytes.readUInt32LE(8), bytes.length, 'GLB header length equals the byte count');
  writeFileSync(out('export.glb'), bytes);
  console.log(`    ${bytes.length} bytes -> ${out('export.glb')}`);
});

// WebGL2 only: the document and the API's answers.
test('replay(session()) reproduces the stats; malformed JSON is refused (the Promise rejects) and changes nothing', { gpu: false }, async () => {
  const stats = await api(app.page, 'stats');
  const session = await api(app.page, 'session');
  assert.ok(stats.curves >= 2, 'the session has strokes to replay');
  const returnedMs = await app.page.evaluate(async (s) => {
    const started = performance.now();
    const replayed = window.sketchmesh.replay(s);
    const ms = performance.now() - started;
    await replayed;
    return ms;
  }, session);
  assert.ok(returnedMs < 50, `replay returns within 50 ms, its Promise resolving later: ${returnedMs.toFixed(1)} ms`);
  await expectStats(app.page, stats, 'replaying the session rebuilds the same document');
  assert.equal(await api(app.page, 'session'), session, 'the replayed session logs the same ops');

  for (const bad of ['{"format":"sketchmesh-session","version":1,"ops":[', '{"format":"nope"}', '[1,2']) {
    const message = await app.page.evaluate(async (s) => {
      try {
        await window.sketchmesh.replay(s);
        return null;
      } catch (e) {
        return e instanceof Error ? e.message : `non-Error: ${String(e)}`;
      }
    }, bad);
    assert.ok(message, `replay(${JSON.stringify(bad)}) must reject`);
    assert.ok(message.length > 5 && !message.startsWith('non-Error'), `a useful Error message, got ${message}`);
    await expectStats(app.page, stats, 'a failed replay leaves the document unchanged');
  }
  const loadGlb = await app.page.evaluate(async () => {
    try {
      await window.sketchmesh.loadGlb(new Uint8Array([0x67, 0x6c, 0x54, 0x46]));
      return null;
    } catch (e) {
      return e.message;
    }
  });
  assert.match(loadGlb ?? '', /^The file is not valid glTF: the GLB header is truncated\.$/, 'a truncated GLB is refused');
  await expectStats(app.page, stats, 'a refused import leaves the document unchanged');
});

// Both paths: the canvas's backing store follows the resize (the surface is configured again) and renders.
test('resize to 800x600: the canvas backing store follows and still renders', { gpu: true }, async () => {
  await app.page.setViewportSize({ width: 800, height: 600 });
  const size = await until(
    () => app.page.evaluate(() => {
      const c = document.getElementById('sketchmesh_canvas');
      return { width: c.width, height: c.height, dpr: window.devicePixelRatio };
    }),
    (s) => s.width === 800 * s.dpr && s.height === 600 * s.dpr,
  );
  assert.equal(size.width, 800 * size.dpr, 'canvas.width follows the viewport');
  assert.equal(size.height, 600 * size.dpr, 'canvas.height follows the viewport');
  await frames(app.page, 3);
  const shot = await screenshot(app.page, out('resize.png'));
  assert.equal(shot.width, 800);
  assert.ok(distinctColours(shot) >= 24, 'the resized canvas still renders');
  assert.deepEqual(app.errors, [], 'console errors during the session');
  await app.context.close();
});

// Both paths: the backing store at DPR 2, and what it renders.
test('deviceScaleFactor 2: the canvas backing store is twice the CSS size and renders', { gpu: true }, async () => {
  const hi = await openApp(await hiDpiBrowser(), url, gpu, { width: 640, height: 400, deviceScaleFactor: 2 });
  try {
    const size = await until(
      () => hi.page.evaluate(() => {
        const c = document.getElementById('sketchmesh_canvas');
        return { width: c.width, height: c.height, dpr: window.devicePixelRatio };
      }),
      (s) => s.width === 1280 && s.height === 800,
    );
    assert.deepEqual(size, { width: 1280, height: 800, dpr: 2 });
    const shot = await screenshot(hi.page, out('dpr2.png'), { scale: 'device' });
    assert.equal(shot.width, 1280);
    assert.ok(distinctColours(shot) >= 24, 'the high-DPI canvas renders');
    assert.deepEqual(hi.errors, [], 'console errors on the high-DPI page');
  } finally {
    await hi.context.close();
  }
});

// WebGL2 only: touch gestures and the document (its screenshot is kept, not checked).
test('tablet (820x1180, DPR 2, touch): a finger-drawn outline creates a model; a two-finger tap undoes it, a three-finger tap redoes it', { gpu: false }, async () => {
  const tablet = await openApp(await hiDpiBrowser(), url, gpu, { width: 820, height: 1180, deviceScaleFactor: 2 });
  try {
    const c = { x: 410, y: 640 };
    // Few samples: on this software renderer a frame of the DPR 2 tablet page takes a good
    // part of a second, and each touch event waits for one.
    const outline = Array.from({ length: 13 }, (_, i) => {
      const a = (2 * Math.PI * i) / 12;
      return { x: c.x + 170 * Math.cos(a), y: c.y + 120 * Math.sin(a) };
    });
    await touchGesture(tablet.cdp, [outline], 16);
    const created = await until(() => api(tablet.page, 'stats'), (s) => s.models === 1, 15_000);
    assert.equal(created.models, 1, 'the finger-drawn outline made a shape');
    await screenshot(tablet.page, out('tablet-created.png'));
    // Fingers down together and up 60 ms later, stamped so: a frame of this page on the
    // software renderer takes most of a second and delays the events' delivery.
    const tap = async (fingers) => {
      await frames(tablet.page, 2);
      await touchTap(tablet.cdp, fingers);
    };
    await tap([{ x: c.x - 60, y: c.y }, { x: c.x + 60, y: c.y }]);
    const undone = await until(() => api(tablet.page, 'stats'), (s) => s.models === 0);
    assert.equal(undone.models, 0, 'a two-finger tap undoes the creation');
    await tap([{ x: c.x - 80, y: c.y }, { x: c.x, y: c.y - 40 }, { x: c.x + 80, y: c.y }]);
    const redone = await until(() => api(tablet.page, 'stats'), (s) => s.models === 1);
    assert.deepEqual(redone, created, 'a three-finger tap redoes it');
    // A slow two-finger press is no tap: nothing changes.
    await touchGesture(tablet.cdp, [line({ x: c.x - 60, y: c.y }, { x: c.x - 60, y: c.y }, 4), line({ x: c.x + 60, y: c.y }, { x: c.x + 60, y: c.y }, 4)], 100);
    await frames(tablet.page, 2);
    assert.deepEqual(await api(tablet.page, 'stats'), created, 'a slow two-finger press changes nothing');
    assert.deepEqual(tablet.errors, [], 'console errors on the tablet page');
  } finally {
    await tablet.context.close();
  }
});

// Both paths: the toolbar's layout is read from the pixels drawn.
test('phone (390x844, DPR 2, touch): the toolbar is two rows at the bottom, the tools nearest the thumb, the file and view buttons behind ☰ and the tools that do not fit behind ⋯; a finger outline creates a model', { gpu: true }, async () => {
  const phone = await openApp(await hiDpiBrowser(), url, gpu, { width: 390, height: 844, deviceScaleFactor: 2 });
  try {
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    const shot = await screenshot(phone.page, out('phone.png'));
    // The toolbar's height: up its left margin from the bottom until the view's colours begin.
    const bottom = shot.height - 1;
    const panel = px(shot, 2, bottom);
    let height = 0;
    while (height < shot.height && px(shot, 2, bottom - height).every((v, i) => Math.abs(v - panel[i]) < 12)) height += 1;
    console.log(`    toolbar ${height} px of 844`);
    // Two rows of 44 px targets, and the view keeps at least 80% of the screen.
    assert.ok(height >= 2 * 44 && height <= 0.2 * 844, `the toolbar is ${height} px tall`);
    // The menu button, bottom left, opens the file and view buttons over the view.
    const menuButton = { x: 30, y: 844 - 30 };
    await touchTap(phone.cdp, [menuButton]);
    await frames(phone.page, 3);
    const menu = await screenshot(phone.page, out('phone-menu.png'));
    assert.ok(maxDiffNear(shot, menu, 60, 844 - height - 60, 20) > 40, 'the menu opened above its button');
    await touchTap(phone.cdp, [{ x: 300, y: 300 }]);
    await frames(phone.page, 3);
    // The last button of the tools row, ⋯ (the tools that do not fit), found from the right
    // by its filled background, opens its menu above it too.
    const row = 844 - 22;
    let right = 389;
    while (right > 200 && px(shot, right, row).every((v, i) => Math.abs(v - panel[i]) < 12)) right -= 1;
    assert.ok(right > 300, `the ⋯ button ends near the right edge: ${right}`);
    const more = { x: right - 22, y: row };
    await touchTap(phone.cdp, [more]);
    await frames(phone.page, 3);
    const moreMenu = await screenshot(phone.page, out('phone-more.png'));
    assert.ok(maxDiffNear(shot, moreMenu, more.x - 40, 844 - height - 60, 20) > 40, 'the ⋯ menu opened above its button');
    // A tap off the menu (it lists the tools with their names, on the right) closes it.
    await touchTap(phone.cdp, [{ x: 60, y: 300 }]);
    await frames(phone.page, 3);
    const c = { x: 195, y: 450 };
    const outline = Array.from({ length: 13 }, (_, i) => {
      const a = (2 * Math.PI * i) / 12;
      return { x: c.x + 120 * Math.cos(a), y: c.y + 90 * Math.sin(a) };
    });
    await touchGesture(phone.cdp, [outline], 16);
    const created = await until(() => api(phone.page, 'stats'), (s) => s.models === 1, 15_000);
    assert.equal(created.models, 1, 'the finger-drawn outline made a shape');
    await screenshot(phone.page, out('phone-created.png'));
    assert.deepEqual(phone.errors, [], 'console errors on the phone page');
  } finally {
    await phone.context.close();
  }
});

/** Every tool's key, in toolbar order (the registry's). */
const TOOL_KEYS = ['s', 'e', 't', 'u', 'p', 'o', 'd', 'l', 'j', 'q', 'm', 'c', 'v'];

// WebGL2 only: the layout and the toolbar's pixels, whatever draws the view.
test('the toolbar keeps its height for every tool on desktop, tablet and phone; each tool draws its own icon; a finger held on a tool shows its tooltip', { gpu: false, limitMs: 120_000 }, async () => {
  const screens = [
    { name: 'desktop', width: 1280, height: 800, bottom: false },
    { name: 'tablet', width: 820, height: 1180, bottom: true },
    { name: 'phone', width: 390, height: 844, bottom: true },
  ];
  for (const screen of screens) {
    const fresh = await openApp(browser, url, gpu, screen);
    try {
      const views = [];
      const icons = new Set();
      if (screen.name === 'tablet') {
        // A finger held on a tool (Feature's button, in Sketch's row) shows its name and when
        // to choose it above the row, and letting go after it picks nothing.
        const before = await screenshot(fresh.page, out('toolbar-hold-before.png'));
        const feature = { x: 571, y: 1155 };
        await fresh.cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ ...feature, id: 1 }] });
        await sleep(900);
        await frames(fresh.page, 3);
        const held = await screenshot(fresh.page, out('toolbar-hold.png'));
        await fresh.cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        await frames(fresh.page, 3);
        const after = await screenshot(fresh.page, out('toolbar-hold-after.png'));
        assert.ok(maxDiffNear(before, held, feature.x - 60, 1080, 20) > 40, 'a tooltip shows above the held tool');
        assert.ok(maxDiffNear(before, after, feature.x - 60, 1080, 20) < 20, 'and goes when the finger lifts');
        assert.ok(maxDiffNear(before, after, feature.x, feature.y, 20) < 40, 'the held tool was not picked');
      }
      for (const key of TOOL_KEYS) {
        await fresh.page.keyboard.press(key);
        await frames(fresh.page, 3);
        views.push((await api(fresh.page, 'layout')).view.map(Math.round));
        if (screen.name !== 'desktop') continue;
        // The selected tool's button, found by its fill in the tools row, holds its icon's
        // light ink above its name: a drawing of its own, unlike every other tool's.
        const shot = await screenshot(fresh.page, out(`toolbar-${key}.png`));
        const at = (x, y) => shot.data.slice((y * shot.width + x) * 4, (y * shot.width + x) * 4 + 3);
        const fill = (x) => { const [r, g, b] = at(x, 6); return b > 100 && b > r + 60; };
        const xs = Array.from({ length: shot.width }, (_, x) => x).filter(fill);
        assert.ok(xs.length > 20, `the ${key} tool's button is shown selected`);
        const [x0, x1] = [xs[0], xs.at(-1)];
        let mask = '';
        let ink = 0;
        for (let y = 6; y < 30; y += 1) {
          for (let x = Math.round((x0 + x1) / 2) - 12; x < Math.round((x0 + x1) / 2) + 12; x += 1) {
            const light = at(x, y).every((v) => v > 170);
            ink += light;
            mask += light ? '1' : '0';
          }
        }
        assert.ok(ink >= 15, `the ${key} tool's icon draws (${ink} light pixels)`);
        icons.add(mask);
      }
      const tops = views.map((v) => v[1]);
      const bottoms = views.map((v) => v[3]);
      console.log(`    ${screen.name}: view ${views[0].join(',')} for all ${views.length} tools`);
      for (const [k, view] of views.entries()) {
        assert.deepEqual(view, views[0], `${screen.name}: the view's rectangle with tool ${TOOL_KEYS[k]}`);
      }
      const toolbar = screen.bottom ? screen.height - bottoms[0] : tops[0];
      // Two rows of a finger's targets (the suite's pages have touch), and no third.
      assert.ok(toolbar >= 2 * 44 && toolbar <= 110, `${screen.name}: the toolbar is ${toolbar} px tall`);
      if (screen.name === 'desktop') assert.equal(icons.size, TOOL_KEYS.length, 'every tool has an icon of its own');
      await screenshot(fresh.page, out(`toolbar-${screen.name}.png`));
      assert.deepEqual(fresh.errors, [], `console errors on the ${screen.name} page`);
    } finally {
      await fresh.context.close();
    }
  }
});

// WebGL2 only: the help's layout, whatever draws the view.
test('help on a phone (390x844) fits the screen and scrolls with a finger to its last entry', { gpu: false, limitMs: 150_000 }, async () => {
  const phone = await openApp(browser, url, gpu, { width: 390, height: 844 });
  try {
    await phone.page.keyboard.press('h');
    let help = await until(() => api(phone.page, 'layout'), (l) => l.help).then((l) => l.help);
    assert.ok(help, 'the help is open');
    const [left, top, right, bottom] = help.rect;
    console.log(`    help list ${help.rect.map(Math.round).join(',')}, scrolls ${Math.round(help.max_offset)} px`);
    assert.ok(left >= 0 && right <= 390 && top >= 0 && bottom <= 844, 'the help list lies on the screen');
    assert.ok(bottom - top >= 0.5 * 844, `the help list takes most of the screen: ${bottom - top} px`);
    assert.ok(help.max_offset > 0, 'the help is longer than the screen, so it scrolls');
    await screenshot(phone.page, out('help-phone.png'));
    const x = (left + right) / 2;
    for (let k = 0; k < 12 && help.offset < help.max_offset - 1; k += 1) {
      await touchGesture(phone.cdp, [line({ x, y: bottom - 20 }, { x, y: top + 20 }, 6)]);
      await frames(phone.page, 4);
      help = (await api(phone.page, 'layout')).help;
    }
    assert.ok(help.offset >= help.max_offset - 1, `the finger scrolled to the end: ${help.offset} of ${help.max_offset}`);
    await screenshot(phone.page, out('help-phone-end.png'));
    const stats = await api(phone.page, 'stats');
    assert.ok(stats.models === 0 && stats.curves === 0, 'the drags over the help drew nothing');
    assert.deepEqual(phone.errors, [], 'console errors on the phone page');
  } finally {
    await phone.context.close();
  }
});

// Both paths: the pen's hover cursor is looked for on screen.
test('pen with a resting palm: exactly one model, no ink from the palm, the view unmoved; a pen hovering shows its cursor', { gpu: true }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page, cdp } = fresh;
    const view = await api(page, 'camera');
    const outline = onEllipse();
    // The pen comes near (hovering, no button), the palm lands, wide, and rests while the pen draws.
    const hover = { pointerType: 'pen', button: 'none', buttons: 0 };
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: 300, y: 300, ...hover });
    await frames(page, 3);
    const hovering = await screenshot(page, out('pen-hover.png'));
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: outline[0].x, y: outline[0].y, ...hover });
    await frames(page, 3);
    const moved = await screenshot(page, out('pen-hover-moved.png'));
    assert.ok(maxDiffNear(hovering, moved, 300, 300, 8) > 60, 'a cursor where the pen hovers, gone when it moves on');
    const palm = (type, x, y) => cdp.send('Input.dispatchTouchEvent', {
      type, touchPoints: type === 'touchEnd' ? [] : [{ x, y, radiusX: 30, radiusY: 24, force: 0.3, id: 7 }],
    });
    await palm('touchStart', 1000, 560);
    await palm('touchMove', 1010, 570);
    await penStroke(cdp, outline);
    await palm('touchMove', 1040, 590);
    await palm('touchEnd');
    const made = await until(() => api(page, 'stats'), (s) => s.models === 1, 15_000);
    assert.equal(made.models, 1, 'the pen made one model');
    await frames(page, 3);
    const ops = JSON.parse(await api(page, 'session')).ops.map((o) => o.op);
    assert.deepEqual(ops, ['create'], 'the palm left no ink');
    assert.deepEqual(await api(page, 'camera'), view, 'the palm did not move the view');
    await screenshot(page, out('palm.png'));
    assert.deepEqual(fresh.errors, [], 'console errors with a palm');
  } finally {
    await fresh.context.close();
  }
});

/** A .glb of a tetrahedron with one triangle given twice: it imports repaired, with a note. */
function tetraWithDuplicateGlb() {
  const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
  const indices = new Uint16Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 1, 2, 3]);
  const bin = Buffer.concat([Buffer.from(positions.buffer), Buffer.from(indices.buffer), Buffer.alloc(2)]);
  const json = Buffer.from(JSON.stringify({
    asset: { version: '2.0' }, scene: 0, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0, name: 'tetra' }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 4, type: 'VEC3', min: [0, 0, 0], max: [1, 1, 1] },
      { bufferView: 1, componentType: 5123, count: 15, type: 'SCALAR' },
    ],
    bufferViews: [{ buffer: 0, byteLength: 48 }, { buffer: 0, byteOffset: 48, byteLength: 30 }],
    buffers: [{ byteLength: bin.length }],
  }));
  const padded = Buffer.concat([json, Buffer.alloc((4 - (json.length % 4)) % 4, 0x20)]);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + padded.length + 8 + bin.length, 8);
  const chunk = (data, type) => {
    const head = Buffer.alloc(8);
    head.writeUInt32LE(data.length, 0);
    head.writeUInt32LE(type, 4);
    return Buffer.concat([head, data]);
  };
  return Buffer.concat([header, chunk(padded, 0x4e4f534a), chunk(bin, 0x004e4942)]);
}

// Both paths: the notes panel is looked for on screen.
test('an import that needed repairs says so in a notes panel; OK or Escape dismisses it', { gpu: true }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page } = fresh;
    const before = await screenshot(page, out('notes-before.png'));
    await page.evaluate((bytes) => window.sketchmesh.loadGlb(new Uint8Array(bytes), 'tetra.glb'), [...tetraWithDuplicateGlb()]);
    await frames(page, 4);
    const notes = await api(page, 'notes');
    assert.equal(notes?.length, 1, `one note: ${JSON.stringify(notes)}`);
    assert.equal(notes[0], 'tetra was not a clean manifold surface: 1 duplicate triangle was dropped.');
    const shown = await screenshot(page, out('notes.png'));
    assert.ok(maxDiffNear(before, shown, 640, 140, 30) > 40, 'the panel shows at the top of the view');
    await page.focus('#sketchmesh_canvas');
    await page.keyboard.press('Escape');
    await frames(page, 3);
    assert.equal(await api(page, 'notes'), null, 'Escape dismissed it');
    assert.equal((await api(page, 'stats')).models, 1, 'the repaired tetrahedron is in');
    assert.deepEqual(fresh.errors, [], 'console errors with notes');
  } finally {
    await fresh.context.close();
  }
});

/** The first image of a GLB file (its bytes), as glTF's JSON chunk places it. */
function glbImage(glb) {
  const jsonLength = glb.readUInt32LE(12);
  const json = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const binStart = 20 + jsonLength + 8;
  const view = json.bufferViews[json.images[0].bufferView];
  const start = binStart + (view.byteOffset ?? 0);
  return glb.subarray(start, start + view.byteLength);
}

/** Mean [r, g, b] of `image`'s pixels where `keep(x, y)` holds, and their share. */
function meanColour(image, keep) {
  const sum = [0, 0, 0];
  let n = 0;
  for (let y = 0; y < image.height; y++) {
    for (let x = 0; x < image.width; x++) {
      if (!keep(x, y)) continue;
      const i = 4 * (y * image.width + x);
      for (let c = 0; c < 3; c++) sum[c] += image.data[i + c];
      n++;
    }
  }
  return { mean: sum.map((v) => v / Math.max(n, 1)), share: n / (image.width * image.height) };
}

const chroma = ([r, g, b]) => [r / (r + g + b), g / (r + g + b)];

// Both paths: the texture's colour on screen.
test('an imported textured model shows its base-colour texture: the model\'s mean colour on screen has the texture\'s hue; Clay hides it', { gpu: true }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page } = fresh;
    const glb = readFileSync(join(dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'shared', 'testdata', 'gltf', 'real', 'BoxTextured.glb'));
    const texture = await page.evaluate(async (bytes) => {
      const bitmap = await createImageBitmap(new Blob([new Uint8Array(bytes)], { type: 'image/png' }));
      const canvas = document.createElement('canvas');
      [canvas.width, canvas.height] = [bitmap.width, bitmap.height];
      const g = canvas.getContext('2d');
      g.drawImage(bitmap, 0, 0);
      const data = g.getImageData(0, 0, bitmap.width, bitmap.height).data;
      const sum = [0, 0, 0];
      for (let i = 0; i < data.length; i += 4) for (let c = 0; c < 3; c++) sum[c] += data[i + c];
      return sum.map((v) => v / (data.length / 4));
    }, [...glbImage(glb)]);
    const empty = await screenshot(page, out('texture-empty.png'));
    await page.evaluate((bytes) => window.sketchmesh.loadGlb(new Uint8Array(bytes), 'BoxTextured.glb'), [...glb]);
    await until(() => api(page, 'stats'), (st) => st.models === 1, 5_000);
    // The texture arrives from the browser's decoder a few frames later.
    await sleep(800);
    await frames(page, 4);
    const textured = await screenshot(page, out('texture.png'));
    const model = (x, y) => y > 90 && maxDiffNear(empty, textured, x, y, 0) > 40;
    const seen = meanColour(textured, model);
    const [want, got] = [chroma(texture), chroma(seen.mean)];
    console.log(`    texture: mean ${texture.map((v) => v.toFixed(0))}, on screen ${seen.mean.map((v) => v.toFixed(0))} over ${(100 * seen.share).toFixed(1)}% of the page; chroma ${want.map((v) => v.toFixed(3))} against ${got.map((v) => v.toFixed(3))}`);
    assert.ok(seen.share > 0.01, 'the box is on screen');
    assert.ok(Math.abs(want[0] - got[0]) < 0.04 && Math.abs(want[1] - got[1]) < 0.04, 'the box has the texture\'s hue');
    // Clay is in the View menu (View, then its fifth item).
    await page.mouse.click(82, 25);
    await frames(page, 3);
    await page.mouse.click(82, 265);
    await frames(page, 4);
    const clay = meanColour(await screenshot(page, out('texture-clay.png')), model);
    const blueish = (c) => c[2] - c[0];
    console.log(`    clay: mean ${clay.mean.map((v) => v.toFixed(0))}`);
    assert.ok(blueish(seen.mean) - blueish(clay.mean) > 15, 'Clay drops the texture\'s blue');
    assert.deepEqual(fresh.errors, [], 'console errors with a texture');
  } finally {
    await fresh.context.close();
  }
});

// WebGL2 only: the camera and the ops.
test('a one-finger double tap on empty canvas frames everything; on a model it does not', { gpu: false }, () => withShape(async ({ fresh }) => {
  const { page, cdp } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  await page.keyboard.press('f');
  await frames(page, 2);
  const framed = await api(page, 'camera');
  // egui spreads a wheel's scroll over frames: wait until the view stops moving.
  const zoomOut = async () => {
    await page.mouse.move(ELLIPSE.c.x, ELLIPSE.c.y);
    await page.mouse.wheel(0, 600);
    let last = null;
    for (let i = 0; i < 40; i++) {
      await frames(page, 3);
      const now = JSON.stringify(await api(page, 'camera'));
      if (now === last) break;
      last = now;
    }
  };
  // The taps' event times are given, 0.2 s apart, so that a busy page cannot stretch them.
  const doubleTap = async (at) => {
    const t0 = Date.now() / 1000;
    await touchTap(cdp, [at], 60, t0);
    await touchTap(cdp, [at], 60, t0 + 0.2);
    await frames(page, 3);
  };
  await zoomOut();
  const away = await api(page, 'camera');
  assert.ok(cameraDistance(away) > cameraDistance(framed) * 1.05, 'the wheel zoomed out');
  await doubleTap(ELLIPSE.c);
  assert.deepEqual(await api(page, 'camera'), away, 'a double tap on the model leaves the view');
  await doubleTap({ x: 150, y: 600 });
  assert.deepEqual(await api(page, 'camera'), framed, 'a double tap on empty canvas frames the shape');
  const ops = JSON.parse(await api(page, 'session')).ops.map((o) => o.op);
  assert.deepEqual(ops, ['create'], 'the taps left no ink');
}, { pen: true }));

// WebGL2 only: the ops and the document.
test('the pen\'s barrel button erases a curve whatever the tool; the tool stays', { gpu: false }, () => withShape(async ({ fresh }) => {
  const { page, cdp } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const c = ELLIPSE.c;
  const across = line({ x: c.x - 90, y: c.y + 10 }, { x: c.x + 90, y: c.y + 10 }, 30).map((p) => ({ ...p, force: 0.5 }));
  await penStroke(cdp, across);
  await until(() => lastOpOf(page), (o) => o.op === 'add_curve', 15_000);
  assert.equal((await api(page, 'stats')).curves, 2, 'a second curve');
  // A pen press with the barrel button (a pointerdown whose buttons are 2).
  const barrel = { pointerType: 'pen', button: 'right', force: 0.5 };
  await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: across[0].x, y: across[0].y, buttons: 2, clickCount: 1, ...barrel });
  for (const p of across.slice(1)) {
    await sleep(20);
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: p.x, y: p.y, buttons: 2, ...barrel });
  }
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: across.at(-1).x, y: across.at(-1).y, buttons: 0, clickCount: 1, ...barrel });
  assert.equal((await until(() => lastOpOf(page), (o) => o.op === 'erase', 15_000)).op, 'erase', 'the barrel stroke erased');
  assert.equal((await api(page, 'stats')).curves, 1, 'the added curve is gone');
  // The tool is still Sketch: the next plain stroke adds a curve again.
  await penStroke(cdp, across);
  assert.equal((await until(() => lastOpOf(page), (o) => o.op === 'add_curve', 15_000)).op, 'add_curve', 'the tool stayed Sketch');
  assert.deepEqual(fresh.errors, [], 'console errors with the barrel button');
}));

// Both paths: the lit shape and its curve on screen.
test('a closed pen outline becomes a lit 3D shape with its blue curve; undo removes it; export validates', { gpu: true }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const centre = ELLIPSE.c;
    const outline = onEllipse();
    const before = await screenshot(fresh.page, out('create-before.png'));
    await penStroke(fresh.cdp, outline);
    const released = Date.now();
    const stats = await until(() => api(fresh.page, 'stats'), (s) => s.models === 1, 15_000);
    const settled = Date.now() - released;
    assert.equal(stats.models, 1, 'a closed outline on empty canvas creates one model');
    assert.equal(stats.curves, 1, 'its outline stays on it as one control curve');
    assert.ok(stats.vertices > 1000 && stats.triangles === 2 * stats.vertices - 4, `closed genus-0 mesh: ${JSON.stringify(stats)}`);
    console.log(`    created ${stats.vertices} vertices; converged and committed ${settled} ms after release`);
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('create.png'));
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    const [r, g, b] = px(after, centre.x, centre.y);
    assert.ok(r > 120 && r >= b, `the shape's middle is lit clay, got rgb(${r}, ${g}, ${b})`);
    const rim = [-4, -2, 0, 2, 4].map((d) => px(after, centre.x + 170 + d, centre.y));
    assert.ok(rim.some(([r2, , b2]) => b2 > 170 && b2 > r2 + 50), `a blue curve on the outline, got ${JSON.stringify(rim)}`);
    const session = JSON.parse(await api(fresh.page, 'session'));
    assert.equal(session.ops.at(-1).op, 'create', 'the session logs a create op');

    const glb = await fresh.page.evaluate(() => Array.from(window.sketchmesh.exportGlb()));
    writeFileSync(out('create-export.glb'), Buffer.from(glb));

    await fresh.page.keyboard.press('Control+z');
    const undone = await until(() => api(fresh.page, 'stats'), (s) => s.models === 0);
    assert.deepEqual(undone, { models: 0, vertices: 0, triangles: 0, curves: 0 }, 'undo removes the shape');
    await frames(fresh.page, 3);
    const reverted = await screenshot(fresh.page, out('create-undone.png'));
    assert.ok(imageChangedFraction(before, reverted) < 0.01, 'the view looks as before the shape');
    assert.deepEqual(fresh.errors, [], 'console errors while creating');
  } finally {
    await fresh.context.close();
  }
});

// Both paths: the imported model on screen.
test('a dropped .glb imports and is framed; Export downloads a valid file; bad files change nothing', { gpu: true }, async () => {
  const spotPath = join(dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'shared', 'testdata', 'meshes', 'spot.glb');
  assert.ok(existsSync(spotPath), `the shared test data is missing: ${spotPath} (this case needs Keenan Crane's spot.glb)`);
  const spot = Array.from(readFileSync(spotPath));
  const fresh = await openApp(browser, url, gpu);
  try {
    const before = await screenshot(fresh.page, out('import-before.png'));
    const dropped = Date.now();
    await fresh.page.evaluate(async (bytes) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([new Uint8Array(bytes)], 'spot.glb', { type: 'model/gltf-binary' }));
      const canvas = document.getElementById('sketchmesh_canvas');
      for (const type of ['dragenter', 'dragover', 'drop']) {
        canvas.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }
    }, spot);
    const stats = await until(() => api(fresh.page, 'stats'), (s) => s.models === 1, 10_000);
    console.log(`    imported ${stats.triangles} triangles ${Date.now() - dropped} ms after the drop (including polling)`);
    assert.deepEqual(stats, { models: 1, vertices: 2930, triangles: 5856, curves: 0 }, 'spot.glb has 2,930 vertices and 5,856 triangles');
    await frames(fresh.page, 4);
    const shot = await screenshot(fresh.page, out('import.png'));
    assert.ok(imageChangedFraction(before, shot) > 0.05, 'the imported cow is framed and visible');
    const session = JSON.parse(await api(fresh.page, 'session'));
    assert.equal(session.ops.at(-1).op, 'import');
    assert.equal(session.ops.at(-1).files[0].name, 'spot.glb');
    // The autosave, written piece by piece to JavaScript, holds the session shown, the file
    // in it.
    await api(fresh.page, 'flushAutosave');
    const stored = await until(() => storedSession(fresh.page), (s) => s !== null, 5000);
    assert.deepEqual(stored, session, 'the autosaved session is the one shown');
    // The import's op (the file's base64) is stored apart from the record, once: neither a
    // later change nor the first autosave after a reload writes it again.
    const record = await storedRecord(fresh.page);
    assert.equal(record.parts.filter((part) => typeof part !== 'string').length, 1, 'the import is a piece apart');
    assert.ok(record.parts.every((part) => typeof part !== 'string' || part.length < 65536), 'the rest of the record is short');
    await fresh.page.reload({ waitUntil: 'load' });
    await fresh.page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
    assert.deepEqual(await until(() => api(fresh.page, 'stats'), (s) => s.models === 1, 15_000), stats, 'the reload restores the cow');
    await countLongWrites(fresh.page, 65536);
    await api(fresh.page, 'undo');
    await api(fresh.page, 'flushAutosave');
    await api(fresh.page, 'redo');
    await api(fresh.page, 'flushAutosave');
    const later = JSON.parse(await api(fresh.page, 'session'));
    assert.deepEqual(await until(() => storedSession(fresh.page), (s) => s?.ops.length === later.ops.length, 5000), later, 'the later autosaves hold the session shown');
    assert.equal(await fresh.page.evaluate(() => window.longWrites), 0, 'and wrote no long piece');

    const [download] = await Promise.all([
      fresh.page.waitForEvent('download', { timeout: 10_000 }),
      fresh.page.keyboard.press('Control+s'),
    ]);
    assert.match(download.suggestedFilename(), /^sketchmesh-\d{8}-\d{4}\.glb$/);
    await download.saveAs(out('download.glb'));
    const downloaded = readFileSync(out('download.glb'));
    // The toolbar's File menu's Export (at their places in the 1280 px wide toolbar) does the same.
    await fresh.page.mouse.click(FILE_MENU.x, FILE_MENU.y);
    await frames(fresh.page, 3);
    const [clicked] = await Promise.all([
      fresh.page.waitForEvent('download', { timeout: 10_000 }),
      fresh.page.mouse.click(36, 225),
    ]);
    await clicked.saveAs(out('download-button.glb'));
    assert.ok(readFileSync(out('download-button.glb')).equals(downloaded), 'the Export button downloads the same file');
    assert.ok(downloaded.subarray(0, 4).equals(Buffer.from('glTF')), 'the download is a .glb');

    // The same bytes through the page API, into a fresh document, give the same model.
    const reloaded = await fresh.page.evaluate(async (bytes) => {
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(new Uint8Array(bytes), 'again.glb');
      return window.sketchmesh.stats();
    }, Array.from(downloaded));
    assert.deepEqual(reloaded, stats, 'an export imports back to the same model');

    const refusal = await fresh.page.evaluate(async () => {
      try {
        await window.sketchmesh.loadGlb(new Uint8Array([103, 108, 84, 70, 2, 0, 0, 0, 9, 9, 9, 9]), 'broken.glb');
        return null;
      } catch (err) {
        return String(err.message);
      }
    });
    assert.match(refusal ?? '', /^The file is not valid glTF: .*\.$/, 'a broken file is refused with a sentence');
    assert.deepEqual(await api(fresh.page, 'stats'), stats, 'and the document is unchanged');
    assert.deepEqual(fresh.errors, [], 'console errors while importing');
  } finally {
    await fresh.context.close();
  }
});

// Both paths: the new outline on screen, without seams.
test('over-sketch mode: a stroke beyond a shape\'s outline pulls the outline to it, without seams; undo restores it', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    // Over-sketch mode first, so that the toolbar (which shows the fit toggle in this mode)
    // is the same in the screenshots compared.
    await fresh.page.keyboard.press('o');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('oversketch-before.png'));
    // From the outline at -60 degrees to +60 degrees, bulging 40 px out at 0 degrees.
    const stroke = onEllipse(-Math.PI / 3, Math.PI / 3, 40, (a) => 40 * Math.cos(1.5 * a) ** 2, 0.5);
    await penStroke(fresh.cdp, stroke);
    const released = Date.now();
    const session = await until(
      () => api(fresh.page, 'session').then((json) => JSON.parse(json)),
      (sess) => sess.ops.at(-1)?.op === 'oversketch',
      10_000,
    );
    console.log(`    over-sketch applied ${Date.now() - released} ms after release (including polling)`);
    assert.equal(session.ops.at(-1).op, 'oversketch', 'the stroke became an oversketch op');
    // The created shape's curve drew that outline: it moved, and the surface around it was
    // settled and remeshed through it (as after a pull), so the counts change a little.
    const moved = await api(fresh.page, 'stats');
    assert.equal(moved.curves, created.curves, 'the curve is kept');
    assert.ok(Math.abs(moved.vertices - created.vertices) < 0.1 * created.vertices, `vertices ${created.vertices} -> ${moved.vertices}`);
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('oversketch.png'));
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    // 8 px above the centre line: the red x axis runs along it behind the shape.
    const probe = { x: c.x + 170 + 22, y: c.y - 8 };
    const [r0] = px(before, probe.x, probe.y);
    const [r1, g1, b1] = px(after, probe.x, probe.y);
    assert.ok(r0 < 100, `outside the original outline is background, got red ${r0}`);
    assert.ok(r1 > 120 && r1 >= b1, `the outline moved out to the stroke: clay at ${probe.x}, got rgb(${r1}, ${g1}, ${b1})`);
    // Without seams: over the stroke's middle 80%, 4 px inside it is the shape (clay, or the
    // blue curve that draws the outline) and 4 px outside it is what was there before (the
    // background: no notch, and no curve or sliver of surface beyond the outline).
    const isShape = ([r, , b]) => r > 100 || b > 150;
    const along = [];
    for (let k = 0; k + 1 < stroke.length; k += 1) {
      for (const t of [0, 0.5]) {
        along.push({ x: stroke[k].x + t * (stroke[k + 1].x - stroke[k].x), y: stroke[k].y + t * (stroke[k + 1].y - stroke[k].y) });
      }
    }
    const seams = [];
    along.slice(Math.floor(0.1 * along.length), Math.ceil(0.9 * along.length)).forEach((p) => {
      const d = { x: p.x - c.x, y: p.y - c.y };
      const len = Math.hypot(d.x, d.y);
      const at = (s) => [Math.round(p.x + (s * d.x) / len), Math.round(p.y + (s * d.y) / len)];
      const inside = px(after, ...at(-4));
      const [ox, oy] = at(4);
      const outside = px(after, ox, oy);
      const was = px(before, ox, oy);
      if (!isShape(inside)) seams.push(`inside ${at(-4)} rgb(${inside})`);
      if (outside.some((v, i) => Math.abs(v - was[i]) > 40)) seams.push(`outside ${[ox, oy]} rgb(${outside}) was rgb(${was})`);
    });
    assert.deepEqual(seams, [], 'the new outline lies on the stroke, within 4 px either side');
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    const undone = await screenshot(fresh.page, out('oversketch-undone.png'));
    assert.ok(imageChangedFraction(before, undone) < 0.01, 'undo restores the shape');
    assert.deepEqual(fresh.errors, [], 'console errors while over-sketching');
}));

// Both paths: the picked piece's highlight and the moved outline on screen.
test('manual over-sketch (K): pick an outline piece, redraw it; pick a curve on the surface, move it; undo restores', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    await fresh.page.keyboard.press('k');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('manual-before.png'));
    const lastOp = () => lastOpOf(fresh.page);
    // Pick: along the outline from -40 to +40 degrees. Nothing changes yet.
    await penStroke(fresh.cdp, onEllipse(-0.7, 0.7, 30, () => 0, 0.5));
    await frames(fresh.page, 3);
    assert.equal((await lastOp()).op, 'create', 'picking is not an op');
    const picked = await screenshot(fresh.page, out('manual-picked.png'));
    // The picked piece is highlighted green on the outline.
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    const [hr, hg, hb] = px(picked, c.x + ELLIPSE.rx, c.y);
    assert.ok(hg > 150 && hg > hr + 40 && hg > hb, `the picked piece is shown green, got rgb(${hr}, ${hg}, ${hb})`);
    // Its new shape: 35 px out in the middle.
    await penStroke(fresh.cdp, onEllipse(-0.7, 0.7, 30, (a) => 35 * Math.cos((Math.PI / 1.4) * a) ** 2, 0.5));
    const op = await until(lastOp, (o) => o.op === 'oversketch', 10_000);
    assert.ok(op.handle?.silhouette, `the op carries the picked outline: ${JSON.stringify(op.handle)}`);
    await frames(fresh.page, 3);
    const moved = await screenshot(fresh.page, out('manual-outline.png'));
    const probe = { x: c.x + ELLIPSE.rx + 20, y: c.y - 8 };
    const [r0] = px(before, probe.x, probe.y);
    const [r1, g1, b1] = px(moved, probe.x, probe.y);
    assert.ok(r0 < 100, `outside the original outline is background, got red ${r0}`);
    assert.ok(r1 > 120 && r1 >= b1, `the picked outline moved out: clay at ${probe.x}, got rgb(${r1}, ${g1}, ${b1})`);
    // A curve across the front, then its new place 25 px higher.
    const positions = () => glbOf(fresh.page);
    const beforeLift = await positions();
    const across = line({ x: c.x - 80, y: c.y + 10 }, { x: c.x + 80, y: c.y + 10 }, 30);
    await penStroke(fresh.cdp, across);
    await frames(fresh.page, 2);
    await penStroke(fresh.cdp, across.map((p) => ({ ...p, y: p.y - 25 })));
    const surface = await until(lastOp, (o) => o.op === 'oversketch' && o.handle?.surface, 10_000);
    assert.ok(surface.handle?.surface, 'the second pick is a curve on the surface');
    await frames(fresh.page, 3);
    const lifted = await screenshot(fresh.page, out('manual-surface.png'));
    // The surface slides along itself under the camera, so the shading changes only a little.
    const shading = imageChangedFraction(moved, lifted, 12);
    console.log(`    moving the surface curve changed ${(100 * shading).toFixed(2)}% of the pixels`);
    assert.ok(shading > 0.0005, 'moving the surface curve changed the shading');
    assert.notDeepEqual(await positions(), beforeLift, 'and the exported mesh');
    assert.deepEqual(await api(fresh.page, 'stats'), created, 'same vertices and triangles, only moved');
    await fresh.page.keyboard.press('Control+z');
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    const undone = await screenshot(fresh.page, out('manual-undone.png'));
    assert.ok(imageChangedFraction(before, undone) < 0.01, 'two undos restore the shape');
    assert.deepEqual(fresh.errors, [], 'console errors while over-sketching by hand');
}));

// Both paths: the live preview and the sharp curve on screen.
test('curve tools with the pen: pull (live preview, its result computed by the page\'s worker), add a curve, make it sharp, rub, erase; undo restores', { gpu: true, limitMs: LONG_CASE_LIMIT_MS }, () => withShape(async ({ fresh }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    const waitOp = async (name, ms = 15_000) => {
      const op = await until(lastOp, (o) => o.op === name, ms);
      assert.equal(op.op, name, `the gesture became a "${name}" op`);
      return op;
    };
    await waitOp('create');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('curves-before.png'));
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    const isClay = ([r, , b]) => r > 120 && r >= b;

    // Pull the outline's rightmost point 80 px out; look at the live preview before release.
    await fresh.page.keyboard.press('p');
    const send = penSender(fresh.cdp);
    await send('mousePressed', c.x + 170, c.y, 1);
    for (let i = 1; i <= 16; i++) {
      await sleep(25);
      await send('mouseMoved', c.x + 170 + 5 * i, c.y, 1);
    }
    await frames(fresh.page, 4);
    const dragging = await screenshot(fresh.page, out('curves-pull-live.png'));
    assert.ok(isClay(px(dragging, c.x + 215, c.y)), `the live preview follows the pen: rgb(${px(dragging, c.x + 215, c.y)})`);
    await send('mouseReleased', c.x + 250, c.y, 0);
    const released = Date.now();
    const pull = await waitOp('pull');
    console.log(`    pull committed ${Date.now() - released} ms after release (including polling)`);
    const timed = (await api(fresh.page, 'timings')).pull;
    assert.equal(timed?.elsewhere_ms?.length, 1, `the page's worker computed the committed pull: ${JSON.stringify(timed)}`);
    assert.equal(pull.stroke[0][0], c.x + 170, 'the pull starts where the curve was grabbed');
    await frames(fresh.page, 3);
    const pulled = await screenshot(fresh.page, out('curves-pull.png'));
    assert.ok(!isClay(px(before, c.x + 225, c.y)), 'outside the original outline is background');
    assert.ok(isClay(px(pulled, c.x + 225, c.y)), `the outline followed the pull: rgb(${px(pulled, c.x + 225, c.y)})`);

    // Sketch mode: an open stroke starting on the shape adds a curve.
    await fresh.page.keyboard.press('s');
    const across = line({ x: c.x - 90, y: c.y + 10 }, { x: c.x + 90, y: c.y + 10 }, 30).map((p) => ({ ...p, force: 0.5 }));
    await penStroke(fresh.cdp, across);
    await waitOp('add_curve');
    assert.equal((await api(fresh.page, 'stats')).curves, 2, 'the shape has a second curve');

    // Type tool: along the new curve, it turns sharp (drawn red).
    await fresh.page.keyboard.press('t');
    await penStroke(fresh.cdp, across);
    const retype = await waitOp('set_curve_type');
    assert.equal(retype.sharp, true, 'a smooth curve toggles to sharp');
    await frames(fresh.page, 3);
    const sharp = await screenshot(fresh.page, out('curves-sharp.png'));
    const reds = across.filter((p) => {
      const [r, g, b] = px(sharp, Math.round(p.x), Math.round(p.y));
      return r > 170 && g < 120 && b < 120;
    }).length;
    assert.ok(reds > across.length / 2, `the sharp curve is drawn red (${reds}/${across.length} samples)`);

    // Rub back and forth over it, then erase it.
    await fresh.page.keyboard.press('u');
    const rub = [...across, ...[...across].reverse(), ...across];
    await penStroke(fresh.cdp, rub, 10);
    await waitOp('rub');
    await fresh.page.keyboard.press('e');
    await penStroke(fresh.cdp, across);
    await waitOp('erase');
    assert.equal((await api(fresh.page, 'stats')).curves, 1, 'erasing removed the added curve');

    // Five undos restore the creation exactly.
    for (let i = 0; i < 5; i++) {
      await fresh.page.keyboard.press('Control+z');
      await frames(fresh.page, 2);
    }
    await frames(fresh.page, 3);
    const undone = await screenshot(fresh.page, out('curves-undone.png'));
    // Below the hint line, which names the tool in use.
    assert.ok(imageChangedFraction(before, undone, 60, { fromY: 150 }) < 0.01, 'undo restores the created shape');
    assert.deepEqual(fresh.errors, [], 'console errors while editing curves');
}));

// Both paths: the preview and the painted band, in the wireframe drawn.
test('optimize (M): a tap previews the shape optimized, Esc drops it, Enter commits one op, undo restores, a painted band bounds it', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    const glb = () => glbOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glb();
    // Wireframe on, so that moved vertices show as moved lines.
    await fresh.page.keyboard.press('m');
    await fresh.page.keyboard.press('w');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('optimize-before.png'));
    // A tap begins the preview; the page's worker computes it (each read of the timings
    // takes them).
    const previewed = () => api(fresh.page, 'timings').then((t) => t.optimize?.preview_ms?.length ?? 0);
    const tap = async () => {
      await previewed();
      await penStroke(fresh.cdp, [{ x: c.x + 40, y: c.y, force: 0.5 }, { x: c.x + 40, y: c.y, force: 0.5 }]);
      await until(previewed, (n) => n >= 1, 15_000);
      await frames(fresh.page, 6);
    };
    // Sample points inside the shape, away from the hint line above it.
    const inside = insideShape();
    await tap();
    const preview = await screenshot(fresh.page, out('optimize-preview.png'));
    const moved = changedFraction(before, preview, inside, { radius: 0 });
    console.log(`    the preview changed ${(100 * moved).toFixed(2)}% of the pixels inside the shape`);
    // Its vertices move by about a pixel: the wireframe's lines (aliased on a software
    // adapter, which draws without MSAA) change about half a percent of the samples.
    assert.ok(moved > 0.003, `the preview moves the wireframe (${moved})`);
    assert.equal((await lastOp()).op, 'create', 'a preview is not an op');
    await fresh.page.keyboard.press('Escape');
    await frames(fresh.page, 3);
    const dropped = await screenshot(fresh.page, out('optimize-dropped.png'));
    assert.ok(imageChangedFraction(before, dropped) < 0.001, 'Esc shows the shape as it was');
    assert.deepEqual(await glb(), original, 'Esc changes nothing');
    await tap();
    await fresh.page.keyboard.press('Enter');
    const op = await until(lastOp, (o) => o.op === 'optimize', 10_000);
    assert.equal(op.op, 'optimize', 'Enter commits an optimize op');
    assert.equal(op.model, 0);
    assert.equal(op.mode, 'shape');
    assert.deepEqual(await api(fresh.page, 'stats'), created, 'same vertices, triangles and curves');
    assert.notDeepEqual(await glb(), original, 'the committed positions differ');
    await frames(fresh.page, 3);
    const committed = await screenshot(fresh.page, out('optimize.png'));
    const differs = changedFraction(preview, committed, inside, { radius: 0 });
    assert.ok(differs < 0.01, `the committed shape is the preview (${(100 * differs).toFixed(1)}% differ)`);
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glb(), original, 'undo restores the shape bit for bit');
    // B: strokes paint what moves. A band painted across the middle moves; the rest holds.
    // Less hold ([ four times: s = 0.41), so that the band's triangles change visibly.
    await fresh.page.keyboard.press('b');
    for (let i = 0; i < 4; i++) {
      await fresh.page.keyboard.press('[');
      await frames(fresh.page, 1);
    }
    await frames(fresh.page, 3);
    const unpainted = await screenshot(fresh.page, out('optimize-unpainted.png'));
    const band = [];
    for (let x = c.x - 120; x <= c.x + 120; x += 8) band.push({ x, y: c.y, force: 0.5 });
    await penStroke(fresh.cdp, band);
    await frames(fresh.page, 6);
    await fresh.page.keyboard.press('Enter');
    const painted = await until(lastOp, (o) => o.op === 'optimize', 10_000);
    assert.equal(painted.painted?.length, 1, 'the op carries the painted stroke');
    assert.ok(painted.painted[0].radius > 0 && !painted.region, 'a brush radius, no lasso');
    await frames(fresh.page, 3);
    const paintedShot = await screenshot(fresh.page, out('optimize-painted.png'));
    const far = inside.filter((p) => Math.abs(p.y - c.y) > 50);
    // Every pixel under the band: its lines move by about a pixel, and aliased lines (a
    // software adapter draws without MSAA) cross few of the sparser samples.
    const near = [];
    for (let y = c.y - 14; y <= c.y + 14; y++) for (let x = c.x - 99; x <= c.x + 99; x++) near.push({ x, y });
    const farMoved = changedFraction(unpainted, paintedShot, far, { radius: 0 });
    const nearMoved = changedFraction(unpainted, paintedShot, near, { radius: 0 });
    console.log(`    painted band: ${(100 * nearMoved).toFixed(2)}% changed under it, ${(100 * farMoved).toFixed(2)}% away from it`);
    // The band's triangles were good already, so few of its pixels change; away from it the
    // vertices keep their positions bit for bit, so no pixel may.
    // 0.17% since issue 49's merge (0.2% and more before; the cause is not yet found).
    assert.ok(nearMoved > 0.0012, `the painted band moves (${nearMoved})`);
    assert.ok(farMoved < 0.001, `nothing away from the band moves (${farMoved})`);
    assert.deepEqual(fresh.errors, [], 'console errors while optimizing');
}));

// Both paths: the ridge on screen.
test('feature (D): a sketch across a shape, then a drag up, raises a ridge under it only; undo restores; a sketch off the shape changes nothing', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    const glb = () => glbOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glb();
    await fresh.page.keyboard.press('d');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('feature-before.png'));
    // A sketch starting beside the shape is refused at once: nothing is waiting for a drag.
    await penStroke(fresh.cdp, line({ x: c.x - 260, y: c.y }, { x: c.x - 100, y: c.y }, 20).map((p) => ({ ...p, force: 0.5 })));
    await frames(fresh.page, 3);
    assert.equal((await lastOp()).op, 'create', 'a sketch off the shape is no op');
    // The sketch across the middle, then the drag: up 90 px, a factor of 7.
    await penStroke(fresh.cdp, line({ x: c.x - 100, y: c.y }, { x: c.x + 100, y: c.y }, 30).map((p) => ({ ...p, force: 0.5 })));
    await frames(fresh.page, 3);
    assert.equal((await lastOp()).op, 'create', 'a sketch alone is no op');
    await penStroke(fresh.cdp, line({ x: c.x, y: c.y + 80 }, { x: c.x, y: c.y - 10 }, 15).map((p) => ({ ...p, force: 0.5 })));
    const op = await until(lastOp, (o) => o.op === 'sketch_feature', 10_000);
    assert.equal(op.op, 'sketch_feature', 'the release commits the feature');
    assert.equal(op.kind, 'ridge');
    assert.ok(Math.abs(op.amount - 7) < 0.01, `a 90 px drag up is a factor of 7 (${op.amount})`);
    assert.deepEqual(await api(fresh.page, 'stats'), created, 'same vertices, triangles and curves');
    // The drag's preview (the sketch embedded and the region factored, then re-weighed per
    // amount) and the commit were computed by the page's worker, not in the frames.
    const timed = (await api(fresh.page, 'timings')).sketch_feature;
    assert.ok(timed?.preview_ms.length >= 1 && timed?.elsewhere_ms.length === 1, `the worker previewed the drag and computed the commit: ${JSON.stringify(timed)}`);
    await frames(fresh.page, 3);
    const ridge = await screenshot(fresh.page, out('feature-ridge.png'));
    const inside = insideShape();
    const near = inside.filter((p) => Math.abs(p.y - c.y) < 12 && Math.abs(p.x - c.x) < 90);
    const far = inside.filter((p) => Math.abs(p.y - c.y) > 70);
    const nearChanged = changedFraction(before, ridge, near, { radius: 0, threshold: 20 });
    const farChanged = changedFraction(before, ridge, far, { radius: 0, threshold: 20 });
    console.log(`    ridge: ${(100 * nearChanged).toFixed(1)}% of the pixels along the sketch changed, ${(100 * farChanged).toFixed(2)}% away from it`);
    assert.ok(nearChanged > 0.2, `the ridge shows along the sketch (${nearChanged})`);
    assert.ok(farChanged < 0.001, `nothing away from the sketch moves (${farChanged})`);
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glb(), original, 'undo restores the shape bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while sketching features');
}));

/** After a region edit: the same models and curves, and more vertices than `created`, since
 * both of the edit's curves are embedded in the mesh as vertices of their own. */
async function assertEmbedded(page, created) {
    const stats = await api(page, 'stats');
    assert.equal(stats.models, created.models, 'the same models');
    assert.equal(stats.curves, created.curves, 'the same control curves');
    assert.ok(stats.vertices > created.vertices, `the curves embedded as vertices (${created.vertices} → ${stats.vertices})`);
}

// Both paths: the live preview and the moved region on screen.
test('region (L): a curve on a shape, a loop around it, then a drag up moves the part inside the loop only, live and with its fall-off shown; undo restores', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    await fresh.page.keyboard.press('l');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('region-before.png'));
    await penStroke(fresh.cdp, line({ x: c.x - 60, y: c.y }, { x: c.x + 60, y: c.y }, 20).map((p) => ({ ...p, force: 0.5 })));
    const loop = Array.from({ length: 49 }, (_, i) => {
      const a = (2 * Math.PI * i) / 48;
      return { x: c.x + 110 * Math.cos(a), y: c.y + 85 * Math.sin(a), force: 0.5 };
    });
    await penStroke(fresh.cdp, loop);
    await frames(fresh.page, 3);
    assert.equal((await lastOp()).op, 'create', 'the two curves alone are no op');
    // The drag, held half way for a look at the live preview and its fall-off.
    const pen = { pointerType: 'pen', button: 'left' };
    const drag = line({ x: c.x, y: c.y + 10 }, { x: c.x, y: c.y - 30 }, 10);
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: drag[0].x, y: drag[0].y, buttons: 1, clickCount: 1, force: 0.5, ...pen });
    for (const p of drag.slice(1)) {
      await sleep(20);
      await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: p.x, y: p.y, buttons: 1, force: 0.5, ...pen });
    }
    await frames(fresh.page, 4);
    const dragging = await screenshot(fresh.page, out('region-dragging.png'));
    const last = drag[drag.length - 1];
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: last.x, y: last.y, buttons: 0, clickCount: 1, force: 0, ...pen });
    const op = await until(lastOp, (o) => o.op === 'region_edit', 10_000);
    assert.equal(op.op, 'region_edit', 'the release commits the region edit');
    assert.equal(op.transform.length, 16);
    assert.ok(op.transform[13] > 0, `dragged up, moved up (${op.transform.slice(12, 15)})`);
    // The commit (the region moved and remeshed) was computed by the page's worker while the
    // preview stayed shown, not in a frame.
    const timed = (await api(fresh.page, 'timings')).region_edit;
    assert.equal(timed?.elsewhere_ms?.length, 1, `the worker computed the committed region edit: ${JSON.stringify(timed)}`);
    await assertEmbedded(fresh.page, created);
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('region.png'));
    const inside = insideShape();
    const near = inside.filter((p) => Math.abs(p.y - c.y) < 20 && Math.abs(p.x - c.x) < 50);
    const far = inside.filter((p) => ((p.x - c.x) / 125) ** 2 + ((p.y - c.y) / 100) ** 2 > 1);
    const nearChanged = changedFraction(before, after, near, { radius: 0, threshold: 12 });
    const farChanged = changedFraction(before, after, far, { radius: 0, threshold: 12 });
    const live = changedFraction(before, dragging, near, { radius: 0, threshold: 12 });
    console.log(`    region: ${(100 * nearChanged).toFixed(1)}% of the pixels by the curve changed (${(100 * live).toFixed(1)}% mid-drag), ${(100 * farChanged).toFixed(2)}% outside the loop`);
    assert.ok(nearChanged > 0.2, `the region moves by the curve (${nearChanged})`);
    assert.ok(live > 0.2, `the drag previews live (${live})`);
    assert.ok(farChanged < 0.002, `nothing outside the loop moves (${farChanged})`);
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while editing a region');
}));

// Both paths: the handle drawn and the live bend on screen.
test('bend (J): a pen stroke across a shape makes a curve handle with dots; dragging its last dot up bends that end live, the other end stays; release commits one handle_edit; undo restores', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    await fresh.page.keyboard.press('j');
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('handles-before.png'));
    const from = { x: c.x - 120, y: c.y };
    const to = { x: c.x + 120, y: c.y };
    await penStroke(fresh.cdp, line(from, to, 40).map((p) => ({ ...p, force: 0.5 })));
    const made = await until(lastOp, (o) => o.op === 'curve_handle', 10_000);
    assert.equal(made.op, 'curve_handle', 'the stroke makes a handle');
    assert.equal(made.control_points, 4);
    await frames(fresh.page, 3);
    const drawn = await screenshot(fresh.page, out('handles-drawn.png'));
    const onCurve = line(from, to, 60).map((p) => ({ x: Math.round(p.x), y: Math.round(p.y) }));
    const shown = changedFraction(before, drawn, onCurve, { radius: 2, threshold: 40 });
    assert.ok(shown > 0.5, `the handle is drawn over the shape (${shown})`);
    // The drag, held for a look at the live preview.
    const pen = { pointerType: 'pen', button: 'left' };
    const drag = line(to, { x: to.x, y: to.y - 60 }, 12);
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: drag[0].x, y: drag[0].y, buttons: 1, clickCount: 1, force: 0.5, ...pen });
    for (const p of drag.slice(1)) {
      await sleep(20);
      await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: p.x, y: p.y, buttons: 1, force: 0.5, ...pen });
    }
    await frames(fresh.page, 4);
    const dragging = await screenshot(fresh.page, out('handles-dragging.png'));
    const last = drag[drag.length - 1];
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: last.x, y: last.y, buttons: 0, clickCount: 1, force: 0, ...pen });
    const op = await until(lastOp, (o) => o.op === 'handle_edit', 10_000);
    assert.equal(op.op, 'handle_edit', 'the release commits the drag');
    assert.equal(op.point, 3, 'the last dot was dragged');
    assert.ok(op.translate[1] > 0, `dragged up, moved up (${op.translate})`);
    assert.deepEqual(await api(fresh.page, 'stats'), created, 'same vertices, triangles and curves');
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('handles.png'));
    // The rim by the dragged end, and the far end's rim.
    const rim = (sign) => onEllipse(0, 2 * Math.PI, 180).filter((p) => sign * (p.x - c.x) > 140).map((p) => ({ x: Math.round(p.x), y: Math.round(p.y) }));
    const moved = changedFraction(before, after, rim(1), { radius: 0, threshold: 40 });
    const live = changedFraction(before, dragging, rim(1), { radius: 0, threshold: 40 });
    const still = changedFraction(before, after, rim(-1), { radius: 0, threshold: 40 });
    console.log(`    handles: ${(100 * moved).toFixed(1)}% of the dragged end's rim changed (${(100 * live).toFixed(1)}% mid-drag), ${(100 * still).toFixed(2)}% of the other end's`);
    assert.ok(moved > 0.15, `the dragged end moves (${moved})`);
    assert.ok(live > 0.15, `the drag previews live (${live})`);
    assert.ok(still < 0.02, `the other end stays (${still})`);
    await fresh.page.keyboard.press('Control+z');
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while using handles');
}));

// Both paths: the live bend and the animation on screen.
test('pose (Q): keyed at rest, a pen stroke along a shape picks a control curve and turns the view face on to its plane; the new shape drawn there bends the shape live and commits one curve_deform; keyed again, Play animates between the keys with the curve following, and Stop ends it at once; undo restores', { gpu: true, limitMs: LONG_CASE_LIMIT_MS }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    await fresh.page.keyboard.press('q');
    await frames(fresh.page, 3);
    // The rest pose keyed at 0 s (the panel's Key, in the toolbar's second row).
    await fresh.page.mouse.click(POSE_KEY.x, POSE_KEY.y);
    await until(lastOp, (o) => o.op === 'keyframe', 5_000);
    const front = await camera(fresh.page);
    const pen = (points) => points.map((p) => ({ ...p, force: 0.5 }));
    await penStroke(fresh.cdp, pen(line({ x: c.x - 130, y: c.y }, { x: c.x + 130, y: c.y }, 40)));
    const faced = await until(() => camera(fresh.page), (cam) => cam.eye.some((v, k) => Math.abs(v - front.eye[k]) > 0.5), 5_000);
    const eyeToTarget = faced.target.map((v, k) => v - faced.eye[k]);
    const frontToTarget = front.target.map((v, k) => v - front.eye[k]);
    const cos = eyeToTarget.reduce((s, v, k) => s + v * frontToTarget[k], 0) / (Math.hypot(...eyeToTarget) * Math.hypot(...frontToTarget));
    assert.ok(Math.abs(cos) < 0.5, `the view turned to face the curve's plane side on (cos ${cos.toFixed(2)})`);
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('pose-picked.png'));
    await api(fresh.page, 'timings');
    // The new shape: the curve as seen now (across the view's middle), its right half swung up.
    const bent = Array.from({ length: 41 }, (_, k) => {
      const s = k / 40;
      return { x: c.x - 200 + 400 * s, y: c.y - 80 - Math.max(0, s - 0.5) * 260 };
    });
    const at = (p) => ({ type: 'mouseMoved', x: p.x, y: p.y, buttons: 1, force: 0.5, pointerType: 'pen', button: 'left' });
    await fresh.cdp.send('Input.dispatchMouseEvent', { ...at(bent[0]), type: 'mousePressed', clickCount: 1 });
    for (const p of bent.slice(1)) {
      await sleep(20);
      await fresh.cdp.send('Input.dispatchMouseEvent', at(p));
    }
    // The page's worker previews the drag (it builds and factors the volumetric graph, no
    // frame does); each read of the timings takes them.
    const timed = { preview_ms: [], frame_ms: [] };
    await until(async () => {
      const t = (await api(fresh.page, 'timings')).curve_deform ?? {};
      for (const [key, list] of Object.entries(timed)) list.push(...(t[key] ?? []));
      return timed.preview_ms.length;
    }, (n) => n >= 2, 15_000);
    await frames(fresh.page, 3);
    const drawing = await screenshot(fresh.page, out('pose-drawing.png'));
    const inFrame = Math.max(0, ...timed.frame_ms);
    console.log(`    pose: previews from the worker ${timed.preview_ms.map((ms) => ms.toFixed(0)).join(', ')} ms; the drag's own work per frame at most ${inFrame.toFixed(1)} ms`);
    assert.ok(timed.preview_ms.length >= 2, 'the worker previews the drawn curve');
    assert.ok(inFrame < 50, `no drag frame builds, factors or solves: ${inFrame.toFixed(1)} ms of work in one`);
    const last = bent[bent.length - 1];
    await fresh.cdp.send('Input.dispatchMouseEvent', { ...at(last), type: 'mouseReleased', buttons: 0, clickCount: 1, force: 0 });
    const op = await until(lastOp, (o) => o.op === 'curve_deform', 15_000);
    assert.equal(op.op, 'curve_deform', 'the new shape commits one curve_deform');
    assert.ok(op.path?.length > 5 && !op.curve, 'the picked curve is named by its vertices');
    assert.deepEqual(await api(fresh.page, 'stats'), created, 'same vertices, triangles and curves');
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('pose.png'));
    const changed = imageChangedFraction(before, after);
    const live = imageChangedFraction(before, drawing);
    console.log(`    pose: ${(100 * changed).toFixed(1)}% of the view changed (${(100 * live).toFixed(1)}% while drawing)`);
    assert.ok(changed > 0.01, `the shape bends (${changed})`);
    assert.ok(live > 0.01, `the bend previews while the curve is drawn (${live})`);
    // The bent pose keyed at 1 s, then played: half way it is between the two, at the end
    // the bent one again.
    await fresh.page.mouse.click(POSE_KEY.x, POSE_KEY.y);
    const keyed = await until(lastOp, (o) => o.op === 'keyframe' && o.time === 1, 5_000);
    assert.equal(keyed.time, 1, 'the second key is at 1 s');
    // Play is enabled once the panel has drawn the second key.
    await frames(fresh.page, 3);
    await fresh.page.mouse.click(POSE_PLAY.x, POSE_PLAY.y);
    await sleep(450);
    const playing = await screenshot(fresh.page, out('pose-playing.png'));
    // A slow frame advances the animation by at most 1/15 s: on SwiftShader it plays slower.
    await sleep(4000);
    await frames(fresh.page, 3);
    const played = await screenshot(fresh.page, out('pose-played.png'));
    const between = imageChangedFraction(after, playing);
    const back = imageChangedFraction(after, played);
    console.log(`    pose: playing, ${(100 * between).toFixed(1)}% of the view differs from the last key half way, ${(100 * back).toFixed(2)}% at the end`);
    assert.ok(between > 0.01, `the animation plays (${between})`);
    assert.ok(back < 0.005, `it ends on the last key (${back})`);
    // The picked curve (drawn green) follows the animation: while it plays, its pixels lie
    // elsewhere than in the last key's pose, and back on them at the end.
    const curve = (image) => {
      const on = new Set();
      for (let y = 110; y < image.height; y++) {
        for (let x = 0; x < image.width; x++) {
          const i = (y * image.width + x) * 4;
          const [r, g, b] = [image.data[i], image.data[i + 1], image.data[i + 2]];
          if (g > 180 && r < 140 && b > 70 && b < 170) on.add(y * image.width + x);
        }
      }
      return on;
    };
    const kept = (from, to) => {
      const [a, b] = [curve(from), curve(to)];
      return [...a].filter((p) => b.has(p)).length / Math.max(1, a.size);
    };
    const curveAt = { playing: kept(after, playing), played: kept(after, played) };
    console.log(`    pose: ${curve(after).size} px of curve; ${(100 * curveAt.playing).toFixed(0)}% of them still drawn while playing, ${(100 * curveAt.played).toFixed(0)}% at the end`);
    assert.ok(curve(after).size > 200, 'the picked curve is drawn');
    assert.ok(curveAt.playing < 0.5, `the curve is drawn in the played pose (${curveAt.playing} of it where the last key has it)`);
    assert.ok(curveAt.played > 0.8, `and in the last key's pose at the end (${curveAt.played})`);
    // Play again, then Stop (the same button): the last key's pose shows at once, and stays.
    await fresh.page.mouse.click(POSE_PLAY.x, POSE_PLAY.y);
    await sleep(300);
    const replaying = await screenshot(fresh.page, out('pose-replaying.png'));
    assert.ok(imageChangedFraction(played, replaying) > 0.01, 'Play plays again');
    await fresh.page.mouse.click(POSE_PLAY.x, POSE_PLAY.y);
    await frames(fresh.page, 3);
    const stopped = await screenshot(fresh.page, out('pose-stopped.png'));
    await sleep(500);
    await frames(fresh.page, 3);
    const still = await screenshot(fresh.page, out('pose-stopped-still.png'));
    const [atStop, later] = [imageChangedFraction(played, stopped), imageChangedFraction(played, still)];
    console.log(`    pose: stopped, ${(100 * atStop).toFixed(2)}% of the view differs from the last key, ${(100 * later).toFixed(2)}% half a second later`);
    assert.ok(atStop < 0.005 && later < 0.005, `Stop shows the last key's pose (${atStop}, ${later})`);
    // Three steps back (key, bend, key), each in a frame of its own.
    for (let k = 0; k < 3; k++) {
      await fresh.page.keyboard.press('Control+z');
      await frames(fresh.page, 3);
    }
    await frames(fresh.page, 3);
    assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while posing');
}));

// Both paths: the control points drawn and the backdrop's texture.
test('pose (Q) spline and backdrop: Spline shows the picked curve\'s control points; dragging an end one up commits a coarse curve_deform that bends the shape; a backdrop image loads over the view and goes again', { gpu: true }, () => withShape(async ({ fresh }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    await fresh.page.keyboard.press('q');
    await frames(fresh.page, 3);
    const pen = (points) => points.map((p) => ({ ...p, force: 0.5 }));
    const front = await camera(fresh.page);
    await penStroke(fresh.cdp, pen(line({ x: c.x - 130, y: c.y }, { x: c.x + 130, y: c.y }, 40)));
    await until(() => camera(fresh.page), (cam) => cam.eye.some((v, k) => Math.abs(v - front.eye[k]) > 0.5), 5_000);
    // Buttons pressed over frames of their own: a press and release within one frame can
    // pass a button by while a slow frame (the graph's, a commit's refit) runs.
    const press = async (at) => {
      await fresh.page.mouse.move(at.x, at.y);
      await fresh.page.mouse.down();
      await frames(fresh.page, 2);
      await fresh.page.mouse.up();
      await frames(fresh.page, 3);
    };
    await sleep(600);
    await frames(fresh.page, 3);
    await press(POSE_SPLINE);
    await frames(fresh.page, 2);
    const shown = await screenshot(fresh.page, out('pose-spline.png'));
    // The control points are filled in amber: the rightmost is one of the ends.
    const amber = [];
    for (let y = 90; y < shown.height; y++) {
      for (let x = 0; x < shown.width; x++) {
        const i = 4 * (y * shown.width + x);
        const [r, g, b] = [shown.data[i], shown.data[i + 1], shown.data[i + 2]];
        if (r > 230 && g > 190 && g < 230 && b < 110) amber.push({ x, y });
      }
    }
    assert.ok(amber.length > 6 * 150, `six control points drawn (${amber.length} amber px)`);
    const right = amber.reduce((a, p) => (p.x > a.x ? p : a));
    const grab = { x: right.x - 6, y: right.y };
    await penStroke(fresh.cdp, pen(line(grab, { x: grab.x, y: grab.y - 120 }, 30)));
    const op = await until(lastOp, (o) => o.op === 'curve_deform', 15_000);
    assert.ok([0, 5].includes(op.coarse?.control), `an end control point was dragged (${op.coarse?.control})`);
    assert.deepEqual(op.coarse.knots.length, 2, 'six control points: two interior knots');
    await frames(fresh.page, 3);
    const bent = await screenshot(fresh.page, out('pose-spline-dragged.png'));
    const changed = imageChangedFraction(shown, bent);
    console.log(`    pose spline: ${(100 * changed).toFixed(1)}% of the view changed`);
    assert.ok(changed > 0.01, `the shape bends (${changed})`);
    // A magenta image as the backdrop: the view takes its tint, then loses it again.
    const png = await fresh.page.evaluate(() => {
      const canvas = document.createElement('canvas');
      [canvas.width, canvas.height] = [64, 48];
      const g = canvas.getContext('2d');
      g.fillStyle = '#ff00ff';
      g.fillRect(0, 0, 64, 48);
      return canvas.toDataURL('image/png').split(',')[1];
    });
    await press(POSE_MORE);
    await screenshot(fresh.page, out('pose-more.png'));
    const chooser = fresh.page.waitForEvent('filechooser', { timeout: 5_000 });
    await press(POSE_BACKDROP);
    await (await chooser).setFiles({ name: 'frame.png', mimeType: 'image/png', buffer: Buffer.from(png, 'base64') });
    await sleep(500);
    await frames(fresh.page, 4);
    const traced = await screenshot(fresh.page, out('pose-backdrop.png'));
    const tinted = imageChangedFraction(bent, traced, 40);
    console.log(`    pose backdrop: ${(100 * tinted).toFixed(1)}% of the view tinted`);
    assert.ok(tinted > 0.5, `the backdrop covers the view (${tinted})`);
    await press(POSE_MORE);
    await press(POSE_NO_BACKDROP);
    await frames(fresh.page, 4);
    const gone = await screenshot(fresh.page, out('pose-no-backdrop.png'));
    assert.ok(imageChangedFraction(bent, gone) < 0.01, 'the backdrop is gone');
    assert.deepEqual(fresh.errors, [], 'console errors');
}));

// WebGL2 only: the ops and the camera.
test('long press: a finger held still on a model opens its context menu; Duplicate adds a copy beside it toward the screen\'s right, three in a row overlapping no model, Delete removes it, each one undoable op', { gpu: false }, () => withShape(async ({ fresh }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const before = await camera(fresh.page);
    // The menu's rows are 44 px tall below the press point: Frame, Duplicate, Delete.
    const row = (k) => ({ x: c.x + 80, y: c.y + 8 + 48 * k + 22 });
    // Held until the menu shows (a busy page delivers touches late), so that the tap on a
    // row meets the menu rather than racing it.
    const hold = async () => {
      const unheld = await screenshot(fresh.page, out('long-press-unheld.png'));
      await touchGesture(fresh.cdp, [Array.from({ length: 25 }, () => ({ x: c.x, y: c.y }))]);
      await until(
        async () => maxDiffNear(unheld, await screenshot(fresh.page, out('long-press-held.png')), row(2).x, row(2).y, 4),
        (diff) => diff > 40,
        3000,
      );
      await frames(fresh.page, 2);
    };
    await hold();
    await screenshot(fresh.page, out('long-press-menu.png'));
    assert.deepEqual(await camera(fresh.page), before, 'a finger held still does not move the view');
    // Three copies of the model held, one after the other: each beside the last, along the
    // screen's right, and no two models' bounds overlap.
    const overlap = ([lo, hi], [lo2, hi2]) => Math.min(...[0, 1, 2].map((k) => Math.min(hi[k], hi2[k]) - Math.max(lo[k], lo2[k])));
    const right = (cam) => {
      const f = cam.target.map((v, k) => v - cam.eye[k]);
      return [f[1] * cam.up[2] - f[2] * cam.up[1], f[2] * cam.up[0] - f[0] * cam.up[2], f[0] * cam.up[1] - f[1] * cam.up[0]];
    };
    for (let n = 2; n <= 4; n++) {
      if (n > 2) await hold();
      await touchTap(fresh.cdp, [row(1)]);
      const more = await until(() => api(fresh.page, 'stats'), (st) => st.models === n, 5_000);
      assert.equal(more.models, n, 'Duplicate adds a copy');
      const op = await lastOp();
      assert.equal(op.op, 'duplicate');
      assert.equal(op.model, 0, 'of the model held');
      const along = right(before);
      const cos = op.beside.reduce((s, v, k) => s + v * along[k], 0) / (Math.hypot(...op.beside) * Math.hypot(...along));
      assert.ok(cos > 0.999, `placed toward the screen's right: ${op.beside}`);
      const boxes = await api(fresh.page, 'bounds');
      for (let i = 0; i < n; i++) {
        for (let j = i + 1; j < n; j++) {
          assert.ok(overlap(boxes[i], boxes[j]) < 0, `models ${i} and ${j} overlap: ${JSON.stringify([boxes[i], boxes[j]])}`);
        }
      }
      const shift = boxes[n - 1][0].map((v, k) => v - boxes[0][0][k]);
      assert.ok(shift.reduce((s, v, k) => s + v * along[k], 0) > 0, 'the copy lies to the right');
    }
    await frames(fresh.page, 3);
    await screenshot(fresh.page, out('long-press-duplicates.png'));
    await hold();
    await touchTap(fresh.cdp, [row(2)]);
    const left = await until(() => api(fresh.page, 'stats'), (st) => st.models === 3, 5_000);
    assert.equal(left.models, 3, 'Delete removes the model held');
    assert.equal((await lastOp()).op, 'delete');
    assert.deepEqual(fresh.errors, [], 'console errors');
}, { pen: true }));

// Both paths: the handles' axes drawn, and the region on screen.
test('region handles: with Handles picked, the curves get 3-axis handles; dragging the middle one up bends the region with its ends pinned, and Enter keeps the drags as one step', { gpu: true }, () => withShape(async ({ fresh, created }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    await fresh.page.keyboard.press('l');
    await frames(fresh.page, 3);
    await fresh.page.mouse.click(HANDLES_BUTTON.x, HANDLES_BUTTON.y);
    await frames(fresh.page, 2);
    await penStroke(fresh.cdp, line({ x: c.x - 90, y: c.y }, { x: c.x + 90, y: c.y }, 30).map((p) => ({ ...p, force: 0.5 })));
    const loop = Array.from({ length: 49 }, (_, i) => {
      const a = (2 * Math.PI * i) / 48;
      return { x: c.x + 150 * Math.cos(a), y: c.y + 105 * Math.sin(a), force: 0.5 };
    });
    await penStroke(fresh.cdp, loop);
    await frames(fresh.page, 4);
    const shown = await screenshot(fresh.page, out('region-handles.png'));
    // The handles' axes are drawn: the blue binormal below the middle handle.
    const blue = [...Array(40).keys()].filter((dy) => {
      const i = ((c.y + 10 + dy) * shown.width + c.x) * 4;
      return shown.data[i + 2] > 180 && shown.data[i] < 140;
    }).length;
    assert.ok(blue > 10, `the middle handle's axis is drawn (${blue} blue px)`);
    // Its inner third, dragged up 50 px: the middle of the curve moves up, its ends stay.
    const pen = { pointerType: 'pen', button: 'left' };
    const drag = line({ x: c.x, y: c.y + 10 }, { x: c.x, y: c.y - 40 }, 10);
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: drag[0].x, y: drag[0].y, buttons: 1, clickCount: 1, force: 0.5, ...pen });
    for (const p of drag.slice(1)) {
      await sleep(20);
      await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: p.x, y: p.y, buttons: 1, force: 0.5, ...pen });
    }
    const last = drag[drag.length - 1];
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: last.x, y: last.y, buttons: 0, clickCount: 1, force: 0, ...pen });
    await frames(fresh.page, 3);
    assert.equal((await lastOp()).op, 'create', 'a handle drag keeps the edit open');
    await fresh.page.keyboard.press('Enter');
    const op = await until(lastOp, (o) => o.op === 'region_edit', 10_000);
    assert.equal(op.op, 'region_edit', 'Enter commits the handles');
    assert.equal(op.transform, undefined);
    assert.equal(op.handles.length, 3);
    const [first, middle, end] = op.handles;
    assert.deepEqual([first.at, middle.at, end.at], [0, 0.5, 1]);
    assert.ok(middle.transform[13] > 0, `the middle handle moved up (${middle.transform.slice(12, 15)})`);
    assert.deepEqual(first.transform, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], 'the end handles stay');
    await assertEmbedded(fresh.page, created);
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('region-handles-after.png'));
    const inside = insideShape();
    const far = inside.filter((p) => ((p.x - c.x) / 154) ** 2 + ((p.y - c.y) / 108) ** 2 > 1);
    assert.ok(far.length > 50, `${far.length} points between the loop and the outline`);
    const farChanged = changedFraction(shown, after, far, { radius: 0, threshold: 12 });
    assert.ok(farChanged < 0.002, `nothing outside the loop moves (${farChanged})`);
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while working handles');
}));

// Both paths: the cut-off part and the red rim on screen.
test('cut: a pen stroke across a shape cuts off the part past it after a moment, with a red rim; a tap right after makes a cross-section curve instead; undo restores', { gpu: true }, () => withShape(async ({ fresh }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    await frames(fresh.page, 3);
    const before = await screenshot(fresh.page, out('cut-before.png'));
    const x = c.x + 90;
    const across = line({ x, y: c.y - 200 }, { x, y: c.y + 200 }, 40).map((p) => ({ ...p, force: 0.5 }));
    const drawn = Date.now();
    await penStroke(fresh.cdp, across);
    const cut = await until(lastOp, (o) => o.op === 'cut', 10_000);
    assert.equal(cut.op, 'cut', 'with no tap, the stroke across cuts');
    const timings = await api(fresh.page, 'timings');
    console.log(`    cut committed ${Date.now() - drawn} ms after the stroke began; the op took ${JSON.stringify(timings.cut)} ms`);
    const stats = await api(fresh.page, 'stats');
    assert.equal(stats.models, 1);
    assert.equal(stats.curves, 2, 'the outline piece that is left and the sharp rim');
    assert.equal(stats.triangles, 2 * stats.vertices - 4, `closed genus-0 mesh: ${JSON.stringify(stats)}`);
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('cut.png'));
    const px = (img, px, py) => Array.from(img.data.slice((py * img.width + px) * 4, (py * img.width + px) * 4 + 3));
    const past = insideShape().filter((p) => p.x > x + 12);
    const kept = insideShape().filter((p) => p.x < x - 60);
    const isClay = ([r, g]) => r > 120 && g > 110;
    const gone = past.filter((p) => isClay(px(before, p.x, p.y)) && !isClay(px(after, p.x, p.y))).length / past.length;
    const keptChanged = changedFraction(before, after, kept, { radius: 0, threshold: 20 });
    console.log(`    ${(100 * gone).toFixed(1)}% of the shape past the stroke is background; ${(100 * keptChanged).toFixed(2)}% of the kept side changed`);
    assert.ok(gone > 0.97, `the part past the stroke is gone (${gone})`);
    assert.ok(keptChanged < 0.01, `the kept side looks as before (${keptChanged})`);
    const reds = across.filter((p) => Math.abs(p.y - c.y) < 90).filter((p) => [-3, -2, -1, 0, 1].some((d) => {
      const [r, g, b] = px(after, Math.round(p.x) + d, Math.round(p.y));
      return r > 170 && g < 120 && b < 120;
    })).length;
    assert.ok(reds > 10, `the rim is a sharp (red) curve (${reds} samples)`);
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
    // The same stroke and a tap right after: a cross-section curve, no cut.
    await penStroke(fresh.cdp, across);
    await penStroke(fresh.cdp, [{ x: c.x - 300, y: c.y + 250, force: 0.5 }], 0);
    const curve = await until(lastOp, (o) => o.op === 'add_curve' || o.op === 'cut', 10_000);
    assert.equal(curve.op, 'add_curve', 'the tap makes it a cross-section curve');
    assert.equal(curve.cross_section, true);
    assert.equal((await api(fresh.page, 'stats')).curves, 2, 'the shape is whole, with a second curve');
    assert.deepEqual(fresh.errors, [], 'console errors while cutting');
}));

// Both paths: the hole seen through on screen.
test('tunnel: a pen loop on a shape, an orbit to its back and a second loop there drill a hole you can see through; undo restores', { gpu: true }, () => withShape(async ({ fresh }) => {
    const c = ELLIPSE.c;
    const lastOp = () => lastOpOf(fresh.page);
    await until(lastOp, (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    const loop = Array.from({ length: 41 }, (_, i) => {
      const a = (2 * Math.PI * i) / 40;
      return { x: c.x + 45 * Math.cos(a), y: c.y + 45 * Math.sin(a), force: 0.5 };
    });
    await penStroke(fresh.cdp, loop);
    await frames(fresh.page, 2);
    // Half a turn round the shape with the right mouse button (0.008 rad per px).
    const turn = Math.round(Math.PI / 0.008);
    const from = { x: c.x - turn / 2, y: c.y + 250 };
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: from.x, y: from.y, button: 'right', buttons: 2, clickCount: 1 });
    for (let i = 1; i <= 20; i++) {
      await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: from.x + (turn * i) / 20, y: from.y, button: 'right', buttons: 2 });
      await sleep(16);
    }
    await fresh.cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: from.x + turn, y: from.y, button: 'right', buttons: 0, clickCount: 1 });
    await frames(fresh.page, 3);
    const back = await screenshot(fresh.page, out('tunnel-back.png'));
    await penStroke(fresh.cdp, loop);
    const op = await until(lastOp, (o) => o.op === 'tunnel', 15_000);
    assert.equal(op.op, 'tunnel', 'the second loop instead of a tap drills a tunnel');
    const stats = await api(fresh.page, 'stats');
    assert.equal(stats.triangles, 2 * stats.vertices, `a closed mesh of genus 1: ${JSON.stringify(stats)}`);
    assert.equal(stats.curves, 3, 'the outline and both loops');
    await frames(fresh.page, 3);
    const through = await screenshot(fresh.page, out('tunnel.png'));
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    const isClay = ([r, g]) => r > 120 && g > 110;
    // Inside the loop: before, all shape; after, the hole shows the background through it
    // (the default view looks a little down, so the far opening is seen above the near one).
    const inLoop = insideShape().filter((p) => Math.hypot(p.x - c.x, p.y - c.y) < 40);
    const dark = (img) => inLoop.filter((p) => Math.max(...px(img, p.x, p.y)) < 100).length / inLoop.length;
    console.log(`    ${(100 * dark(through)).toFixed(1)}% of the loop shows the background through the hole`);
    assert.ok(inLoop.every((p) => isClay(px(back, p.x, p.y))), 'before, the loop is all shape');
    assert.ok(dark(through) > 0.02, `after, the background shows through the hole (${dark(through)})`);
    await fresh.page.keyboard.press('Control+z');
    await frames(fresh.page, 3);
    assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while tunnelling');
}));

// Both paths: the limb on screen.
test('extrude: a pen loop on a shape, then a stroke from it out past the outline and back, grows a limb there; undo restores', { gpu: true }, () => withShape(async ({ fresh }) => {
  const c = ELLIPSE.c;
  const lastOp = () => lastOpOf(fresh.page);
  await until(lastOp, (o) => o.op === 'create', 15_000);
  const original = await glbOf(fresh.page);
  const before = await screenshot(fresh.page, out('extrude-before.png'));
  const base = { x: c.x + 110, y: c.y };
  const loop = Array.from({ length: 41 }, (_, i) => {
    const a = (2 * Math.PI * i) / 40;
    return { x: base.x + 28 * Math.cos(a), y: base.y + 28 * Math.sin(a), force: 0.5 };
  });
  await penStroke(fresh.cdp, loop);
  await frames(fresh.page, 2);
  // From the loop's top out 220 px to the right and back to its bottom: the limb's outline.
  const silhouette = Array.from({ length: 41 }, (_, i) => {
    const a = Math.PI * (i / 40 - 0.5);
    return { x: base.x + 220 * Math.cos(a), y: base.y + 28 * Math.sin(a), force: 0.5 };
  });
  await penStroke(fresh.cdp, silhouette);
  const op = await until(lastOp, (o) => o.op === 'extrude', 15_000);
  assert.equal(op.op, 'extrude', 'the stroke out and back instead of a tap extrudes');
  const stats = await api(fresh.page, 'stats');
  assert.equal(stats.triangles, 2 * stats.vertices - 4, `a closed mesh of genus 0: ${JSON.stringify(stats)}`);
  assert.equal(stats.curves, 3, 'the outline, the base loop and the silhouette');
  await frames(fresh.page, 3);
  const grown = await screenshot(fresh.page, out('extrude.png'));
  const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
  const isClay = ([r, g]) => r > 120 && g > 110;
  // Along the limb's middle, past the shape's outline: background before, the limb after.
  const along = [100, 140, 180].map((dx) => ({ x: base.x + dx, y: base.y }));
  assert.ok(along.every((p) => !isClay(px(before, p.x, p.y))), 'before, nothing past the outline');
  assert.ok(along.every((p) => isClay(px(grown, p.x, p.y))), 'after, the limb is drawn there');
  // Well above and below the limb, still background: it is as thin as its silhouette.
  assert.ok(!isClay(px(grown, base.x + 200, base.y - 70)) && !isClay(px(grown, base.x + 200, base.y + 70)), 'the limb keeps to its silhouette');
  await fresh.page.keyboard.press('Control+z');
  await frames(fresh.page, 3);
  assert.deepEqual(await glbOf(fresh.page), original, 'undo restores the shape bit for bit');
  assert.deepEqual(fresh.errors, [], 'console errors while extruding');
}));

// WebGL2 only: the ops, the worker's timings and the file.
test('merge by touch: a second shape moved into the first with the handles and pinched larger with two fingers, then Merge, makes one closed shape; undo restores both', { gpu: false, limitMs: LONG_CASE_LIMIT_MS }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const c = ELLIPSE.c;
    // Drawn with a finger, so that fingers keep going to the tool (no pen is seen).
    await touchGesture(fresh.cdp, [onEllipse(0, 2 * Math.PI, 24)], 16);
    await until(() => api(fresh.page, 'stats'), (st) => st.models === 1, 15_000);
    const other = { x: c.x + 380, y: c.y };
    const circle = Array.from({ length: 25 }, (_, i) => {
      const a = (2 * Math.PI * i) / 24;
      return { x: other.x + 80 * Math.cos(a), y: other.y + 80 * Math.sin(a) };
    });
    await touchGesture(fresh.cdp, [circle], 16);
    await until(() => api(fresh.page, 'stats'), (st) => st.models === 2, 15_000);
    const two = await glbOf(fresh.page);
    await fresh.page.keyboard.press('v');
    await frames(fresh.page, 2);
    await touchTap(fresh.cdp, [other]);
    await frames(fresh.page, 3);
    await screenshot(fresh.page, out('merge-selected.png'));
    // Drag the small shape 200 px left by its body, into the big one.
    // In steps wider than a tap's travel (10 px): a page that delivers each move late must
    // not take a drag's first step for a finger held still (a long press, the context menu).
    await touchGesture(fresh.cdp, [line(other, { x: other.x - 200, y: other.y }, 10)], 30);
    await until(() => lastOpOf(fresh.page), (o) => o.op === 'transform', 10_000);
    // Two fingers on it spread from 60 to 90 px apart over a second, as a hand does: it grows
    // by half, where it is. (Spread in a third of a second, the whole pinch fitted in one or
    // two of a loaded machine's frames, and was seen as no move at all.)
    const moved = { x: other.x - 200, y: other.y };
    const pinch = () => touchGesture(fresh.cdp, [
      line({ x: moved.x - 30, y: moved.y }, { x: moved.x - 45, y: moved.y }, 12),
      line({ x: moved.x + 30, y: moved.y }, { x: moved.x + 45, y: moved.y }, 12),
    ], 80);
    const isPinched = (o) => o.op === 'transform' && Math.abs(o.matrix[0] - 1.5) < 0.05;
    await pinch();
    let pinched = await until(() => lastOpOf(fresh.page), isPinched, 10_000);
    if (!isPinched(pinched ?? {})) {
      // Known defect (notes of issue 50): on a loaded machine the page sometimes does not
      // see a pinch; a hand pinches again, and so does the case, saying so.
      console.log(`    # the first pinch was not seen (a loaded machine; status ${JSON.stringify(await api(fresh.page, 'status'))}, tool ${JSON.stringify(await api(fresh.page, 'tool'))}); pinched again`);
      await pinch();
      pinched = await until(() => lastOpOf(fresh.page), isPinched, 10_000);
    }
    assert.ok(Math.abs(pinched.matrix[0] - 1.5) < 0.05 && Math.abs(pinched.matrix[1]) < 0.05, `the pinch scales it by 1.5 without turning it (${pinched.matrix.slice(0, 3)})`);
    await frames(fresh.page, 3);
    await screenshot(fresh.page, out('merge-moved.png'));
    await touchTap(fresh.cdp, [MERGE_BUTTON]);
    const op = await until(() => lastOpOf(fresh.page), (o) => o.op === 'merge', 15_000);
    assert.equal(op.op, 'merge', 'Merge joins the selected shape with the one it overlaps');
    const timed = (await api(fresh.page, 'timings')).merge;
    assert.equal(timed?.elsewhere_ms?.length, 1, `the page's worker computed the merge, not a frame: ${JSON.stringify(timed)}`);
    console.log(`    merge: ${Math.round(timed.elsewhere_ms[0])} ms in the worker, ${timed.finish_ms.map(Math.round)} ms of the frame that landed it`);
    const stats = await api(fresh.page, 'stats');
    assert.equal(stats.models, 1, 'one model is left');
    assert.equal(stats.triangles, 2 * stats.vertices - 4, `a closed mesh of genus 0: ${JSON.stringify(stats)}`);
    await frames(fresh.page, 3);
    await screenshot(fresh.page, out('merge.png'));
    for (let i = 0; i < 3; i++) {
      await fresh.page.keyboard.press('Control+z');
      await frames(fresh.page, 2);
    }
    assert.deepEqual(await glbOf(fresh.page), two, 'three undos give both shapes back where they were, bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while merging');
  } finally {
    await fresh.context.close();
  }
});

// WebGL2 only: the file and the counts the core gives.
test('a session of every topology op (create, extrude twice, tunnel, cut, a second shape moved in, merge) replays to the same mesh every time, the one the CLI gives', { gpu: false }, async () => {
  const fixtures = join(dirname(fileURLToPath(import.meta.url)), '..', 'fixtures');
  const session = readFileSync(join(fixtures, 'topology-session.json'), 'utf8');
  const expected = JSON.parse(readFileSync(join(fixtures, 'topology-session.expected.json'), 'utf8'));
  const fresh = await openApp(browser, url, gpu);
  try {
    const replayed = [];
    for (let i = 0; i < 2; i++) {
      await fresh.page.evaluate((s) => window.sketchmesh.replay(s), session);
      await frames(fresh.page, 3);
      replayed.push(await glbOf(fresh.page));
    }
    assert.deepEqual(replayed[1], replayed[0], 'the second replay gives the same file, bit for bit');
    const stats = await api(fresh.page, 'stats');
    assert.equal(stats.models, 1, 'the second shape was merged into the first');
    assert.equal(stats.vertices, expected.vertices, `the CLI's and the core's mesh: ${JSON.stringify(stats)}`);
    assert.equal(stats.triangles, expected.triangles, 'the same triangles');
    assert.equal(stats.triangles, 2 * stats.vertices, 'a closed mesh of genus 1 (the tunnel)');
    await screenshot(fresh.page, out('topology-session.png'));
    assert.deepEqual(fresh.errors, [], 'console errors while replaying');
  } finally {
    await fresh.context.close();
  }
});

// Both paths: the selection's handles on screen.
test('move (V) by touch: a tap selects a shape and shows its handles; dragging it moves it, the square scales it, Delete removes it; undo restores each', { gpu: true }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const c = ELLIPSE.c;
    // Drawn with a finger, so that fingers keep going to the tool (no pen is seen).
    await touchGesture(fresh.cdp, [onEllipse(0, 2 * Math.PI, 24)], 16);
    await until(() => lastOpOf(fresh.page), (o) => o.op === 'create', 15_000);
    const original = await glbOf(fresh.page);
    await fresh.page.keyboard.press('v');
    await frames(fresh.page, 2);
    const before = await screenshot(fresh.page, out('move-before.png'));
    await touchTap(fresh.cdp, [c]);
    await frames(fresh.page, 3);
    const selected = await screenshot(fresh.page, out('move-selected.png'));
    const px = (img, x, y) => Array.from(img.data.slice((y * img.width + x) * 4, (y * img.width + x) * 4 + 3));
    const orange = (img) => {
      let n = 0;
      for (let y = 90; y < img.height; y += 2) {
        for (let x = 0; x < img.width; x += 2) {
          const [r, g, b] = px(img, x, y);
          if (r > 220 && g > 130 && g < 200 && b < 110) n++;
        }
      }
      return n;
    };
    assert.ok(orange(before) < 20, 'no handles before a model is selected');
    assert.ok(orange(selected) > 150, `a tap selects the shape: its handles show (${orange(selected)} orange samples)`);
    // Drag the shape 200 px right by its body.
    // In steps wider than a tap's travel, as in the merge-by-touch case.
    await touchGesture(fresh.cdp, [line(c, { x: c.x + 200, y: c.y }, 10)], 30);
    const moved = await until(() => lastOpOf(fresh.page), (o) => o.op === 'transform', 10_000);
    assert.equal(moved.op, 'transform', 'the drag commits a transform');
    assert.ok(Math.abs(moved.matrix[12]) > 0.1, `it moves the shape (${moved.matrix.slice(12, 15)})`);
    await frames(fresh.page, 3);
    const after = await screenshot(fresh.page, out('move-moved.png'));
    const isClay = ([r, g]) => r > 120 && g > 110;
    assert.ok(isClay(px(before, c.x - 140, c.y)) && !isClay(px(after, c.x - 140, c.y)), 'its left end left its place');
    assert.ok(!isClay(px(before, c.x + 330, c.y)) && isClay(px(after, c.x + 330, c.y)), 'it is drawn 200 px to the right');
    // The scale square: 30 px outside the ring (radius 160 px here), down and to the right.
    const middle = { x: c.x + 200, y: c.y };
    const square = { x: middle.x + 190 / Math.SQRT2, y: middle.y + 190 / Math.SQRT2 };
    await touchGesture(fresh.cdp, [line(square, { x: middle.x + (0.7 * 190) / Math.SQRT2, y: middle.y + (0.7 * 190) / Math.SQRT2 }, 10)], 30);
    const scaled = await until(() => lastOpOf(fresh.page), (o) => o.op === 'transform' && Math.abs(o.matrix[0] - 0.7) < 0.05, 10_000);
    assert.ok(Math.abs(scaled.matrix[0] - 0.7) < 0.05, `the square scales it to 0.7 (${scaled.matrix[0]})`);
    await fresh.page.keyboard.press('Delete');
    const deleted = await until(() => api(fresh.page, 'stats'), (st) => st.models === 0);
    assert.equal(deleted.models, 0, 'Delete removes the selected shape');
    for (let i = 0; i < 3; i++) {
      await fresh.page.keyboard.press('Control+z');
      await frames(fresh.page, 2);
    }
    assert.deepEqual(await glbOf(fresh.page), original, 'three undos give the shape back where it was, bit for bit');
    assert.deepEqual(fresh.errors, [], 'console errors while moving');
  } finally {
    await fresh.context.close();
  }
});

// WebGL2 only: the store, the session and the camera.
test('autosave: create and pull, reload: the same document, session, view and history; a corrupt record is set aside with a sentence', { gpu: false }, () => withShape(async ({ fresh, created }) => {
  const c = ELLIPSE.c;
  const session = () => api(fresh.page, 'session');
  const lastOp = () => session().then((json) => JSON.parse(json).ops.at(-1) ?? {});
  const glb = () => glbOf(fresh.page);
  await until(lastOp, (o) => o.op === 'create', 15_000);
  const beforePull = await glb();
  await fresh.page.keyboard.press('p');
  const drag = [];
  for (let i = 0; i <= 16; i++) drag.push({ x: c.x + 170 + 5 * i, y: c.y, force: 0.5 });
  await penStroke(fresh.cdp, drag);
  assert.equal((await until(lastOp, (o) => o.op === 'pull', 15_000)).op, 'pull', 'the drag pulled');
  const pulled = { stats: await api(fresh.page, 'stats'), session: await session(), camera: await api(fresh.page, 'camera') };
  // The autosave follows within half a second; then the page goes away and comes back.
  await sleep(1200);
  await frames(fresh.page, 2);
  await fresh.page.reload({ waitUntil: 'load' });
  await fresh.page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
  const restored = await until(() => api(fresh.page, 'stats'), (s) => s.models === 1, 15_000);
  assert.deepEqual(restored, pulled.stats, 'the reloaded page has the pulled shape');
  assert.equal(await session(), pulled.session, 'the same session');
  assert.deepEqual(await api(fresh.page, 'camera'), pulled.camera, 'the same view');
  await api(fresh.page, 'undo');
  assert.deepEqual(await api(fresh.page, 'stats'), created, 'undo after the reload gives the shape before the pull');
  assert.deepEqual(await glb(), beforePull, 'bit for bit');
  await frames(fresh.page, 3);
  await screenshot(fresh.page, out('autosave-restored.png'));
  // A document kept by the previous version of the store (version 2: the record one JSON
  // text) opens in this one, in a fresh profile.
  await api(fresh.page, 'flushAutosave');
  const undone = JSON.parse(await session());
  await until(() => storedSession(fresh.page), (s) => s?.ops.length === undone.ops.length, 5000);
  const { parts } = await storedRecord(fresh.page);
  assert.ok(parts.every((part) => typeof part === 'string'), 'a record without an import has no piece apart');
  await restoresFromVersion2(parts.join(''), await session());
  // A corrupt record: the page starts empty, says why, and keeps the record aside.
  await sleep(1200);
  const [kept] = await api(fresh.page, 'documents');
  assert.ok(kept?.shown, 'the document shown is kept');
  await fresh.page.evaluate((id) => new Promise((resolve, reject) => {
    const request = indexedDB.open('sketchmesh');
    request.onsuccess = () => {
      const transaction = request.result.transaction('records', 'readwrite');
      transaction.objectStore('records').put('{"session": "not a session", "camera": 7}', id);
      transaction.oncomplete = resolve;
      transaction.onerror = () => reject(transaction.error);
    };
    request.onerror = () => reject(request.error);
  }), kept.id);
  const warnings = [];
  fresh.page.on('console', (msg) => warnings.push(msg.text()));
  await fresh.page.reload({ waitUntil: 'load' });
  await fresh.page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
  const keys = await until(
    () => fresh.page.evaluate(() => new Promise((resolve) => {
      const request = indexedDB.open('sketchmesh');
      request.onsuccess = () => {
        const all = request.result.transaction('autosave').objectStore('autosave').getAllKeys();
        all.onsuccess = () => resolve(all.result);
      };
    })),
    (k) => k.some((key) => key.startsWith('set-aside-')),
    5000,
  );
  assert.ok(keys.some((key) => key.startsWith('set-aside-')), `the record is set aside: ${keys}`);
  assert.deepEqual(await api(fresh.page, 'documents'), [], 'and its document is no longer listed');
  assert.equal((await api(fresh.page, 'stats')).models, 0, 'the page starts empty');
  assert.ok(warnings.some((w) => w.includes('could not be restored')), `a sentence says why: ${warnings}`);
  await frames(fresh.page, 3);
  await screenshot(fresh.page, out('autosave-set-aside.png'));
  assert.deepEqual(fresh.errors, [], 'console errors around the reloads');
}));

// WebGL2 only: the menu is looked for where it opens, drawn the same on both paths.
test('the File menu closes with Esc, and with a pen stroke on the view (which draws)', { gpu: false }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page, cdp } = fresh;
    const menuArea = [];
    for (let x = 12; x <= 180; x += 6) for (let y = 60; y <= 240; y += 6) menuArea.push({ x, y });
    const closed = await screenshot(page, out('file-menu-closed.png'));
    const differs = (shot) => changedFraction(closed, shot, menuArea, { radius: 0, threshold: 40 });
    const open = async (name) => {
      await page.mouse.click(FILE_MENU.x, FILE_MENU.y);
      await frames(page, 3);
      const shot = await screenshot(page, out(`file-menu-${name}.png`));
      assert.ok(differs(shot) > 0.2, `the File menu opened (${differs(shot)})`);
    };
    await open('open');
    await page.keyboard.press('Escape');
    await frames(page, 3);
    const escaped = await screenshot(page, out('file-menu-escaped.png'));
    assert.ok(differs(escaped) < 0.01, `Esc closes the File menu (${differs(escaped)})`);
    await open('open-again');
    await penStroke(cdp, line({ x: 520, y: 420 }, { x: 820, y: 440 }, 14).map((p) => ({ ...p, force: 0.5 })));
    await frames(page, 3);
    const stroked = await screenshot(page, out('file-menu-stroked.png'));
    assert.ok(differs(stroked) < 0.01, `a pen stroke on the view closes the File menu (${differs(stroked)})`);
    assert.equal((await lastOpOf(page)).op, 'stroke', 'and the stroke is drawn');
    assert.deepEqual(fresh.errors, [], 'console errors');
  } finally {
    await fresh.context.close();
  }
});

// WebGL2 only: the camera, the tool and the store.
test('the view comes back after a reload with no edit after it (an orbit, a wheel zoom, a two-finger pinch on a phone); New and a reload start in Sketch; documents made in the same minute get distinct names', { gpu: false }, () => withShape(async ({ fresh }) => {
  const { page, cdp } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  await sleep(1200);
  // The view's camera once it holds still (egui spreads a wheel's scroll over frames).
  const settled = async (p) => {
    let last = null;
    for (let i = 0; i < 40; i++) {
      await frames(p, 3);
      const now = await api(p, 'camera');
      if (JSON.stringify(now) === JSON.stringify(last)) return now;
      last = now;
    }
    return last;
  };
  // Reloads once the view has been written (it is, shortly after it holds still), and reads
  // the view restored.
  const reloaded = async (p) => {
    await sleep(1500);
    await p.reload({ waitUntil: 'load' });
    await p.waitForFunction(() => window.sketchmesh?.stats?.().models === 1, null, { timeout: 15_000, polling: 100 });
    await frames(p, 2);
    return api(p, 'camera');
  };
  await page.keyboard.press('p');
  await frames(page, 2);
  assert.equal(await api(page, 'tool'), 'pull', 'P picks Pull');
  const front = await settled(page);
  await orbitDrag(cdp);
  const orbited = await settled(page);
  assert.notDeepEqual(orbited, front, 'the right drag orbited');
  assert.deepEqual(await reloaded(page), orbited, 'the orbit comes back after a reload');
  assert.equal(await api(page, 'tool'), 'sketch', 'the reloaded document starts in Sketch, not Pull');
  await page.mouse.move(ELLIPSE.c.x, ELLIPSE.c.y);
  await page.mouse.wheel(0, 500);
  const zoomed = await settled(page);
  assert.ok(cameraDistance(zoomed) > 1.05 * cameraDistance(orbited), 'the wheel zoomed out');
  assert.deepEqual(await reloaded(page), zoomed, 'the wheel zoom comes back after a reload');
  // New, from Pull: an empty document in Sketch; two more made within the minute.
  for (let k = 2; k <= 3; k++) {
    await page.keyboard.press('p');
    await frames(page, 2);
    assert.equal(await api(page, 'tool'), 'pull', 'P picks Pull');
    await api(page, 'newDocument');
    assert.equal(await api(page, 'tool'), 'sketch', 'New starts in Sketch');
    // The app takes the new document in its next frame; a replay begun before is the old one's.
    await frames(page, 2);
    await page.evaluate((s) => window.sketchmesh.replay(s), drawnShape.session);
    await until(() => api(page, 'documents'), (d) => d.length === k, 5000);
  }
  const names = (await api(page, 'documents')).map((d) => d.name);
  console.log(`    names: ${names.join('; ')}`);
  assert.equal(names.length, 3, 'three documents kept');
  assert.equal(new Set(names).size, 3, `distinct names: ${names}`);
  assert.deepEqual(fresh.errors, [], 'console errors around the reloads');
  // A phone: a two-finger pinch, then a reload.
  const phone = await openApp(browser, url, gpu, { width: 390, height: 844 });
  try {
    await phone.page.evaluate((s) => window.sketchmesh.replay(s), drawnShape.session);
    await until(() => api(phone.page, 'stats'), (s) => s.models === 1, 15_000);
    await sleep(1200);
    const before = await settled(phone.page);
    const c = { x: 195, y: 420 };
    await touchGesture(phone.cdp, [
      line({ x: c.x - 40, y: c.y }, { x: c.x - 150, y: c.y }, 10),
      line({ x: c.x + 40, y: c.y }, { x: c.x + 150, y: c.y }, 10),
    ]);
    const pinched = await settled(phone.page);
    assert.ok(cameraDistance(pinched) < 0.95 * cameraDistance(before), 'the pinch zoomed in');
    assert.deepEqual(await reloaded(phone.page), pinched, 'the pinch zoom comes back after a reload on a phone');
    assert.deepEqual(phone.errors, [], 'console errors on the phone');
  } finally {
    await phone.context.close();
  }
}));

// WebGL2 only: the camera and the document.
test('an import into a document with a model frames both: every corner of both models\' bounds is inside the view', { gpu: false }, () => withShape(async ({ fresh }) => {
  const { page } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const spotPath = join(dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'shared', 'testdata', 'meshes', 'spot.glb');
  const spot = Array.from(readFileSync(spotPath));
  await page.evaluate((bytes) => window.sketchmesh.loadGlb(new Uint8Array(bytes), 'spot.glb'), spot);
  await until(() => api(page, 'stats'), (s) => s.models === 2, 15_000);
  await frames(page, 4);
  const cam = await api(page, 'camera');
  const boxes = await api(page, 'bounds');
  // The 3D view is the window below the toolbar: its aspect is wider than the window's, so
  // the window's is the stricter test across.
  const worst = boxes.map((box) => viewExtent(cam, box, 1280 / 720));
  console.log(`    import framing: the models reach ${worst.map((w) => w.toFixed(2)).join(' and ')} of the view's half-size`);
  await screenshot(page, out('import-framed.png'));
  assert.ok(worst.every((w) => w <= 1), `both models in view: ${worst}`);
  assert.deepEqual(fresh.errors, [], 'console errors');
}));

// WebGL2 only: the store and the session.
test('a file imported while the page still reads its store is autosaved into the new document', { gpu: false }, async () => {
  const spotPath = join(dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'shared', 'testdata', 'meshes', 'spot.glb');
  assert.ok(existsSync(spotPath), `the shared test data is missing: ${spotPath}`);
  const fresh = await openApp(browser, url, gpu);
  try {
    // The store answers 1.5 s late (a slow disk): the import lands before it does.
    await fresh.page.addInitScript(() => {
      const open = IDBFactory.prototype.open;
      IDBFactory.prototype.open = function (...args) {
        const slow = {};
        setTimeout(() => {
          const request = open.apply(this, args);
          for (const name of ['onsuccess', 'onerror', 'onupgradeneeded', 'onblocked']) {
            request[name] = (event) => slow[name]?.(event);
          }
          for (const name of ['result', 'error', 'transaction']) {
            Object.defineProperty(slow, name, { get: () => request[name] });
          }
        }, 1500);
        return slow;
      };
    });
    await fresh.page.reload({ waitUntil: 'load' });
    await fresh.page.waitForFunction(() => typeof window.sketchmesh?.loadGlb === 'function', null, { timeout: 15_000 });
    await fresh.page.evaluate((bytes) => window.sketchmesh.loadGlb(new Uint8Array(bytes), 'spot.glb'), Array.from(readFileSync(spotPath)));
    const session = JSON.parse(await api(fresh.page, 'session'));
    assert.equal(session.ops.length, 1, 'the import is the document\'s first op');
    const stored = await until(() => storedSession(fresh.page), (s) => s !== null, 8000);
    assert.deepEqual(stored, session, 'the import is autosaved once the store answers');
    assert.deepEqual(fresh.errors, [], 'console errors');
  } finally {
    await fresh.context.close();
  }
});

// WebGL2 only: the page's message and the reload.
test('a panic (forced through the test API) shows a message with a bug report and Reload; the reload restores the work from before it', { gpu: false }, () => withShape(async ({ fresh, created }) => {
    await fresh.page.evaluate(() => window.sketchmesh.flushAutosave());
    const thrown = await fresh.page.evaluate(() => {
      try {
        window.sketchmesh.panicForTest();
        return null;
      } catch (e) {
        return String(e);
      }
    });
    assert.ok(thrown, 'the panic ends the call with an error');
    const failure = await fresh.page.evaluate(() => ({
      shown: !document.getElementById('failure').hidden,
      text: document.getElementById('failure-message').textContent,
    }));
    console.log(`    message: ${failure.text.slice(0, 100)}`);
    assert.ok(failure.shown, 'the failure message shows');
    assert.match(failure.text, /^Sketchmesh .* stopped because of a bug: a panic forced by the browser suite \(at .*\)\.$/);
    await screenshot(fresh.page, out('panic.png'));
    await fresh.page.click('#failure-reload');
    await fresh.page.waitForFunction(() => window.sketchmesh?.stats?.().models === 1, null, { timeout: 20_000, polling: 100 });
    assert.deepEqual(await api(fresh.page, 'stats'), created, 'the reload restores the shape');
    const hidden = await fresh.page.evaluate(() => document.getElementById('failure').hidden);
    assert.ok(hidden, 'the reloaded page runs without the message');
}));

// WebGL2 only: the file and the document.
test('session files: Ctrl+Shift+S downloads the session; dropping it in a fresh profile gives the same document; a broken one changes nothing', { gpu: false }, () => withShape(async ({ fresh, created }) => {
  const session = await api(fresh.page, 'session');
  const [download] = await Promise.all([
    fresh.page.waitForEvent('download', { timeout: 10_000 }),
    fresh.page.keyboard.press('Control+Shift+S'),
  ]);
  assert.match(download.suggestedFilename(), /^sketchmesh-\d{8}-\d{4}\.sketchmesh\.json$/);
  const saved = out('session.sketchmesh.json');
  await download.saveAs(saved);
  assert.equal(readFileSync(saved, 'utf8'), session, 'the file is the session');
  const other = await openApp(browser, url, gpu);
  try {
    // Drops `file` on the canvas, as a person dragging it from their files would.
    const pick = (file) => other.page.evaluate(async ([name, text]) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([text], name, { type: 'application/json' }));
      const canvas = document.getElementById('sketchmesh_canvas');
      for (const type of ['dragenter', 'dragover', 'drop']) {
        canvas.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }
    }, [file.split('/').at(-1), readFileSync(file, 'utf8')]);
    const broken = out('broken.sketchmesh.json');
    writeFileSync(broken, '{"format": "sketchmesh-session", "version": 1, "ops": [{"op": "nope"}]}');
    await pick(broken);
    await frames(other.page, 6);
    assert.equal((await api(other.page, 'stats')).models, 0, 'a broken session changes nothing');
    await pick(saved);
    const opened = await until(() => api(other.page, 'stats'), (s) => s.models === 1, 15_000);
    assert.deepEqual(opened, created, 'the same shape in the fresh profile');
    assert.equal(await api(other.page, 'session'), session, 'the same session');
    await frames(other.page, 4);
    await screenshot(other.page, out('session-opened.png'));
    assert.deepEqual(other.errors, [], 'console errors while opening sessions');
  } finally {
    await other.context.close();
  }
}));

// Both paths: the thumbnails are read back from what the path drew.
test('documents: New keeps the shape and starts empty; the panel lists both with thumbnails; Open, rename and delete; a reload shows the one last shown', { gpu: true }, () => withShape(async ({ fresh, created }) => {
  const { page, cdp } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const egg = await api(page, 'session');
  await api(page, 'newDocument');
  assert.deepEqual(await api(page, 'stats'), { models: 0, vertices: 0, triangles: 0, curves: 0 }, 'New starts empty');
  let kept = await api(page, 'documents');
  assert.equal(kept.length, 1, 'the shape is kept');
  assert.ok(!kept[0].shown && kept[0].thumbnail, `kept with a thumbnail, not shown: ${JSON.stringify(kept)}`);
  // A second, smaller shape in the new document.
  const c = { x: 420, y: 420 };
  const circle = Array.from({ length: 41 }, (_, i) => {
    const a = (2 * Math.PI * i) / 40;
    return { x: c.x + 90 * Math.cos(a), y: c.y + 90 * Math.sin(a), force: 0.6 };
  });
  await penStroke(cdp, circle);
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const ball = await api(page, 'stats');
  assert.equal(ball.models, 1, 'the second document has its own shape');
  kept = await until(() => api(page, 'documents'), (d) => d.length === 2, 3000);
  assert.equal(kept.length, 2, 'the new document is kept within a second');
  assert.ok(kept[0].shown, 'the one shown was changed last');
  // The panel, from the toolbar's File menu.
  await page.mouse.click(FILE_MENU.x, FILE_MENU.y);
  await frames(page, 3);
  await page.mouse.click(DOCUMENTS_ITEM.x, DOCUMENTS_ITEM.y);
  await page.waitForSelector('#documents:not([hidden]) li.shown img', { timeout: 5000 });
  const rows = await page.$$eval('#documents-list li', (items) => items.map((item) => ({
    name: item.querySelector('input.name').value,
    shown: item.classList.contains('shown'),
    image: item.querySelector('img') != null,
  })));
  assert.equal(rows.length, 2);
  assert.ok(rows.every((row) => row.image), `both have thumbnails: ${JSON.stringify(rows)}`);
  // The thumbnails show the shapes: light pixels of the lit surface on the dark view.
  const light = await page.$$eval('#documents-list li img', (images) => images.map((image) => {
    const canvas = document.createElement('canvas');
    canvas.width = image.naturalWidth;
    canvas.height = image.naturalHeight;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const { data } = context.getImageData(0, 0, canvas.width, canvas.height);
    let count = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] > 150 && data[i + 1] > 150) count++;
    return count / (data.length / 4);
  }));
  assert.ok(light.every((f) => f > 0.005 && f < 0.5), `the thumbnails show a shape: ${light}`);
  await screenshot(page, out('documents-panel.png'));
  // Rename the egg, then open it.
  await page.fill('#documents-list li:not(.shown) input.name', 'Egg');
  await page.press('#documents-list li:not(.shown) input.name', 'Enter');
  await page.click('#documents-list li:not(.shown) button.open');
  await until(() => api(page, 'stats'), (s) => s.models === 1 && s.vertices === created.vertices, 5000);
  assert.equal(await api(page, 'session'), egg, 'Open brings the egg back, history and all');
  assert.ok(await page.evaluate(() => document.getElementById('documents').hidden), 'the panel closed');
  kept = await api(page, 'documents');
  assert.deepEqual(kept.map((d) => [d.name, d.shown]).sort(), [['Egg', true], [kept.find((d) => !d.shown).name, false]].sort());
  await api(page, 'undo');
  assert.equal((await api(page, 'stats')).models, 0, 'undo works in the reopened document');
  await api(page, 'redo');
  const reopened = await api(page, 'session');
  // Delete the ball: the first tap arms the button, the second deletes.
  await page.evaluate(() => window.sketchmeshDocuments.show());
  await page.waitForSelector('#documents:not([hidden]) li:not(.shown) button.delete');
  await page.click('#documents-list li:not(.shown) button.delete');
  assert.equal((await api(page, 'documents')).length, 2, 'one tap deletes nothing');
  await page.click('#documents-list li:not(.shown) button.delete.armed');
  kept = await until(() => api(page, 'documents'), (d) => d.length === 1, 3000);
  assert.deepEqual(kept.map((d) => d.name), ['Egg'], 'the ball is gone');
  await page.keyboard.press('Escape');
  assert.ok(await page.evaluate(() => document.getElementById('documents').hidden), 'Escape closes the panel');
  await page.reload({ waitUntil: 'load' });
  await page.waitForFunction(() => window.sketchmesh?.stats?.().models === 1, null, { timeout: 15_000, polling: 100 });
  assert.equal(await api(page, 'session'), reopened, 'a reload shows the egg, with its undo and redo');
  assert.deepEqual(fresh.errors, [], 'console errors with documents');
}));

// WebGL2 only: the panel, the documents and the files.
test('examples: the Documents panel lists at least three with thumbnails; each opens into a new document, the one its session replays to; an unknown name is refused; the user\'s document stays kept', { gpu: false, limitMs: LONG_CASE_LIMIT_MS }, () => withShape(async ({ fresh }) => {
  const { page } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const mine = await until(() => api(page, 'documents'), (d) => d.length === 1, 3000);
  assert.equal(mine.length, 1, 'the shape drawn is a kept document');
  const listed = await api(page, 'examples');
  assert.ok(listed.length >= 3, `at least three examples: ${JSON.stringify(listed)}`);
  assert.ok(listed.every((e) => e.name && e.title && e.description), 'each with a name, a title and a line on it');
  await page.evaluate(() => window.sketchmeshDocuments.show());
  await page.waitForFunction((n) => [...document.querySelectorAll('#documents-examples li img')].filter((i) => i.complete && i.naturalWidth > 0).length === n, listed.length, { timeout: 5000 });
  const rows = await page.$$eval('#documents-examples li', (items) => items.map((item) => ({
    title: item.querySelector('.title').textContent,
    buttons: [...item.querySelectorAll('button')].map((b) => ({ text: b.textContent, height: b.getBoundingClientRect().height })),
  })));
  assert.deepEqual(rows.map((r) => r.title), listed.map((e) => e.title), 'the panel lists them');
  assert.ok(rows.every((r) => r.buttons.some((b) => b.text === 'Play how it was made') && r.buttons.every((b) => b.height >= 44)), `Open and Play, 44 px tall: ${JSON.stringify(rows)}`);
  await screenshot(page, out('documents-examples.png'));
  // Open, from the panel: a new document, the replay of the example's session.
  await page.click(`#documents-examples li[data-example="${listed[0].name}"] button.open`);
  const opsOf = async () => JSON.parse(await api(page, 'session')).ops.length;
  for (const example of listed) {
    const text = await page.evaluate((name) => fetch('examples/index.json').then((r) => r.json())
      .then((index) => fetch(`examples/${index.examples.find((e) => e.name === name).session}`)).then((r) => r.text()), example.name);
    if (example !== listed[0]) await page.evaluate((name) => window.sketchmesh.openExample(name), example.name);
    const ops = JSON.parse(text).ops.length;
    assert.equal(await until(opsOf, (n) => n === ops, 20_000), ops, `${example.name}: its session's every op`);
    await frames(page, 2);
    const glb = await glbOf(page);
    await page.evaluate((s) => window.sketchmesh.replay(s), text);
    assert.deepEqual(await glbOf(page), glb, `${example.name}: the document is the one its session replays to`);
  }
  const refused = await page.evaluate(() => window.sketchmesh.openExample('no-such-example').then(() => null, (e) => e.message));
  assert.match(refused ?? '', /no example named "no-such-example".*character/i, 'an unknown name is refused with the names');
  const kept = await until(() => api(page, 'documents'), (d) => d.length === 1 + listed.length, 5000);
  assert.ok(kept.some((d) => d.id === mine[0].id), `the user's document is still kept: ${JSON.stringify(kept)}`);
  assert.deepEqual(kept.map((d) => d.name).filter((n) => listed.some((e) => e.title === n)).sort(), listed.map((e) => e.title).sort(), 'each example is a document of its own, by its title');
  assert.deepEqual(fresh.errors, [], 'console errors with examples');
}));

/** How many pixels of `image` have the replayed strokes' ink colour. */
function inkPixels(image) {
  let count = 0;
  for (let k = 0; k < image.data.length; k += 4) {
    const [r, g, b] = [image.data[k], image.data[k + 1], image.data[k + 2]];
    if (Math.abs(r - 242) < 24 && Math.abs(g - 199) < 24 && Math.abs(b - 82) < 30) count++;
  }
  return count;
}

/** Clicks button `k` (0 Pause, 1 Skip step, 2 Skip to end) of the making's panel. */
async function clickMaking(page, k) {
  const { buttons } = await api(page, 'examplePlayback');
  const [x, y, w, h] = buttons[k];
  assert.ok(w >= 44 && h >= 44, `the button is touch-sized: ${w}x${h}`);
  await page.mouse.click(x + w / 2, y + h / 2);
}

// WebGL2 only: the ink drawn over the view and the document.
test('examples: Play how it was made draws each stroke as it was drawn, then applies its op; Pause holds, Skip step moves on, Skip to end reaches the document the session replays to; the user\'s document stays kept', { gpu: false, limitMs: LONG_CASE_LIMIT_MS }, () => withShape(async ({ fresh }) => {
  const { page } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const mine = await until(() => api(page, 'documents'), (d) => d.length === 1, 3000);
  await page.evaluate(() => window.sketchmesh.openExample('character', { play: true }));
  assert.deepEqual(await api(page, 'stats'), { models: 0, vertices: 0, triangles: 0, curves: 0 }, 'a new, empty document plays it');
  const playback = () => api(page, 'examplePlayback');
  const drawing = (low, high) => until(playback, (p) => p?.stage === 'drawing' && p.drawn >= low && p.drawn <= high, 10_000);
  // Paused twice while the outline is drawn (a screenshot takes longer than a frame), and
  // held paused for a second and a half the first time.
  const early = await drawing(0.05, 0.4);
  await clickMaking(page, 0);
  const paused = await until(playback, (p) => p.paused, 3000);
  assert.equal(paused.op, 1, `the first step: ${JSON.stringify(paused)}`);
  assert.match(paused.caption, /Sketch/, 'the caption names the tool');
  const first = await screenshot(page, out('example-drawing-early.png'));
  await sleep(1500);
  const still = await playback();
  assert.ok(still.paused && still.op === paused.op && still.drawn === paused.drawn && still.stage === 'drawing', `Pause holds: ${JSON.stringify([paused, still])}`);
  await clickMaking(page, 0);
  await until(playback, (p) => !p.paused, 3000);
  await drawing(paused.drawn + 0.35, 1);
  await clickMaking(page, 0);
  const later = await until(playback, (p) => p.paused, 3000);
  const second = await screenshot(page, out('example-drawing.png'));
  const [inkEarly, inkLater] = [inkPixels(first), inkPixels(second)];
  console.log(`    examples: ink ${inkEarly} px at ${(100 * paused.drawn).toFixed(0)}% of the outline, ${inkLater} px at ${(100 * later.drawn).toFixed(0)}% (${later.stage})`);
  assert.ok(early.drawn < later.drawn && inkEarly > 100 && inkLater > inkEarly * 1.4, `the stroke is drawn as it goes (${inkEarly} then ${inkLater} ink pixels)`);
  await clickMaking(page, 0);
  // The op applied after its stroke: the body.
  const body = await until(() => api(page, 'stats'), (s) => s.models === 1, 20_000);
  assert.equal(body.models, 1, 'the outline became the body');
  // Skip step: the step's op applies at once, and the next one comes.
  const before = (await api(page, 'examplePlayback')).op;
  await clickMaking(page, 1);
  const next = await until(() => api(page, 'examplePlayback'), (p) => p.op === before + 1, 20_000);
  assert.equal(next.op, before + 1, 'Skip step moved on');
  await clickMaking(page, 2);
  const done = await until(() => api(page, 'examplePlayback'), (p) => !p.playing, 60_000);
  assert.ok(!done.playing && done.op === done.of && done.failed === null, `played to its end: ${JSON.stringify(done)}`);
  const played = await glbOf(page);
  const text = await page.evaluate(() => fetch('examples/character.json').then((r) => r.text()));
  assert.deepEqual(JSON.parse(await api(page, 'session')).ops, JSON.parse(text).ops, 'the played document\'s session is the example\'s');
  await page.evaluate((s) => window.sketchmesh.replay(s), text);
  assert.deepEqual(await glbOf(page), played, 'the played document is the one its session replays to, bit for bit');
  const kept = await until(() => api(page, 'documents'), (d) => d.length === 2, 5000);
  assert.ok(kept.some((d) => d.id === mine[0].id), 'the user\'s document is still kept');
  // On a phone, the stroke is drawn inside the narrower view.
  const phone = await openApp(await hiDpiBrowser(), url, gpu, { width: 390, height: 844, deviceScaleFactor: 2 });
  try {
    await phone.page.evaluate(() => window.sketchmesh.openExample('character', { play: true }));
    await until(() => api(phone.page, 'examplePlayback'), (p) => p?.stage === 'drawing' && p.drawn > 0.5, 10_000);
    await clickMaking(phone.page, 0);
    await until(() => api(phone.page, 'examplePlayback'), (p) => p.paused, 3000);
    const shot = await screenshot(phone.page, out('example-drawing-phone.png'));
    await clickMaking(phone.page, 0);
    assert.ok(inkPixels(shot) > 100, `the stroke shows on a phone (${inkPixels(shot)} ink pixels)`);
    await until(() => api(phone.page, 'examplePlayback'), (p) => p?.op >= 2 && p.stage === 'drawing' && p.drawn > 0.5, 20_000);
    await screenshot(phone.page, out('example-drawing-phone-2.png'));
    assert.deepEqual(phone.errors, [], 'console errors playing on a phone');
  } finally {
    await phone.context.close();
  }
  assert.deepEqual(fresh.errors, [], 'console errors playing an example');
}));

// WebGL2 only: the store's failure and the document.
test('a full store: the autosave says so in a sentence, and the document stays as it is', { gpu: false }, () => withShape(async ({ fresh, created }) => {
  const { page } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const warnings = [];
  page.on('console', (msg) => warnings.push(msg.text()));
  await page.evaluate(() => {
    IDBObjectStore.prototype.put = () => { throw new DOMException('The quota has been exceeded.', 'QuotaExceededError'); };
  });
  await api(page, 'undo');
  await until(async () => warnings, (w) => w.some((text) => text.includes('storage for Sketchmesh is full')), 3000);
  assert.ok(warnings.some((w) => /^Could not autosave your work: this browser's storage for Sketchmesh is full: delete documents/.test(w)), `a sentence: ${warnings}`);
  await api(page, 'redo');
  assert.deepEqual(await api(page, 'stats'), created, 'the document is as it was');
  await frames(page, 3);
  await screenshot(page, out('storage-full.png'));
}));

// WebGL2 only: the session and the document.
test('navigate away in the middle of a creation, come back: the last complete state, with its history', { gpu: false }, () => withShape(async ({ fresh, created }) => {
  const { page, cdp } = fresh;
  await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
  const session = await api(page, 'session');
  // A second, large outline: its creation runs over many frames; the page goes away at once.
  const c = { x: 300, y: 420 };
  const outline = Array.from({ length: 61 }, (_, i) => {
    const a = (2 * Math.PI * i) / 60;
    return { x: c.x + 140 * Math.cos(a), y: c.y + 200 * Math.sin(a), force: 0.6 };
  });
  await penStroke(cdp, outline, 8);
  const during = await api(page, 'stats');
  assert.equal(during.models, 1, 'the page left while the second shape was still being made');
  await page.goto('about:blank');
  await page.goBack({ waitUntil: 'load' });
  await page.waitForFunction(() => window.sketchmesh?.stats?.().models >= 1, null, { timeout: 15_000, polling: 100 });
  await frames(page, 4);
  assert.deepEqual(await api(page, 'stats'), created, 'the first shape only');
  assert.equal(await api(page, 'session'), session, 'the session of the last complete state');
  await api(page, 'undo');
  assert.equal((await api(page, 'stats')).models, 0, 'and its history');
  assert.deepEqual(fresh.errors, [], 'console errors around the navigation');
}));

// WebGL2 only: the service worker and its cache.
test('offline: after one visit, with the server stopped, a reload opens the app and creating a shape works; a new version is taken on the next load, with a notice', { gpu: false }, async () => {
  // A copy of the page, so that the case can publish a "new version" of it.
  const site = mkdtempSync(join(tmpdir(), 'sketchmesh-site-'));
  cpSync(DIST, site, { recursive: true });
  const server = await serveDirectory(site);
  const visit = await openApp(browser, server.url, gpu);
  const warnings = [];
  visit.page.on('console', (msg) => warnings.push(msg.text()));
  try {
    await visit.page.waitForFunction(() => navigator.serviceWorker?.controller != null, null, { timeout: 30_000 });
    const cached = await visit.page.evaluate(async () => {
      const keys = await caches.keys();
      const cache = await caches.open(keys.find((key) => key.startsWith('sketchmesh-')));
      return (await cache.keys()).map((request) => new URL(request.url).pathname);
    });
    assert.ok(cached.includes('/sketchmesh_app_bg.wasm') && cached.includes('/'), `the app's files are cached: ${cached}`);
    const manifest = await visit.page.evaluate(async () => {
      const link = document.querySelector('link[rel=manifest]');
      return (await fetch(link.href)).json();
    });
    assert.equal(manifest.display, 'standalone');
    assert.ok(manifest.icons.some((icon) => icon.sizes === '512x512'), 'installable: a 512 px icon');
    assert.ok(!warnings.some((w) => w.includes('new version')), 'no update notice on a first visit');
    // A new version: the page loaded next still runs the old one and says a new one is ready;
    // the load after that runs it.
    const worker = join(site, 'sw.js');
    writeFileSync(worker, readFileSync(worker, 'utf8').replace(/const VERSION = "([0-9a-f]+)"/, 'const VERSION = "$1-next"'));
    writeFileSync(join(site, 'index.html'), readFileSync(join(site, 'index.html'), 'utf8').replace('<title>Sketchmesh</title>', '<title>Sketchmesh next</title>'));
    await visit.page.reload({ waitUntil: 'load' });
    assert.equal(await visit.page.title(), 'Sketchmesh', 'the reload runs the cached version');
    await until(async () => warnings, (w) => w.some((text) => text.includes('A new version of Sketchmesh is ready')), 15_000);
    assert.ok(warnings.some((w) => w.includes('A new version of Sketchmesh is ready')), `the page says a new version is ready: ${warnings}`);
    await visit.page.reload({ waitUntil: 'load' });
    assert.equal(await visit.page.title(), 'Sketchmesh next', 'the next load runs the new version');
    await visit.page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
    await server.close();
    await visit.page.reload({ waitUntil: 'load' });
    await visit.page.waitForFunction(() => typeof window.sketchmesh?.stats === 'function', null, { timeout: 15_000 });
    await frames(visit.page, 2);
    await penStroke(visit.cdp, onEllipse());
    const made = await until(() => api(visit.page, 'stats'), (s) => s.models === 1, 15_000);
    assert.equal(made.models, 1, 'a shape is made offline');
    await frames(visit.page, 3);
    await screenshot(visit.page, out('offline.png'));
    assert.deepEqual(visit.errors, [], 'console errors offline');
  } finally {
    await visit.context.close();
    await server.close();
    rmSync(site, { recursive: true, force: true });
  }
});

// WebGL2 only: the ops and where the worker computed them.
test('a pull dragged while the worker computes the last pull of a 40k shape is refused, not computed in the frame; dragged again once it landed, it pulls', { gpu: false, limitMs: LONG_CASE_LIMIT_MS }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page, cdp } = fresh;
    const c = ELLIPSE.c;
    await pull40k(page, cdp);
    const send = penSender(cdp);
    const drag = async (x, dx) => {
      await send('mousePressed', x, c.y, 1);
      for (let i = 1; i <= 8; i++) {
        await sleep(25);
        await send('mouseMoved', x + dx * i, c.y, 1);
      }
      await send('mouseReleased', x + 8 * dx, c.y, 0);
    };
    // The outline's right end pulled out: the worker computes the pull (about 0.5 s at 40k).
    await drag(c.x + 170, 5);
    // Its left end dragged meanwhile (a few frames later, so that the pull was handed over):
    // refused (no op), and the first pull still lands from the worker, not computed by this
    // drag's frame. (A drag after the landing would pull: the ops below would say so.)
    await sleep(100);
    await drag(c.x - 170, -5);
    await screenshot(page, out('pull-refused.png'));
    await until(() => api(page, 'progress'), (p) => p === null, 60_000);
    await sleep(500);
    const ops = JSON.parse(await api(page, 'session')).ops;
    assert.deepEqual(ops.map((o) => o.op), ['create', 'pull'], 'the drag made during the work made nothing');
    assert.equal(ops[1].stroke[0][0], c.x + 170, 'the pull is the first drag');
    const timed = (await api(page, 'timings')).pull;
    assert.equal(timed?.elsewhere_ms?.length, 1, `the worker computed the pull, not the frame: ${JSON.stringify(timed)}`);
    // Dragged again now, the left end pulls.
    await drag(c.x - 170, -5);
    const second = await until(() => lastOpOf(page), (o) => o.op === 'pull' && o.stroke[0][0] === c.x - 170, 60_000);
    assert.equal(second.stroke?.[0]?.[0], c.x - 170, 'the same drag, after the landing, pulls');
    assert.deepEqual(fresh.errors, [], 'console errors while pulling');
  } finally {
    await fresh.context.close();
  }
});

// Both paths: the frames drawn during the work, and the preview on screen.
test('a long pull of a 40k shape is previewed by the worker: the shape follows the pen, refactoring the region as the peel grows stalls no frame, and the release commits the pull; Esc during a drag makes nothing and the next drag pulls', { gpu: true, limitMs: LONG_CASE_LIMIT_MS }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page, cdp } = fresh;
    const c = ELLIPSE.c;
    await pull40k(page, cdp);
    const record = await recordFrames(page);
    const idleLongest = await idleOrbits(cdp, record);
    await frames(page, 3);
    const before = await screenshot(page, out('pull-40k-before.png'));
    // The outline's right end pulled 90 px right and 30 up in 60 samples (the page bench's
    // drag): the peel outgrows the region factored at the grab, which is factored again.
    const send = penSender(cdp);
    const grab = { x: c.x + 170, y: c.y };
    // The app's timings of the pull, gathered (each read takes them).
    await api(page, 'timings');
    const timed = { preview_ms: [], frame_ms: [], elsewhere_ms: [] };
    const gather = async () => {
      const pull = (await api(page, 'timings')).pull ?? {};
      for (const [key, list] of Object.entries(timed)) list.push(...(pull[key] ?? []));
      return timed;
    };
    const ownScript = await watchOwnScript(page);
    await record(true);
    await send('mousePressed', grab.x, grab.y, 1);
    for (let i = 1; i <= 60; i++) {
      await sleep(16);
      await send('mouseMoved', grab.x + 1.5 * i, grab.y - 0.5 * i, 1);
    }
    await until(gather, (t) => t.preview_ms.length >= 2, 10_000);
    await sleep(1000);
    const dragLongest = await record(false);
    const dragScript = await ownScript();
    const previewed = await screenshot(page, out('pull-40k-preview.png'));
    await send('mouseReleased', grab.x + 90, grab.y - 30, 0);
    const pulled = await until(() => lastOpOf(page), (o) => o.op === 'pull', 60_000);
    assert.equal(pulled.stroke.length, 61, 'the pull is the whole drag');
    await gather();
    const inFrame = Math.max(...timed.frame_ms);
    const limit = 1.5 * idleLongest + 50;
    console.log(`    # previews from the worker: ${timed.preview_ms.map((ms) => ms.toFixed(0)).join(', ')} ms; the drag's own work per frame at most ${inFrame.toFixed(1)} ms; longest frame ${dragLongest.toFixed(0)} ms (idle ${idleLongest.toFixed(0)}, limit ${limit.toFixed(0)}; the page's script in one frame at most ${dragScript.toFixed(0)} ms, 0 when no frame took 50)`);
    assert.ok(timed.preview_ms.length >= 2, 'the worker previewed the drag');
    assert.ok(inFrame < 50, `no drag frame factors or solves: ${inFrame.toFixed(1)} ms of work in one`);
    assertNoStall(dragLongest, limit, dragScript, 'the worker previews the pull');
    assert.equal(timed.elsewhere_ms?.length, 1, `the worker computed the committed pull: ${JSON.stringify(timed)}`);
    const moved = imageChangedFraction(before, previewed);
    assert.ok(moved > 0.002, `the preview shows the shape pulled (${(100 * moved).toFixed(2)} % of the view changed)`);
    // The outline's left end dragged, and Esc pressed while the worker previews it: nothing
    // is made (the worker is replaced, as a cancel does); the same drag again pulls.
    const left = { x: c.x - 170, y: c.y };
    const leftDrag = async (cancel) => {
      await send('mousePressed', left.x, left.y, 1);
      for (let i = 1; i <= 10; i++) {
        await sleep(16);
        await send('mouseMoved', left.x - 3 * i, left.y, 1);
      }
      if (cancel) await page.keyboard.press('Escape');
      await send('mouseReleased', left.x - 30, left.y, 0);
    };
    await leftDrag(true);
    await sleep(500);
    assert.equal(await api(page, 'opCount'), 2, 'Esc during the drag makes nothing');
    await leftDrag(false);
    const again = await until(() => lastOpOf(page), (o) => o.op === 'pull' && o.stroke[0][0] === left.x, 60_000);
    assert.equal(again.stroke?.[0]?.[0], left.x, 'after the cancel, a drag pulls');
    assert.equal(await api(page, 'opCount'), 3, 'one pull for the drag');
    assert.deepEqual(fresh.errors, [], 'console errors while pulling');
  } finally {
    await fresh.context.close();
  }
});

/** Makes the test ellipse a 40k-vertex shape in a fresh page and picks the Pull tool. */
async function pull40k(page, cdp) {
  await page.mouse.click(DETAIL_40K.x, DETAIL_40K.y);
  await penStroke(cdp, onEllipse());
  await until(() => api(page, 'opCount'), (n) => n === 1, 60_000);
  await page.keyboard.press('p');
  await frames(page, 3);
}

/** A right-button drag across the view: an orbit, as a mouse user does it. */
async function orbitDrag(cdp, from = { x: 640, y: 420 }, dx = 240, steps = 12) {
  const at = (i) => ({ x: from.x + (dx * i) / steps, y: from.y });
  await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...from, button: 'right', buttons: 2, clickCount: 1 });
  for (let i = 1; i <= steps; i++) {
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...at(i), button: 'right', buttons: 2 });
    await sleep(16);
  }
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...at(steps), button: 'right', buttons: 0, clickCount: 1 });
}

/**
 * The longest frame of the scene as it is, without work: two orbits of it, over about as long
 * as the worker takes, recorded with `record` (from `recordFrames`).
 */
async function idleOrbits(cdp, record) {
  await record(true);
  await orbitDrag(cdp);
  await sleep(400);
  await orbitDrag(cdp, { x: 880, y: 420 }, -240);
  await sleep(300);
  return record(false);
}

/**
 * Starts recording the page's long animation frames (the Long Animation Frames API: every
 * frame over 50 ms, with the script it ran). SwiftShader draws the page's frames on the same
 * two cores the worker computes on, so a frame can be long while the page's thread waits;
 * the script a long frame ran is the stall the page itself caused. Returns
 * `ownScript(before)`: the most script one long frame ran among those that ended before
 * `before` (the page's clock; all of them by default).
 */
async function watchOwnScript(page) {
  await page.evaluate(() => {
    window.__longFrames = [];
    new PerformanceObserver((list) => window.__longFrames.push(...list.getEntries().map((e) => ({
      end: e.startTime + e.duration,
      script: e.scripts.reduce((sum, script) => sum + script.duration, 0),
    })))).observe({ type: 'long-animation-frame' });
  });
  return (before = Infinity) => page.evaluate((b) => Math.max(0, ...window.__longFrames
    .filter((f) => f.end < b).map((f) => f.script)), before);
}

/**
 * No frame during the work stalls: its longest is within `limit` (1.5 × the longest of the
 * scene without the work, plus 50 ms), or, where the machine made it longer, no frame ran
 * 50 ms of the page's own script (`ownScript`, from `watchOwnScript`).
 */
function assertNoStall(longest, limit, ownScript, what) {
  assert.ok(longest <= limit || ownScript < 50, `no frame stalls while ${what}: ${longest.toFixed(0)} ms > ${limit.toFixed(0)} ms, and one frame ran ${ownScript.toFixed(0)} ms of the page's script`);
}

/**
 * The frame that lands the work's result (the commit, the scene's arrays built and uploaded,
 * the first draw) is no longer than the same scene's frames with the result in it, as an
 * orbit shows them: 1.5 × its longest plus 50 ms, the rule for the frames during the work.
 */
function assertLandingFrame(landingLongest, sceneLongest) {
  const limit = 1.5 * sceneLongest + 50;
  assert.ok(landingLongest <= limit, `the frame that lands the result stalls: ${landingLongest.toFixed(0)} ms > ${limit.toFixed(0)} ms`);
}

/**
 * Imports the million-triangle grid (`window.__glb`) with an orbit drag while the worker
 * reads it: how long `loadGlb` took to return, the longest frame before the import landed,
 * the most script the page ran in one of those frames (see `watchOwnScript`), the frame
 * that landed it, an orbit of the result, and the camera before and at landing.
 */
async function importOffTheFrame(page, cdp, record) {
  const before = await camera(page);
  const ownScript = await watchOwnScript(page);
  await record(true);
  const returnedMs = await page.evaluate(() => {
    const started = performance.now();
    window.__landed = null;
    // Settled inside the frame that lands the import: the frames before it are the work's.
    const during = () => Math.max(0, ...window.__frames.list);
    window.sketchmesh.loadGlb(window.__glb, 'grid.glb').then(
      () => { window.__landed = { during: during(), at: performance.now(), camera: window.sketchmesh.camera() }; },
      (e) => { window.__landed = { error: e.message }; });
    return performance.now() - started;
  });
  await orbitDrag(cdp, undefined, 240, 6);
  await screenshot(page, out('import-progress.png'));
  const landed = await until(() => page.evaluate(() => window.__landed), (l) => l !== null, 60_000);
  assert.ok(landed && !landed.error, `the import lands: ${landed?.error}`);
  // The frame that lands it (commit, the scene's arrays built and uploaded, the first draw
  // of a million triangles), beside an orbit of the same scene: reported, see BENCHMARKS.md.
  await sleep(1500);
  const landingLongest = await record(false);
  // The frames that ended before the worker's answer arrived (the page marks it): the ones
  // after it land the import, its arrays copied out, then checked and committed (`landed.at`).
  const answered = await page.evaluate(() => performance.getEntriesByName('sketchmesh:answer').at(-1)?.startTime ?? Infinity);
  const ownLongest = await ownScript(Math.min(answered, landed.at));
  await record(true);
  await orbitDrag(cdp);
  await sleep(300);
  const modelLongest = await record(false);
  return { returnedMs, workLongest: landed.during, ownLongest, landingLongest, modelLongest, before, turned: landed.camera };
}

// Both paths: the frames drawn during the work, and the frame that uploads a million triangles.
test('a 1 M-triangle import runs off the frame: loadGlb returns at once, frames stay short, an orbit turns the view meanwhile, Escape cancels and changes nothing', { gpu: true, limitMs: LONG_CASE_LIMIT_MS }, async () => {
  // The machine's own spikes come and go: SwiftShader draws the page's frames on the CPU,
  // and on two cores it shares them with the worker, so a frame can wait for the CPU while
  // the page's thread does nothing. A stall the import causes would be in every run. So the
  // import runs up to three times, each in a fresh page, until a run keeps its frames within
  // the limit; should none, the long frames must not be the page's (`assertNoStall`).
  let fresh;
  let run;
  let limit;
  for (let attempt = 1; attempt <= 3; attempt++) {
    await fresh?.context.close();
    fresh = await openApp(browser, url, gpu);
    const { page, cdp } = fresh;
    await page.evaluate(GRID_GLB_SOURCE);
    await page.evaluate(() => { window.__glb = window.gridGlb(708); });
    const record = await recordFrames(page);
    const idleLongest = await idleOrbits(cdp, record);
    limit = 1.5 * idleLongest + 50;
    run = await importOffTheFrame(page, cdp, record);
    console.log(`    # run ${attempt}: longest frame ${idleLongest.toFixed(0)} ms without the work, ${run.workLongest.toFixed(0)} ms while the worker read 1 M triangles (limit ${limit.toFixed(0)}; the page's script in one frame meanwhile at most ${run.ownLongest.toFixed(0)} ms, 0 when no frame took 50); the landing frame ${run.landingLongest.toFixed(0)} ms, an orbit of the million triangles ${run.modelLongest.toFixed(0)} ms`);
    if (run.workLongest <= limit) break;
  }
  try {
    const { page } = fresh;
    const stats = await api(page, 'stats');
    assert.equal(stats.triangles, 1_002_528, 'the grid is in the document');
    assert.equal(await api(page, 'opCount'), 1, 'as one op');
    assert.ok(run.returnedMs < 50, `loadGlb returns within 50 ms: ${run.returnedMs.toFixed(1)} ms`);
    assert.ok(Math.hypot(...run.turned.eye.map((e, i) => e - run.before.eye[i])) > 1e-3, `an orbit during the work turns the view before the import lands: ${run.before.eye} -> ${run.turned.eye}`);
    assertNoStall(run.workLongest, limit, run.ownLongest, 'the worker reads, in three runs');

    // Escape while the file is read again into an empty document (its frames are short, so
    // the import is under way two frames after the call): refused as cancelled, and the
    // document and its session stay empty.
    await page.evaluate(() => window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] })));
    const empty = await api(page, 'stats');
    const rejected = page.evaluate(() => window.sketchmesh.loadGlb(window.__glb, 'again.glb').then(() => null, (e) => e.message))
      .catch((e) => `the page went: ${e.message}`);
    const progress = await until(() => api(page, 'progress'), (p) => p !== null, 5_000);
    assert.equal(progress, 'Importing again.glb (18.1 MB)…', 'the progress line says what is read');
    await page.keyboard.press('Escape');
    assert.equal(await rejected, 'The import was cancelled.', 'the Promise rejects with the sentence');
    await sleep(500);
    assert.deepEqual(await api(page, 'stats'), empty, 'a cancelled import leaves the document as it was');
    assert.equal(await api(page, 'opCount'), 0, 'and the session too');
    assert.equal(await api(page, 'progress'), null, 'and the progress line is gone');
    assert.deepEqual(fresh.errors, [], 'console errors while importing');
  } finally {
    await fresh.context.close();
  }
});

// Both paths: the frames drawn during the work, and the frame that uploads the shape.
test('a 40k-vertex shape is created off the frame: Escape cancels it and changes nothing; its outline stays with a progress line, frames stay short, an orbit turns the view and a stroke waits meanwhile; its replay runs in the worker too', { gpu: true, limitMs: LONG_CASE_LIMIT_MS }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page, cdp } = fresh;
    await page.mouse.click(DETAIL_40K.x, DETAIL_40K.y);
    const empty = await api(page, 'stats');
    // An outline cancelled while its shape is computed. (This also draws the outline, the
    // progress line and its text once, whose first frames cost more on WebGPU, before the
    // frames are measured.)
    await penStroke(cdp, onEllipse());
    const progress = await until(() => api(page, 'progress'), (p) => p !== null, 5_000);
    assert.equal(progress, 'Computing the new shape…', 'a progress line says what is computed');
    await screenshot(page, out('create-40k-progress.png'));
    await page.keyboard.press('Escape');
    await sleep(500);
    assert.deepEqual(await api(page, 'stats'), empty, 'a cancelled creation leaves the document as it was');
    assert.equal(await api(page, 'opCount'), 0, 'and the session too');
    assert.equal(await api(page, 'progress'), null, 'and the progress line is gone');

    // The same scene without the work: orbits, and a stroke of ink drawn and shown.
    const record = await recordFrames(page);
    const orbitsLongest = await idleOrbits(cdp, record);
    await record(true);
    await penStroke(cdp, line({ x: 150, y: 620 }, { x: 400, y: 640 }, 30));
    await sleep(600);
    const inkLongest = await record(false);
    assert.equal((await lastOpOf(page)).op, 'stroke', 'the ink is a stroke');
    const idleLongest = Math.max(orbitsLongest, inkLongest);
    // The work begins as the pen lifts: its frames are recorded from there to the frame that
    // lands the shape.
    const ownScript = await watchOwnScript(page);
    await penStroke(cdp, onEllipse());
    await record(true);
    await page.evaluate(() => { window.__frames.stopWhen = () => window.sketchmesh.stats().models === 1; });
    const before = await camera(page);
    await orbitDrag(cdp, undefined, 120, 6);
    const turned = await camera(page);
    assert.equal((await api(page, 'stats')).models, 0, 'the orbit came before the shape landed (worker too quick to test the stall)');
    assert.ok(Math.hypot(...turned.eye.map((e, i) => e - before.eye[i])) > 1e-3, 'an orbit during the work turns the view');
    // A stroke drawn meanwhile waits for the shape (it does not make the frame compute it).
    await penStroke(cdp, line({ x: 150, y: 560 }, { x: 400, y: 580 }, 30));
    await until(() => page.evaluate(() => window.__frames.on), (on) => !on, 60_000);
    await frames(page, 2, 0);
    const workLongest = await record(false);
    const landingLongest = await page.evaluate(() => window.__frames.landing);
    const workScript = await ownScript(await page.evaluate(() => window.__frames.stoppedAt));
    const ops = (await until(() => api(page, 'session').then((json) => JSON.parse(json).ops), (o) => o.length === 3, 5_000)).map((o) => o.op);
    assert.deepEqual(ops, ['stroke', 'create', 'stroke'], 'the ink, the shape, then the stroke that waited for it');
    const stats = await api(page, 'stats');
    assert.ok(stats.vertices > 36_000 && stats.vertices < 44_000 && stats.triangles === 2 * stats.vertices - 4, `a closed 40k-vertex shape: ${JSON.stringify(stats)}`);
    const op = JSON.parse(await api(page, 'session')).ops[1];
    assert.equal(op.vertices, 40_000, 'the session records the detail');
    const limit = 1.5 * idleLongest + 50;
    console.log(`    # longest frame: ${idleLongest.toFixed(0)} ms without the work, ${workLongest.toFixed(0)} ms while the worker created ${stats.vertices} vertices (limit ${limit.toFixed(0)}; the page's script in one frame at most ${workScript.toFixed(0)} ms, 0 when no frame took 50)`);
    assertNoStall(workLongest, limit, workScript, 'the worker creates');
    // The frame that lands it (commit, the shape's arrays built and uploaded, its first draw)
    // is no longer than the frames of an orbit of the shape.
    await record(true);
    await sleep(1500);
    await orbitDrag(cdp, undefined, 120, 6);
    await sleep(300);
    const shapeLongest = await record(false);
    console.log(`    # the landing frame ${landingLongest.toFixed(0)} ms, an orbit of the shape ${shapeLongest.toFixed(0)} ms`);
    assertLandingFrame(landingLongest, shapeLongest);
    await frames(page, 3);
    await screenshot(page, out('create-40k.png'));

    // Its session replayed in the page: the creation is computed in the worker there too.
    const session = await api(page, 'session');
    await record(true);
    const replay = await page.evaluate((text) => {
      const started = performance.now();
      window.__replayed = null;
      window.sketchmesh.replay(text).then(
        () => { window.__replayed = { during: Math.max(0, ...window.__frames.list) }; },
        (e) => { window.__replayed = { error: e.message }; });
      return performance.now() - started;
    }, session);
    const replayed = await until(() => page.evaluate(() => window.__replayed), (r) => r !== null, 60_000);
    await record(false);
    assert.ok(replayed && !replayed.error, `the replay lands: ${replayed?.error}`);
    assert.ok(replay < 50, `replay returns within 50 ms: ${replay.toFixed(1)} ms`);
    assert.deepEqual(await api(page, 'stats'), stats, 'the replay makes the same shape');
    // Reported, not asserted: the replay repaints the scene with the 40k shape (about 200 ms a
    // frame on SwiftShader) while a fresh worker starts and computes on the other core; the
    // creation itself, 2–3 s in a frame before, is not among them.
    console.log(`    # replayed in the worker: longest frame ${replayed.during.toFixed(0)} ms (an orbit of the shape: ${shapeLongest.toFixed(0)} ms)`);
    assert.deepEqual(fresh.errors, [], 'console errors while creating');
  } finally {
    await fresh.context.close();
  }
});

// ---------------------------------------------------------------------------------------------
// Guidance: the hint line, the status line's tones and the first visit's introduction.

/** Every tool's key as the keyboard presses it (upper case: the hints' tests name them so). */
const TOOL_KEYS_UPPER = TOOL_KEYS.map((key) => key.toUpperCase());

/** A pen hovering at (x, y): the page sees the pen without a stroke. */
async function penHover(cdp, x, y) {
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x, y, buttons: 0, pointerType: 'pen', force: 0 });
}

/** How many pixels of `image`, in the band of rows `[y0, y1)`, lie within 40 of `rgb`. */
function pixelsNear(image, rgb, y0, y1) {
  let n = 0;
  for (let y = y0; y < y1; y++) {
    for (let x = 0; x < image.width; x++) {
      const i = 4 * (y * image.width + x);
      const d = Math.abs(image.data[i] - rgb[0]) + Math.abs(image.data[i + 1] - rgb[1]) + Math.abs(image.data[i + 2] - rgb[2]);
      if (d < 40) n++;
    }
  }
  return n;
}

// Whatever draws, the hint and status lines are the same text and colours: the WebGL2 run covers them.
test('hints: on an empty document every tool says what to do in the words of the mouse, the finger and the pen, naming Sketch where it cannot work on nothing; an outline drawn in Pull is refused in orange, naming Sketch, and an export is reported in green', { gpu: false }, async () => {
  const fresh = await openApp(browser, url, gpu);
  try {
    const { page, cdp } = fresh;
    const devices = [
      ['mouse', 'with the mouse', () => page.mouse.move(300, 300)],
      ['finger', 'with one finger', () => touchTap(cdp, [{ x: 300, y: 500 }])],
      ['pen', 'with the pen', () => penHover(cdp, 320, 320)],
    ];
    const said = {};
    for (const [device, words, use] of devices) {
      for (const key of TOOL_KEYS_UPPER) {
        await page.keyboard.press(key);
        await use();
        await frames(page, 2);
        const hint = await api(page, 'hint');
        said[key] = [...(said[key] ?? []), hint];
        assert.ok(hint.includes(words), `${key} with the ${device}: "${hint}"`);
        assert.ok(hint.includes('closed outline'), `${key} says how shapes are made: "${hint}"`);
        if (key !== 'S') assert.ok(hint.includes('Sketch'), `${key} names the tool that makes shapes: "${hint}"`);
      }
    }
    for (const key of TOOL_KEYS_UPPER) assert.equal(new Set(said[key]).size, 3, `${key}'s hint differs by device: ${JSON.stringify(said[key])}`);
    console.log(`    # Pull, by the pen: "${said.P[2]}"`);

    // A closed outline in Pull on nothing makes nothing, and says which tool makes shapes.
    await page.keyboard.press('P');
    await penStroke(cdp, onEllipse());
    const refused = await until(() => api(page, 'status'), (s) => s !== null, 5000);
    assert.equal(refused?.kind, 'refusal', JSON.stringify(refused));
    assert.match(refused.text, /Sketch/);
    assert.equal((await api(page, 'stats')).models, 0, 'Pull made no shape');
    await frames(page, 2);
    const height = page.viewportSize().height;
    const orange = await screenshot(page, out('status-refusal.png'));
    const [ORANGE, GREEN] = [[255, 160, 60], [110, 220, 140]];
    const refusalPixels = [pixelsNear(orange, ORANGE, height - 160, height), pixelsNear(orange, GREEN, height - 160, height)];

    // An export is a success: green, with its own marker.
    await page.keyboard.press('S');
    const [download] = await Promise.all([page.waitForEvent('download', { timeout: 10_000 }), page.keyboard.press('Control+e')]);
    await download.cancel().catch(() => {});
    const done = await until(() => api(page, 'status'), (s) => s?.kind === 'success', 5000);
    assert.equal(done?.kind, 'success', JSON.stringify(done));
    await frames(page, 2);
    const green = await screenshot(page, out('status-success.png'));
    const successPixels = [pixelsNear(green, ORANGE, height - 160, height), pixelsNear(green, GREEN, height - 160, height)];
    console.log(`    # orange/green pixels: refusal ${refusalPixels}, success ${successPixels}`);
    assert.ok(refusalPixels[0] > 200 && refusalPixels[1] < 20, `the refusal is orange: ${refusalPixels}`);
    assert.ok(successPixels[1] > 200 && successPixels[0] < 20, `the success is green: ${successPixels}`);
  } finally {
    await fresh.context.close();
  }
});

// The introduction is the page's UI and store, the same on both GPU paths.
test('introduction: a first visit shows step 1, a shape moves it to 2, an edit to 3; Skip hides it, it stays hidden after a reload, and Help shows it again', { gpu: false }, async () => {
  const fresh = await openApp(browser, url, gpu, { intro: true });
  try {
    const { page, cdp } = fresh;
    let intro = await until(() => api(page, 'intro'), (i) => i !== null, 3000);
    assert.equal(intro?.step, 1, `a first visit shows the first step: ${JSON.stringify(intro)}`);
    await screenshot(page, out('intro-1.png'));
    await penStroke(cdp, onEllipse());
    intro = await until(() => api(page, 'intro'), (i) => i?.step === 2, 15_000);
    assert.equal(intro?.step, 2, 'a shape moves it on');
    await screenshot(page, out('intro-2.png'));
    await page.keyboard.press('E');
    // Erase a curve of the shape: the ellipse's outline curve, at its right end.
    await penStroke(cdp, line({ x: CENTRE.x + 200, y: CENTRE.y - 40 }, { x: CENTRE.x + 200, y: CENTRE.y + 40 }, 12));
    await page.keyboard.press('V');
    await page.mouse.click(CENTRE.x, CENTRE.y);
    await frames(page, 2);
    const dragged = line({ x: CENTRE.x, y: CENTRE.y }, { x: CENTRE.x + 60, y: CENTRE.y + 20 }, 10);
    await penStroke(cdp, dragged);
    intro = await until(() => api(page, 'intro'), (i) => i?.step === 3, 10_000);
    assert.equal(intro?.step, 3, `an edit moves it on: ${JSON.stringify(intro)}, ops ${JSON.parse(await api(page, 'session')).ops.map((o) => o.op)}`);
    assert.ok(Array.isArray(intro.skip), 'Skip is on screen');
    await page.mouse.click(intro.skip[0], intro.skip[1]);
    intro = await until(() => api(page, 'intro'), (i) => i === null, 3000);
    assert.equal(intro, null, 'Skip hides it');
    await page.reload({ waitUntil: 'load' });
    await page.waitForFunction(() => typeof window.sketchmesh?.intro === 'function', null, { timeout: 15_000 });
    await frames(page, 3);
    assert.equal(await api(page, 'intro'), null, 'it stays hidden after a reload');
    await page.keyboard.press('F1');
    await frames(page, 3);
    await screenshot(page, out('intro-help.png'));
    // Help's "Show the introduction", beside "User guide" at the top of the 1280 px wide
    // page's Help window.
    await page.mouse.click(180, 67);
    intro = await until(() => api(page, 'intro'), (i) => i !== null, 3000);
    assert.equal(intro?.step, 2, `Help shows it again, past the shape that exists: ${JSON.stringify(intro)}`);
  } finally {
    await fresh.context.close();
  }
});

// ---------------------------------------------------------------------------------------------
// Symmetry (issue 50): on for a new visitor, about the plane x = 0 (the view's middle, x = 640).

/** The toolbar's Symmetry switch, beside Redo, at 1280 px wide. */
const SYMMETRY_SWITCH = { x: 249, y: 25 };

/**
 * A fresh page with Symmetry on (a new visitor's default, checked) and the ELLIPSE outline
 * drawn across the plane: runs `body({ fresh, body })` (`body` the shape's bounds
 * `[lo, hi]`) and closes the page whatever happens.
 */
async function withSymmetricBody(run) {
  const fresh = await openApp(browser, url, gpu, { symmetry: true });
  try {
    const { page } = fresh;
    const symmetry = await api(page, 'symmetry');
    assert.deepEqual(symmetry, { on: true, forNew: true, plane: [1, 0, 0, 0] }, 'on for a new visitor, about x = 0');
    await penStroke(fresh.cdp, onEllipse());
    const made = await until(() => lastOpOf(page), (o) => o.op === 'create', 15_000);
    assert.deepEqual(made.mirror, [1, 0, 0, 0], `the outline is made with symmetry on: ${JSON.stringify(made).slice(-80)}`);
    const [body] = await api(page, 'bounds');
    assertMirrored(body, body, 'the outline across the plane makes one symmetric shape');
    await run({ fresh, body });
    assert.deepEqual(fresh.errors, [], 'console errors');
  } finally {
    await fresh.context.close();
  }
}

/** Asserts that box `b` (`[lo, hi]`) is box `a` mirrored across x = 0, to 1e-6 of its size. */
function assertMirrored(a, b, what) {
  const size = Math.hypot(...a[1].map((v, k) => v - a[0][k]));
  const mirrored = [[-a[1][0], a[0][1], a[0][2]], [-a[0][0], a[1][1], a[1][2]]];
  const off = Math.max(...mirrored.flat().map((v, k) => Math.abs(v - b.flat()[k])));
  assert.ok(off <= 1e-6 * size, `${what}: ${JSON.stringify(b)} is not ${JSON.stringify(mirrored)} (off by ${off})`);
}

// WebGL2 only: the ops and the document.
test('symmetry: an outline across the plane makes one symmetric shape, and a limb extruded on its right grows one on its left too', { gpu: false }, () => withSymmetricBody(async ({ fresh, body }) => {
  const { page, cdp } = fresh;
  const c = ELLIPSE.c;
  // The extrude case's gesture: a loop on the right of the shape, a stroke out and back.
  const base = { x: c.x + 110, y: c.y };
  const loop = Array.from({ length: 41 }, (_, i) => {
    const a = (2 * Math.PI * i) / 40;
    return { x: base.x + 28 * Math.cos(a), y: base.y + 28 * Math.sin(a), force: 0.5 };
  });
  await penStroke(cdp, loop);
  await frames(page, 2);
  const silhouette = Array.from({ length: 41 }, (_, i) => {
    const a = Math.PI * (i / 40 - 0.5);
    return { x: base.x + 220 * Math.cos(a), y: base.y + 28 * Math.sin(a), force: 0.5 };
  });
  await penStroke(cdp, silhouette);
  const op = await until(() => lastOpOf(page), (o) => o.op === 'extrude', 15_000);
  assert.deepEqual([op.op, op.mirror], ['extrude', [1, 0, 0, 0]], 'the limb is extruded with symmetry on');
  const [limbs] = await api(page, 'bounds');
  assertMirrored(limbs, limbs, 'the shape with its limbs stays symmetric');
  const width = (box) => box[1][0] - box[0][0];
  assert.ok(width(limbs) > 1.6 * width(body), `a limb on each side: ${width(body)} wide, then ${width(limbs)}`);
  await frames(page, 3);
  await screenshot(page, out('symmetry-limbs.png'));
}));

// WebGL2 only: the ops and the document.
test('symmetry: a blob drawn beside the plane comes with its mirror twin and one undo takes both; the toolbar switch turns symmetry off, kept for new documents; an import turns it off for its document only', { gpu: false }, async () => {
  const fresh = await openApp(browser, url, gpu, { symmetry: true });
  try {
    const { page, cdp } = fresh;
    // A small blob right of the middle, wholly on one side: it and its twin on the left.
    const blob = Array.from({ length: 41 }, (_, i) => {
      const a = (2 * Math.PI * i) / 40;
      return { x: 1130 + 50 * Math.cos(a), y: 640 + 35 * Math.sin(a), force: 0.5 };
    });
    await penStroke(cdp, blob);
    const boxes = await until(() => api(page, 'bounds'), (b) => b.length === 2, 15_000);
    assert.equal(boxes.length, 2, 'the blob and its twin');
    assert.ok(boxes[0][0][0] > 0, `the blob is right of the plane: ${JSON.stringify(boxes[0])}`);
    assertMirrored(boxes[0], boxes[1], 'the twin is the blob mirrored');
    await frames(page, 3);
    await screenshot(page, out('symmetry-twins.png'));
    // One undo takes the blob and its twin.
    await page.keyboard.press('Control+z');
    assert.equal((await until(() => api(page, 'bounds'), (b) => b.length === 0, 5000)).length, 0, 'one undo takes both');
    // The toolbar's switch, beside Redo, turns it off, for new documents too (kept by the
    // page across visits); the same blob then makes one shape.
    await page.mouse.click(SYMMETRY_SWITCH.x, SYMMETRY_SWITCH.y);
    const off = await until(() => api(page, 'symmetry'), (s) => !s.on, 3000);
    assert.deepEqual([off.on, off.forNew], [false, false], 'the switch turns it off');
    assert.equal(await page.evaluate(() => localStorage.getItem('sketchmesh.symmetry')), 'off', 'kept for the next visit');
    await penStroke(cdp, blob);
    assert.equal((await until(() => api(page, 'bounds'), (b) => b.length === 1, 15_000)).length, 1, 'one blob without symmetry');
    assert.equal((await lastOpOf(page)).mirror, undefined, 'made with symmetry off');
    // On again; an import turns it off for its document only (a scan is rarely symmetric).
    await page.mouse.click(SYMMETRY_SWITCH.x, SYMMETRY_SWITCH.y);
    assert.ok((await until(() => api(page, 'symmetry'), (s) => s.on, 3000)).on, 'the switch turns it on');
    const glb = tetraWithDuplicateGlb();
    await page.evaluate((bytes) => window.sketchmesh.loadGlb(new Uint8Array(bytes), 'tetra.glb'), Array.from(glb));
    const imported = await api(page, 'symmetry');
    assert.deepEqual([imported.on, imported.forNew], [false, true], 'off after the import, still on for new documents');
    assert.deepEqual(fresh.errors, [], 'console errors');
  } finally {
    await fresh.context.close();
  }
});

// WebGL2 only: the ops and the document.
test('symmetry: a pull on the right of a symmetric shape moves both sides; the switch off (X), the next pull moves one', { gpu: false }, () => withSymmetricBody(async ({ fresh, body }) => {
  const { page, cdp } = fresh;
  const c = ELLIPSE.c;
  await page.keyboard.press('p');
  const drag = [];
  for (let i = 0; i <= 16; i++) drag.push({ x: c.x + 170 + 5 * i, y: c.y, force: 0.5 });
  await penStroke(cdp, drag);
  const pull = await until(() => lastOpOf(page), (o) => o.op === 'pull', 15_000);
  assert.deepEqual(pull.mirror, [1, 0, 0, 0], 'the pull is made with symmetry on');
  const [pulled] = await api(page, 'bounds');
  assertMirrored(pulled, pulled, 'both sides moved alike');
  assert.ok(pulled[1][0] > body[1][0] * 1.1 && pulled[0][0] < body[0][0] * 1.1, `wider on both sides: ${JSON.stringify(body)} then ${JSON.stringify(pulled)}`);
  await frames(page, 3);
  await screenshot(page, out('symmetry-pull.png'));
  await page.keyboard.press('x');
  assert.deepEqual(await until(() => api(page, 'symmetry'), (s) => !s.on, 3000), { on: false, forNew: false, plane: [1, 0, 0, 0] }, 'X turns it off');
  // The left side's outline is where the right one was pulled to, mirrored: pull it further.
  const left = drag.map((p, i) => ({ ...p, x: c.x - 170 - 80 - 5 * i }));
  await penStroke(cdp, left);
  const plain = await until(() => lastOpOf(page), (o) => o.op === 'pull' && o.mirror === undefined, 15_000);
  assert.equal(plain.mirror, undefined, 'made with symmetry off');
  const [once] = await api(page, 'bounds');
  const width = pulled[1][0] - pulled[0][0];
  assert.ok(Math.abs(once[1][0] - pulled[1][0]) < 0.02 * width, `the right side stays: ${pulled[1][0]} then ${once[1][0]}`);
  assert.ok(once[0][0] < pulled[0][0] - 0.05 * width, `the left side moved out: ${pulled[0][0]} then ${once[0][0]}`);
}));

// ---------------------------------------------------------------------------------------------
// Paint (issue 51).

/** The JSON chunk of a .glb and its BIN chunk. */
function glbParts(bytes) {
  const buffer = Buffer.from(bytes);
  const jsonLength = buffer.readUInt32LE(12);
  const json = JSON.parse(buffer.subarray(20, 20 + jsonLength).toString('utf8'));
  return { json, bin: buffer.subarray(20 + jsonLength + 8) };
}

/** The float VEC3 values of accessor `index` of a .glb's parts. */
function vec3s({ json, bin }, index) {
  const accessor = json.accessors[index];
  const view = json.bufferViews[accessor.bufferView];
  const start = (view.byteOffset ?? 0) + (accessor.byteOffset ?? 0);
  return Array.from({ length: accessor.count }, (_, k) => [0, 1, 2].map((c) => bin.readFloatLE(start + 12 * k + 4 * c)));
}

// WebGL2 only: the op, the file and the pixels of the colour.
test('paint (C): a pen stroke with pressure paints the shape under it as it goes, the export carries the colours as COLOR_0, one undo takes them back', { gpu: false }, () => withShape(async ({ fresh }) => {
  const { page, cdp } = fresh;
  await page.keyboard.press('c');
  await frames(page, 3);
  const before = await screenshot(page, out('paint-before.png'));
  const c = ELLIPSE.c;
  const stroke = Array.from({ length: 31 }, (_, i) => ({ x: c.x - 100 + (200 * i) / 30, y: c.y, force: 0.3 + (0.5 * i) / 30 }));
  await penStroke(cdp, stroke, 25);
  const paint = await until(() => lastOpOf(page), (o) => o.op === 'paint', 15_000);
  assert.equal(paint.op, 'paint', 'the stroke is one paint op');
  const forces = paint.stroke.map((s) => s[2]);
  assert.ok(Math.max(...forces) - Math.min(...forces) > 0.3, `the pen's pressure is kept: ${forces[0]} to ${forces.at(-1)}`);
  await frames(page, 4);
  const after = await screenshot(page, out('paint-after.png'));
  const at = (shot, x, y) => shot.data.slice((y * shot.width + x) * 4, (y * shot.width + x) * 4 + 3);
  const reddened = stroke.filter((p, i) => i % 3 === 0).filter((p) => {
    const [r0, g0] = at(before, Math.round(p.x), Math.round(p.y));
    const [r1, g1] = at(after, Math.round(p.x), Math.round(p.y));
    return r1 - g1 > r0 - g0 + 60;
  });
  assert.ok(reddened.length >= 6, `the stroke shows in the brush's red at ${reddened.length} of 11 points`);
  const { x: farX, y: farY } = { x: c.x, y: c.y + 90 };
  assert.ok(maxDiffNear(before, after, farX, farY, 6) < 30, 'away from the stroke the shape keeps its clay');
  const bytes = await glbOf(page);
  writeFileSync(out('painted.glb'), Buffer.from(bytes));
  const parts = glbParts(bytes);
  const primitive = parts.json.meshes[0].primitives[0];
  assert.ok(primitive.attributes.COLOR_0 !== undefined, 'the export has vertex colours');
  const colours = vec3s(parts, primitive.attributes.COLOR_0);
  const red = colours.filter(([r, g, b]) => r > 0.6 && g < 0.25 && b < 0.25).length;
  assert.ok(red > 5 && red < colours.length / 2, `${red} of ${colours.length} vertices painted red`);
  const material = parts.json.materials[primitive.material];
  assert.deepEqual(material.pbrMetallicRoughness.baseColorFactor, [1, 1, 1, 1], 'a white base colour under the paint');
  await page.keyboard.press('Control+z');
  await until(() => lastOpOf(page), (o) => o.op === 'undo', 5000);
  const undone = glbParts(await glbOf(page));
  assert.equal(undone.json.meshes[0].primitives[0].attributes.COLOR_0, undefined, 'one undo takes the colours back');
  assert.deepEqual(fresh.errors, [], 'console errors');
}));

const failed = await runAll();
await hiDpi?.close();
await browser.close();
process.exit(failed === 0 ? 0 : 1);
