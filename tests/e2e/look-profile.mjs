// Scratch driver: the region tool's profile panel, screenshots to /tmp/look.
import { api, frames, launch, line, openApp, penStroke, screenshot, sleep } from './lib.mjs';
const url = process.env.SKETCHMESH_URL;
const browser = await launch('webgl2');
const fresh = await openApp(browser, url, 'webgl2');
const c = { x: 640, y: 400 };
const ellipse = Array.from({ length: 61 }, (_, i) => { const a = 2 * Math.PI * i / 60; return { x: c.x + 170 * Math.cos(a), y: c.y + 120 * Math.sin(a), force: 0.6 }; });
await penStroke(fresh.cdp, ellipse);
await sleep(3000);
await fresh.page.keyboard.press('l');
await frames(fresh.page, 3);
await screenshot(fresh.page, '/tmp/look/p0.png');
const [bx, by] = (process.env.PROFILE_AT ?? '0,0').split(',').map(Number);
if (bx) { await fresh.page.mouse.click(bx, by); await frames(fresh.page, 3); }
await penStroke(fresh.cdp, line({ x: c.x, y: c.y - 90 }, { x: c.x, y: c.y + 90 }, 30).map((p) => ({ ...p, force: 0.5 })));
const loop = Array.from({ length: 49 }, (_, i) => { const a = (2 * Math.PI * i) / 48; return { x: c.x + 110 * Math.cos(a), y: c.y + 105 * Math.sin(a), force: 0.5 }; });
await penStroke(fresh.cdp, loop);
await frames(fresh.page, 5);
await screenshot(fresh.page, '/tmp/look/p1.png');
const stroke = (process.env.STROKE ?? '').split(';').filter(Boolean).map((s) => s.split(',').map(Number));
if (stroke.length) {
  const [x0, y0, x1, y1, h] = stroke[0];
  const pts = Array.from({ length: 25 }, (_, i) => { const t = i / 24; return { x: x0 + (x1 - x0) * t, y: y0 + (y1 - y0) * t - h * Math.sin(Math.PI * t), force: 0.5 }; });
  await penStroke(fresh.cdp, pts);
  await sleep(800);
  await frames(fresh.page, 5);
  await screenshot(fresh.page, '/tmp/look/p2.png');
  await fresh.page.keyboard.press('Enter');
  await sleep(1500);
  await frames(fresh.page, 4);
  await screenshot(fresh.page, '/tmp/look/p3.png');
  const session = JSON.parse(await api(fresh.page, 'session'));
  console.log(JSON.stringify(session.ops.at(-1)).slice(0, 200), JSON.stringify(session.ops.at(-1).profile).slice(0, 300));
}
await browser.close();
