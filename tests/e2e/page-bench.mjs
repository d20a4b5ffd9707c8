// Page timings for `cargo xtask bench`: time to interactive and frame times while a pen stroke is
// drawn (from requestAnimationFrame timestamps inside the page), and the import of a 1 M-triangle
// .glb. Prints one JSON line at the end.
//
//   SKETCHMESH_URL=http://127.0.0.1:8080/ SKETCHMESH_GPU=webgl2 node tests/e2e/page-bench.mjs
//
// Headless Chromium renders with SwiftShader on the CPU here, so absolute numbers are a floor
// for real hardware rather than a prediction; compare runs on the same machine.

import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

import { GRID_GLB_SOURCE, OUT_DIR, api, launch, penStroke, screenshot, settings, sleep } from './lib.mjs';

const round = (ms) => (ms === null || ms === undefined ? null : Math.round(ms * 10) / 10);

/** Count, mean, median, 95th percentile and maximum of a list of times. */
function distribution(list) {
  const sorted = [...list].sort((a, b) => a - b);
  const at = (q) => (sorted.length ? sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))] : null);
  const mean = sorted.length ? sorted.reduce((a, b) => a + b, 0) / sorted.length : null;
  return { n: sorted.length, mean: round(mean), p50: round(at(0.5)), p95: round(at(0.95)), max: round(sorted.at(-1) ?? null) };
}

const STROKE_POINTS = 90;
const { url, gpu } = settings();

const browser = await launch(gpu);

/**
 * A fresh page of its own with Nefertiti (99,938 triangles) imported, every animation frame's
 * timestamp recorded into `window.__bench.frames` while `window.__bench.recording`; `null`
 * (said loudly) when the test data is missing.
 */
async function nefertitiPage(what) {
  const file = join(process.env.SKETCHMESH_TESTDATA ?? '../shared/testdata', 'meshes', 'nefertiti.glb');
  if (!existsSync(file)) {
    console.error(`${what}: SKIPPED, ${file} is missing (set SKETCHMESH_TESTDATA)`);
    return { skipped: `${file} is missing` };
  }
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  await context.addInitScript(() => {
    const bench = { frames: [], callbackMs: [], recording: false, apiAt: null, shownAt: null };
    window.__bench = bench;
    // The page's own animation-frame callbacks (the app's update, paint and GPU submission),
    // timed: what the app costs the main thread per frame, apart from the rasterizer.
    const raf = window.requestAnimationFrame.bind(window);
    window.requestAnimationFrame = (callback) => raf((t) => {
      const start = performance.now();
      try {
        callback(t);
      } finally {
        if (bench.recording) bench.callbackMs.push(performance.now() - start);
      }
    });
    const tick = (t) => {
      if (bench.apiAt === null && window.sketchmesh) bench.apiAt = performance.now();
      if (bench.shownAt === null && window.sketchmesh?.stats?.().models > 0) bench.shownAt = performance.now();
      if (bench.recording) bench.frames.push(t);
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const page = await context.newPage();
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.sketchmesh?.stats !== undefined, null, { timeout: 30_000 });
  const triangles = await page.evaluate(async (data) => {
    await window.sketchmesh.loadGlb(new Uint8Array(data), 'nefertiti.glb');
    return window.sketchmesh.stats().triangles;
  }, [...readFileSync(file)]);
  await sleep(1500);
  return { context, page, triangles };
}

/**
 * The autosave of a 100k-triangle document (Nefertiti, 99,938 triangles, imported): the longest
 * frame while a change is written (the session with the import's bytes is what is serialized),
 * the app's own time for each write (serialized and handed to IndexedDB's queue), and the
 * restore on reload (from `window.sketchmesh` appearing to the document shown, and from
 * navigation).
 */
async function autosaveBench() {
  const { context, page, triangles, skipped } = await nefertitiPage('autosave');
  if (skipped) return { skipped };
  try {
    // An undo is written at once (the last write is old); a redo 100 ms later waits for the
    // half-second interval, so its write has a frame of its own, apart from the redo's
    // rebuild of the view: the frames from 250 ms after the redo hold the write and no rebuild.
    const frames = await page.evaluate(async () => {
      const b = window.__bench;
      window.sketchmesh.timings();
      window.sketchmesh.undo();
      await new Promise((resolve) => setTimeout(resolve, 100));
      b.frames = [];
      b.recording = true;
      window.sketchmesh.redo();
      const redoneAt = performance.now();
      await new Promise((resolve) => setTimeout(resolve, 1500));
      b.recording = false;
      return b.frames.filter((t) => t > redoneAt + 250);
    });
    const longest = Math.max(...frames.slice(1).map((t, i) => t - frames[i]));
    const writes = (await api(page, 'timings')).autosave?.frame_ms ?? [];
    const bytes = await page.evaluate(() => window.sketchmesh.session().length);
    await sleep(500);
    await page.reload({ waitUntil: 'load' });
    await page.waitForFunction(() => window.__bench.shownAt !== null, null, { timeout: 30_000, polling: 50 });
    const restore = await page.evaluate(() => ({ fromApi: window.__bench.shownAt - window.__bench.apiAt, fromNavigation: window.__bench.shownAt }));
    return {
      triangles,
      session_bytes: bytes,
      longest_frame_while_saving_ms: round(longest),
      frames: frames.length,
      writes: writes.length,
      write_ms: round(Math.max(...writes)),
      restore_ms: round(restore.fromApi),
      load_to_document_ms: round(restore.fromNavigation),
    };
  } finally {
    await context.close();
  }
}
/**
 * Moving a 100k-triangle model with the Move tool's handles (Nefertiti, 99,938 triangles): the
 * model is tapped, then dragged 240 px by its body with the mouse in 60 moves 16 ms apart;
 * the animation frames' intervals during the drag, and the app's own time per drag frame (the
 * transform previewed) and for the release (the op committed).
 */
async function gizmoBench() {
  const { context, page, triangles, skipped } = await nefertitiPage('gizmo');
  if (skipped) return { skipped };
  try {
    await page.keyboard.press('v');
    const middle = await page.evaluate(() => {
      const r = document.querySelector('canvas').getBoundingClientRect();
      return { x: r.left + r.width / 2, y: r.top + r.height / 2 };
    });
    await page.mouse.click(middle.x, middle.y);
    await sleep(300);
    await page.evaluate(() => {
      window.sketchmesh.timings();
      window.__bench.frames = [];
      window.__bench.callbackMs = [];
      window.__bench.recording = true;
    });
    await page.mouse.move(middle.x, middle.y);
    await page.mouse.down();
    for (let i = 1; i <= 60; i++) {
      await page.mouse.move(middle.x + 4 * i, middle.y);
      await sleep(16);
    }
    await page.mouse.up();
    await sleep(300);
    const { frames, callbackMs } = await page.evaluate(() => { window.__bench.recording = false; return window.__bench; });
    const intervals = frames.slice(1).map((t, i) => t - frames[i]).sort((a, b) => a - b);
    const at = (q) => intervals[Math.min(intervals.length - 1, Math.floor(q * intervals.length))];
    const callbacks = [...callbackMs].sort((a, b) => a - b);
    const transform = (await api(page, 'timings')).transform ?? { frame_ms: [], finish_ms: [] };
    const mean = (list) => (list.length ? list.reduce((a, b) => a + b, 0) / list.length : null);
    const last = JSON.parse(await api(page, 'session')).ops.at(-1)?.op;
    if (last !== 'transform') console.error(`gizmo: the drag committed ${last}, not a transform`);
    return {
      triangles,
      frames: intervals.length,
      interval_ms: { mean: round(mean(intervals)), p50: round(at(0.5)), p95: round(at(0.95)), max: round(intervals.at(-1) ?? null) },
      drag_frame_ms: { mean: round(mean(transform.frame_ms)), max: round(Math.max(...transform.frame_ms)) },
      app_frame_ms: {
        mean: round(mean(callbacks)),
        p95: round(callbacks[Math.min(callbacks.length - 1, Math.floor(0.95 * callbacks.length))] ?? null),
        max: round(callbacks.at(-1) ?? null),
      },
      release_ms: round(transform.finish_ms.at(-1) ?? null),
    };
  } finally {
    await context.close();
  }
}
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 }, hasTouch: true });
  // Runs before the page's scripts: records every animation frame's timestamp (ms since navigation
  // start) while recording, when `window.sketchmesh` appears, and the second animation frame after
  // that (the app, which draws in its own animation frames, has drawn by then).
  await context.addInitScript(() => {
    const bench = { frames: [], recording: false, apiAt: null, interactiveAt: null, framesSinceApi: 0 };
    window.__bench = bench;
    const tick = (t) => {
      if (bench.apiAt !== null && bench.interactiveAt === null && ++bench.framesSinceApi === 2) {
        bench.interactiveAt = performance.now();
      }
      if (bench.apiAt === null && window.sketchmesh) bench.apiAt = performance.now();
      if (bench.recording) bench.frames.push(t);
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  });
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.__bench.interactiveAt !== null, null, { timeout: 30_000, polling: 50 });
  const backend = await api(page, 'backend');
  await sleep(300);

  const n = STROKE_POINTS;
  const points = Array.from({ length: n + 1 }, (_, i) => {
    const t = i / n;
    const angle = 2 * Math.PI * 0.9 * t;
    return { x: 660 + 180 * Math.cos(angle), y: 380 + 140 * Math.sin(angle), force: 0.3 + 0.5 * Math.sin(Math.PI * t) };
  });
  await page.evaluate(() => {
    window.__bench.recording = true;
  });
  const strokeStarted = Date.now();
  await penStroke(cdp, points, 16);
  // Include the frames that commit the stroke.
  await sleep(250);
  const strokeMs = Date.now() - strokeStarted;
  const timing = await page.evaluate(() => {
    const b = window.__bench;
    b.recording = false;
    return { frames: b.frames, apiAt: b.apiAt, interactiveAt: b.interactiveAt };
  });
  const stats = await api(page, 'stats');

  // Import of a 1 M-triangle .glb (a 708 x 708 grid, built in the page) through loadGlb: the
  // parse, weld and manifold check, timed inside the page.
  await page.evaluate(GRID_GLB_SOURCE);
  const imported = await page.evaluate(async (n) => {
    const glb = window.gridGlb(n);
    await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
    const started = performance.now();
    const landed = window.sketchmesh.loadGlb(glb, 'grid.glb');
    const returnedMs = performance.now() - started;
    await landed;
    const ms = performance.now() - started;
    return { ms, returnedMs, bytes: glb.length, triangles: window.sketchmesh.stats().triangles };
  }, 708);

  // Curve pulls on FiberMesh shapes of 10k and 40k vertices (written by `cargo xtask bench`,
  // paths in SKETCHMESH_PULL_FIXTURES): the app times pointer-down (grab), every drag frame
  // (curve deformation + regional surface update) and the release (the committed op).
  const pulls = [];
  // A fresh page: the sections above leave their strokes and imports behind.
  await page.reload();
  await page.waitForFunction(() => window.sketchmesh !== undefined, null, { timeout: 30_000 });
  await sleep(1000);
  for (const path of (process.env.SKETCHMESH_PULL_FIXTURES ?? '').split(',').filter(Boolean)) {
    const bytes = [...readFileSync(path)];
    const vertices = await page.evaluate(async (data) => {
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(new Uint8Array(data), 'fixture.glb');
      window.sketchmesh.timings();
      return window.sketchmesh.stats().vertices;
    }, bytes);
    await sleep(300);
    // The import framed the view; back to the default camera the fixture was drawn with.
    await page.keyboard.press('r');
    await page.keyboard.press('p');
    await sleep(100);
    // Grab the outline (drawn blue) at its rightmost visible pixel, once the page has drawn
    // the import (egui repaints on input).
    for (let i = 0; i < 3; i++) {
      await page.mouse.move(5 + i, 715);
      await sleep(150);
    }
    const shot = await screenshot(page, join(OUT_DIR, `bench-pull-${vertices}.png`));
    // The rightmost blue pixel, grabbed 2 px inside it.
    let rightmost = null;
    for (let y = 60; y < shot.height; y++) {
      for (let x = shot.width - 1; x > (rightmost?.x ?? 0); x--) {
        const [r, g, b] = shot.data.slice((y * shot.width + x) * 4, (y * shot.width + x) * 4 + 3);
        if (b > 200 && g > 110 && r < 110) {
          rightmost = { x, y };
          break;
        }
      }
    }
    let grab = rightmost && { x: rightmost.x - 2, y: rightmost.y };
    if (!grab) {
      // Not drawn yet (a large import can take longer than the waits above): the fixture's
      // ellipse is centred in the canvas with a half-width of 260 px (benches/common).
      const canvas = await page.evaluate(() => {
        const r = document.querySelector('canvas').getBoundingClientRect();
        return { x: r.left, y: r.top, width: r.width, height: r.height };
      });
      grab = { x: Math.round(canvas.x + canvas.width / 2 + 258), y: Math.round(canvas.y + canvas.height / 2) };
      console.error(`no blue outline found in the ${vertices}-vertex view; grabbing at the fixture's known outline point`);
    }
    const pen = { pointerType: 'pen', button: 'left', force: 0.5 };
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: grab.x, y: grab.y, buttons: 1, clickCount: 1, ...pen });
    for (let i = 1; i <= 60; i++) {
      await sleep(16);
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: grab.x + 1.5 * i, y: grab.y - 0.5 * i, buttons: 1, ...pen });
    }
    await sleep(50);
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: grab.x + 90, y: grab.y - 30, buttons: 0, clickCount: 1, ...pen });
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'pull', null, { timeout: 30_000, polling: 50 })
      .catch(() => {});
    const t = await api(page, 'timings');
    const pull = t.pull ?? { begin_ms: [], frame_ms: [], finish_ms: [] };
    // A cut across the same shape, left of the pull, with the pen in the sketch tool: the
    // stroke waits 0.6 s for a tap, then cuts; the app times the op itself (and the tunnel's
    // below).
    await page.keyboard.press('s');
    const box = await page.evaluate(() => {
      const r = document.querySelector('canvas').getBoundingClientRect();
      return { x: r.left + r.width / 2, y: r.top + r.height / 2 };
    });
    const cutX = box.x - 0.6 * 260;
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: cutX, y: box.y - 240, buttons: 1, clickCount: 1, ...pen });
    for (let i = 1; i <= 40; i++) {
      await sleep(16);
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: cutX, y: box.y - 240 + 12 * i, buttons: 1, ...pen });
    }
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: cutX, y: box.y + 240, buttons: 0, clickCount: 1, ...pen });
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'cut', null, { timeout: 30_000, polling: 50 })
      .catch(() => console.error(`the cut at ${vertices} vertices was not applied`));
    const cut = (await api(page, 'timings')).cut;
    // A tunnel through the middle: a pen loop, half a turn round the shape with the right
    // mouse button (0.008 rad per px), the same loop on the far side.
    const loop = Array.from({ length: 41 }, (_, i) => {
      const a = (2 * Math.PI * i) / 40;
      return { x: box.x + 40 * Math.cos(a), y: box.y + 40 * Math.sin(a) };
    });
    const drawLoop = async () => {
      await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...loop[0], buttons: 1, clickCount: 1, ...pen });
      for (const point of loop.slice(1)) {
        await sleep(16);
        await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...point, buttons: 1, ...pen });
      }
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...loop.at(-1), buttons: 0, clickCount: 1, ...pen });
    };
    await drawLoop();
    await sleep(200);
    const turn = Math.round(Math.PI / 0.008);
    const right = { button: 'right' };
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: box.x - turn / 2, y: box.y + 280, buttons: 2, clickCount: 1, ...right });
    for (let i = 1; i <= 20; i++) {
      await sleep(16);
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: box.x - turn / 2 + (turn * i) / 20, y: box.y + 280, buttons: 2, ...right });
    }
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: box.x + turn / 2, y: box.y + 280, buttons: 0, clickCount: 1, ...right });
    await sleep(200);
    await drawLoop();
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'tunnel', null, { timeout: 30_000, polling: 50 })
      .catch(() => console.error(`the tunnel at ${vertices} vertices was not applied`));
    const tunnel = (await api(page, 'timings')).tunnel;
    // An extrusion upward from the right half, seen from the front again: a pen loop, then
    // (instead of the tap) its silhouette from the loop's left side up 150 px and back down
    // to its right side.
    await page.keyboard.press('r');
    await sleep(200);
    const base = { x: box.x + 100, y: box.y - 40 };
    const baseLoop = Array.from({ length: 41 }, (_, i) => {
      const a = (2 * Math.PI * i) / 40;
      return { x: base.x + 22 * Math.cos(a), y: base.y + 22 * Math.sin(a) };
    });
    const silhouette = Array.from({ length: 41 }, (_, i) => {
      const a = Math.PI * (i / 40 - 0.5);
      return { x: base.x + 22 * Math.sin(a), y: base.y - 150 * Math.cos(a) };
    });
    for (const stroke of [baseLoop, silhouette]) {
      await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...stroke[0], buttons: 1, clickCount: 1, ...pen });
      for (const point of stroke.slice(1)) {
        await sleep(16);
        await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...point, buttons: 1, ...pen });
      }
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...stroke.at(-1), buttons: 0, clickCount: 1, ...pen });
      await sleep(200);
    }
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'extrude', null, { timeout: 30_000, polling: 50 })
      .catch(async () => console.error(`the extrusion at ${vertices} vertices was not applied: ${JSON.parse(await api(page, 'session')).ops.slice(-3).map((o) => o.op)}`));
    const extrude = (await api(page, 'timings')).extrude;
    // A merge of the fixture and a copy moved to overlap it by half its width (1.8 units):
    // the replay of [import, duplicate, move, merge] less that of the same without the merge.
    const ops = JSON.parse(await api(page, 'session')).ops;
    const half = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1.8 - 1.2 * 3.59, 0, 0, 1];
    const prefix = [ops[0], { op: 'duplicate', model: 0 }, { op: 'transform', model: 1, matrix: half }];
    const replayMs = (list) => page.evaluate(async (text) => {
      const start = performance.now();
      await window.sketchmesh.replay(text);
      return performance.now() - start;
    }, JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: list }));
    const withoutMerge = await replayMs(prefix);
    let merge_ms = null;
    try {
      merge_ms = (await replayMs([...prefix, { op: 'merge', models: [0, 1] }])) - withoutMerge;
    } catch (error) {
      console.error(`the merge at ${vertices} vertices was refused: ${error.message}`);
    }
    pulls.push({
      vertices,
      grab_ms: round(pull.begin_ms.at(-1) ?? null),
      frame_ms: distribution(pull.frame_ms),
      // Each preview the worker computed while the pen moved, asked to shown (the region's
      // factorizations run there).
      preview_ms: distribution(pull.preview_ms ?? []),
      // The committed ops' work in the page's frames, and in its worker (the page drew
      // meanwhile).
      release_ms: round(pull.finish_ms.at(-1) ?? null),
      release_worker_ms: round(pull.elsewhere_ms?.at(-1) ?? null),
      cut_ms: round(cut?.finish_ms.at(-1) ?? null),
      cut_worker_ms: round(cut?.elsewhere_ms?.at(-1) ?? null),
      tunnel_ms: round(tunnel?.finish_ms.at(-1) ?? null),
      tunnel_worker_ms: round(tunnel?.elsewhere_ms?.at(-1) ?? null),
      extrude_ms: round(extrude?.finish_ms.at(-1) ?? null),
      extrude_worker_ms: round(extrude?.elsewhere_ms?.at(-1) ?? null),
      merge_ms: round(merge_ms),
    });
    console.error(`pull, cut and tunnel at ${vertices} vertices: ${JSON.stringify(pulls.at(-1))}`);
  }

  // An over-sketch of the 36,864-vertex bumpy torus (SKETCHMESH_OVERSKETCH_FIXTURE), seen down
  // its axis: a pen stroke pushes 70 degrees of the outer outline out by up to 25 px. Timed
  // from inside the page, from just before the pen lifts to the animation frame after the one
  // that applied the op (the result on screen), and by the app around the op itself.
  let oversketch = null;
  const torusPath = process.env.SKETCHMESH_OVERSKETCH_FIXTURE;
  if (torusPath) {
    const vertices = await page.evaluate(async (data) => {
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(new Uint8Array(data), 'bumpy-torus.glb');
      window.sketchmesh.timings();
      return window.sketchmesh.stats().vertices;
    }, [...readFileSync(torusPath)]);
    await sleep(300);
    await page.keyboard.press('r');
    await page.keyboard.press('o');
    for (let i = 0; i < 3; i++) {
      await page.mouse.move(5 + i, 715);
      await sleep(150);
    }
    const shot = await screenshot(page, join(OUT_DIR, 'bench-oversketch-before.png'));
    // The lit model is the only bright thing below the toolbar (two rows, with the tool's
    // options, about 80 px: its labels are bright too): its bounding box gives the outline's
    // centre and outer radius.
    const box = { x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity };
    for (let y = 100; y < shot.height; y++) {
      for (let x = 0; x < shot.width; x++) {
        const [r, g, b] = shot.data.slice((y * shot.width + x) * 4, (y * shot.width + x) * 4 + 3);
        if (Math.min(r, g, b) > 110) {
          box.x0 = Math.min(box.x0, x);
          box.x1 = Math.max(box.x1, x);
          box.y0 = Math.min(box.y0, y);
          box.y1 = Math.max(box.y1, y);
        }
      }
    }
    if (box.x1 > box.x0) {
      const centre = { x: (box.x0 + box.x1) / 2, y: (box.y0 + box.y1) / 2 };
      const radius = (box.x1 - box.x0) / 2;
      const n = 45;
      const stroke = Array.from({ length: n + 1 }, (_, i) => {
        const u = i / n;
        const angle = ((-35 + 70 * u) * Math.PI) / 180;
        const r = radius + 25 * Math.sin(Math.PI * u);
        return { x: centre.x + r * Math.cos(angle), y: centre.y + r * Math.sin(angle) };
      });
      const pen = { pointerType: 'pen', button: 'left', force: 0.5 };
      const [first, ...rest] = stroke;
      await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...first, buttons: 1, clickCount: 1, ...pen });
      for (const point of rest) {
        await sleep(16);
        await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...point, buttons: 1, ...pen });
      }
      await sleep(50);
      // Installed (and awaited) before the pen lifts: the watcher's clock starts first.
      await page.evaluate(() => {
        const started = performance.now();
        const before = window.sketchmesh.opCount();
        window.__shown = new Promise((resolve) => {
          const tick = () => {
            if (window.sketchmesh.opCount() > before) requestAnimationFrame(() => resolve(performance.now() - started));
            else if (performance.now() - started > 10_000) resolve(null);
            else requestAnimationFrame(tick);
          };
          requestAnimationFrame(tick);
        });
      });
      const last = stroke.at(-1);
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...last, buttons: 0, clickCount: 1, ...pen });
      const shownMs = await page.evaluate(() => window.__shown);
      const t = await api(page, 'timings');
      await page.mouse.move(10, 715);
      await sleep(150);
      await screenshot(page, join(OUT_DIR, 'bench-oversketch-after.png'));
      oversketch = { vertices, release_to_shown_ms: round(shownMs), op_ms: round(t.oversketch?.finish_ms.at(-1) ?? null) };
      if (shownMs === null) console.error('the over-sketch was not applied (no new op within 10 s)');
    } else {
      console.error('no lit model found in the over-sketch view');
    }
    console.error(`over-sketch: ${JSON.stringify(oversketch)}`);
  }

  // Laplacian mesh optimization of the Stanford bunny (SKETCHMESH_OPTIMIZE_FIXTURE, from the
  // shared test data): a tap opens the preview (weights, system, factorization, solve: one
  // step), `[` moves the amount (conjugate-gradient steps on the kept factorization), Enter
  // applies (the exact refactorization at the new amount). Timed by the app per step.
  let optimize = null;
  const scanPath = process.env.SKETCHMESH_OPTIMIZE_FIXTURE;
  if (scanPath && existsSync(scanPath)) {
    const vertices = await page.evaluate(async (data) => {
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(new Uint8Array(data), 'bunny.glb');
      window.sketchmesh.timings();
      return window.sketchmesh.stats().vertices;
    }, [...readFileSync(scanPath)]);
    await sleep(500);
    // loadGlb frames what it imports, as a dropped file is; 'f' frames again (harmless), 'm' picks Move.
    await page.keyboard.press('f');
    await page.keyboard.press('m');
    await sleep(300);
    const canvas = await page.evaluate(() => {
      const r = document.querySelector('canvas').getBoundingClientRect();
      return { x: r.left + r.width / 2, y: r.top + (r.height + 80) / 2 + 20 };
    });
    const pen = { pointerType: 'pen', button: 'left', force: 0.5 };
    for (const type of ['mousePressed', 'mouseReleased']) {
      await cdp.send('Input.dispatchMouseEvent', { type, ...canvas, buttons: type === 'mousePressed' ? 1 : 0, clickCount: 1, ...pen });
    }
    await sleep(300);
    await screenshot(page, join(OUT_DIR, 'bench-optimize-preview.png'));
    // The app's timings, gathered (each read takes them): its begin and first frame, its
    // frames' own work, and the previews the page's worker computed (weights, factor, solve
    // for the first; the kept optimizer for the slider's steps).
    const timed = { begin_ms: [], frame_ms: [], preview_ms: [] };
    const gather = async () => {
      const o = (await api(page, 'timings')).optimize ?? {};
      for (const [key, list] of Object.entries(timed)) list.push(...(o[key] ?? []));
      return timed;
    };
    for (let waited = 0; waited < 30_000 && timed.preview_ms.length === 0; waited += 200) {
      await sleep(200);
      await gather();
    }
    const firstPreview = timed.preview_ms[0] ?? null;
    await page.keyboard.press('[');
    await page.keyboard.press('[');
    await sleep(4000);
    await gather();
    const applied = Date.now();
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'optimize', null, { timeout: 30_000, polling: 50 })
      .catch(() => {});
    const t = await api(page, 'timings');
    optimize = {
      vertices,
      first_ms: round(timed.begin_ms.at(-1) ?? null),
      first_preview_ms: round(firstPreview),
      step_ms: distribution(timed.frame_ms),
      preview_ms: distribution(timed.preview_ms.slice(1)),
      apply_ms: round(t.optimize?.finish_ms.at(-1) ?? null),
      apply_worker_ms: round(t.optimize?.elsewhere_ms?.at(-1) ?? null),
      apply_wall_ms: Date.now() - applied,
    };
    console.error(`optimize: ${JSON.stringify(optimize)}`);
  } else {
    console.error(`WARNING: ${scanPath} is missing (the shared test data); the optimize timing is skipped`);
  }

  /**
   * A new document with the bunny scan, framed, and the tool of `key`: the middle of the view
   * (a little below centre, where the bunny's body is), in page px.
   */
  const bunnyWith = async (key) => {
    await page.evaluate(async (data) => {
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(new Uint8Array(data), 'bunny.glb');
      window.sketchmesh.timings();
    }, [...readFileSync(scanPath)]);
    await sleep(500);
    await page.keyboard.press('f');
    await page.keyboard.press(key);
    await sleep(300);
    return page.evaluate(() => {
      const r = document.querySelector('canvas').getBoundingClientRect();
      return { x: r.left + r.width / 2, y: r.top + (r.height + 80) / 2 + 20 };
    });
  };
  /** A loop around most of the framed bunny as seen, about `c`. */
  const aroundBunny = (c) => Array.from({ length: 61 }, (_, i) => {
    const a = (2 * Math.PI * i) / 60;
    return { x: c.x + 260 * Math.cos(a), y: c.y + 220 * Math.sin(a), force: 0.5 };
  });
  /** A stroke across the framed bunny's body through `c`. */
  const acrossBunny = (c) => Array.from({ length: 31 }, (_, i) => ({ x: c.x - 90 + 6 * i, y: c.y, force: 0.5 }));
  /**
   * A 60 px pen drag up from `grab` in 40 steps, the page's animation frames recorded while
   * it moves and a screenshot before the release; the frames' times.
   */
  const timedDrag = async (grab, shot, path = (i) => ({ x: grab.x, y: grab.y - 1.5 * i })) => {
    const pen = { pointerType: 'pen', button: 'left', force: 0.5 };
    await page.evaluate(() => { window.__bench.frames = []; window.__bench.recording = true; });
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', ...grab, buttons: 1, clickCount: 1, ...pen });
    for (let i = 1; i <= 40; i++) {
      await sleep(16);
      await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', ...path(i), buttons: 1, ...pen });
    }
    await sleep(100);
    const frames = await page.evaluate(() => { window.__bench.recording = false; return window.__bench.frames; });
    await screenshot(page, join(OUT_DIR, shot));
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', ...path(40), buttons: 0, clickCount: 1, ...pen });
    return frames;
  };
  /** What a timed drag of an `op` edit cost: its first step, later steps, frames, release. */
  const dragReport = async (op, frames) => {
    const t = (await api(page, 'timings'))[op];
    const drag = frames.slice(1).map((f, i) => f - frames[i]);
    // The first frames of the drag carry the setup; the rest are the drag proper.
    const later = drag.slice(3).sort((a, b) => a - b);
    const steps = [...(t?.frame_ms ?? [])].sort((a, b) => a - b);
    return {
      committed: JSON.parse(await api(page, 'session')).ops.at(-1)?.op === op,
      first_ms: round(t?.begin_ms.at(-1) ?? null),
      step_ms: { n: steps.length, p50: round(steps[Math.floor(steps.length / 2)] ?? null), max: round(steps.at(-1) ?? null) },
      drag_frame_ms: { n: later.length, p50: round(later[Math.floor(later.length / 2)] ?? null), max: round(later.at(-1) ?? null) },
      apply_ms: round(t?.finish_ms.at(-1) ?? null),
      // Previews computed by the page's worker (asked to shown), and commits computed there.
      preview_ms: distribution(t?.preview_ms ?? []),
      worker_ms: round(t?.elsewhere_ms?.at(-1) ?? null),
    };
  };

  // Feature sketching on the same scan: a lasso around most of the bunny as seen (its front
  // half is the region), a sketch across it, then a pen drag that raises a bump. The first
  // drag step places and embeds the sketch and factors the region; every later one re-weighs
  // the kept solutions. Frame times come from the page's animation frames while dragging.
  let feature = null;
  if (scanPath && existsSync(scanPath)) {
    const c = await bunnyWith('d');
    // The toolbar's second row, drawn by egui on the canvas: the Bump button.
    await page.mouse.click(96, 59);
    await penStroke(cdp, aroundBunny(c), 8);
    await penStroke(cdp, acrossBunny(c), 8);
    await sleep(200);
    const frames = await timedDrag({ x: c.x, y: c.y + 150 }, 'bench-feature-drag.png');
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'sketch_feature', null, { timeout: 30_000, polling: 50 })
      .catch(() => {});
    feature = await dragReport('sketch_feature', frames);
    console.error(`feature: ${JSON.stringify(feature)}`);
  }

  // Region editing on the same scan: a reference curve across the bunny's middle, a boundary
  // around most of it as seen, then a pen drag that lifts the region. The first drag step
  // places the curves and weighs the region; every later one moves it by the new transform.
  let region = null;
  if (scanPath && existsSync(scanPath)) {
    const c = await bunnyWith('l');
    await penStroke(cdp, acrossBunny(c), 8);
    await penStroke(cdp, aroundBunny(c), 8);
    await sleep(200);
    const frames = await timedDrag({ x: c.x, y: c.y + 150 }, 'bench-region-drag.png');
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'region_edit', null, { timeout: 30_000, polling: 50 })
      .catch(() => {});
    region = await dragReport('region_edit', frames);
    console.error(`region: ${JSON.stringify(region)}`);
  }

  // Curve handles (Blanco) on the 500,002-vertex bar (SKETCHMESH_BEND_FIXTURE): a stroke
  // along it makes a handle over all of it (place: its op), then a pen drag on its last dot
  // bends it. The first drag step binds every vertex to its slab; every later one rebuilds
  // every vertex from new frames.
  let bend = null;
  const barPath = process.env.SKETCHMESH_BEND_FIXTURE;
  if (barPath && existsSync(barPath)) {
    // 24 MB, handed over as base64 text (as an array of numbers it exhausts Node's heap).
    await page.evaluate(async (base64) => {
      const text = atob(base64);
      const data = new Uint8Array(text.length);
      for (let i = 0; i < text.length; i++) data[i] = text.charCodeAt(i);
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(data, 'bar.glb');
      window.sketchmesh.timings();
    }, readFileSync(barPath).toString('base64'));
    await sleep(1000);
    await page.keyboard.press('f');
    await page.keyboard.press('j');
    await sleep(300);
    const r = await page.evaluate(() => {
      const b = document.querySelector('canvas').getBoundingClientRect();
      return { left: b.left, width: b.width, y: b.top + (b.height + 80) / 2 + 20 };
    });
    const from = { x: r.left + 0.35 * r.width, y: r.y };
    const to = { x: r.left + 0.65 * r.width, y: r.y };
    await penStroke(cdp, Array.from({ length: 41 }, (_, i) => ({ x: from.x + ((to.x - from.x) * i) / 40, y: r.y, force: 0.5 })), 8);
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'curve_handle', null, { timeout: 30_000, polling: 50 })
      .catch(() => {});
    const placed = (await api(page, 'timings')).curve_handle;
    const frames = await timedDrag(to, 'bench-bend-drag.png');
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'handle_edit', null, { timeout: 60_000, polling: 50 })
      .catch(() => {});
    bend = { vertices: (await api(page, 'stats')).vertices, place_ms: round(placed?.finish_ms.at(-1) ?? null), ...(await dragReport('handle_edit', frames)) };
    console.error(`bend: ${JSON.stringify(bend)}`);
  } else {
    console.error(`WARNING: the bend fixture (${barPath}) is missing; the bend timing is skipped`);
  }

  // The pose tool (volumetric graph Laplacian) on a capsule of 5,252 vertices, 28.6k graph
  // points (SKETCHMESH_POSE_FIXTURE): a stroke along it picks the control curve and turns the
  // view to its plane; the new curve, drawn left to right and bending up, is the timed drag
  // (its first steps get the graph and factor; every later one back-substitutes).
  let pose = null;
  const capsulePath = process.env.SKETCHMESH_POSE_FIXTURE;
  if (capsulePath && existsSync(capsulePath)) {
    await page.evaluate(async (bytes) => {
      await window.sketchmesh.replay(JSON.stringify({ format: 'sketchmesh-session', version: 1, ops: [] }));
      await window.sketchmesh.loadGlb(new Uint8Array(bytes), 'capsule.glb');
      window.sketchmesh.timings();
    }, [...readFileSync(capsulePath)]);
    await sleep(1000);
    await page.keyboard.press('f');
    await page.keyboard.press('q');
    await sleep(300);
    const r = await page.evaluate(() => {
      const b = document.querySelector('canvas').getBoundingClientRect();
      return { left: b.left, width: b.width, y: b.top + (b.height + 80) / 2 + 20 };
    });
    const from = { x: r.left + 0.3 * r.width, y: r.y };
    const to = { x: r.left + 0.7 * r.width, y: r.y };
    await penStroke(cdp, Array.from({ length: 41 }, (_, i) => ({ x: from.x + ((to.x - from.x) * i) / 40, y: r.y, force: 0.5 })), 8);
    await sleep(800);
    const width = to.x - from.x;
    const frames = await timedDrag(from, 'bench-pose-drag.png', (i) => ({ x: from.x + (width * i) / 40, y: r.y - 40 - Math.max(0, i - 20) * 4 }));
    await page.waitForFunction(() => JSON.parse(window.sketchmesh.session()).ops.at(-1)?.op === 'curve_deform', null, { timeout: 60_000, polling: 50 })
      .catch(() => {});
    pose = { vertices: (await api(page, 'stats')).vertices, ...(await dragReport('curve_deform', frames)) };
    console.error(`pose: ${JSON.stringify(pose)}`);
  } else {
    console.error(`WARNING: the pose fixture (${capsulePath}) is missing; the pose timing is skipped`);
  }

  const autosave = await autosaveBench();
  console.error(`autosave: ${JSON.stringify(autosave)}`);
  const gizmo = await gizmoBench();
  console.error(`gizmo: ${JSON.stringify(gizmo)}`);

  const deltas = timing.frames.slice(1).map((t, i) => t - timing.frames[i]);
  const sorted = [...deltas].sort((a, b) => a - b);
  const quantile = (q) => (sorted.length ? sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))] : null);
  const mean = deltas.length ? deltas.reduce((a, b) => a + b, 0) / deltas.length : null;
  const report = {
    url,
    gpu,
    backend,
    api_ready_ms: round(timing.apiAt),
    time_to_interactive_ms: round(timing.interactiveAt),
    stroke: {
      points: points.length,
      wall_ms: strokeMs,
      frames: timing.frames.length,
      curves_after: stats.curves,
      frame_ms: { mean: round(mean), p50: round(quantile(0.5)), p95: round(quantile(0.95)), max: round(sorted.at(-1)) },
    },
    import_glb: { triangles: imported.triangles, bytes: imported.bytes, ms: round(imported.ms), returned_ms: round(imported.returnedMs) },
    pulls,
    oversketch,
    optimize,
    feature,
    region,
    bend,
    pose,
    autosave,
    gizmo,
  };
  console.log(JSON.stringify(report));
} finally {
  await browser.close();
}
