// Temporary look at the pose tool (not part of the suite).
import { launch, openApp, penStroke, screenshot, frames, api, camera, line, sleep } from './lib.mjs';
const url = 'http://127.0.0.1:8080/';
const browser = await launch('webgl2');
const app = await openApp(browser, url, 'webgl2', { width: 1280, height: 720 });
const c = { x: 640, y: 400 };
const ellipse = Array.from({ length: 61 }, (_, i) => {
  const a = (2 * Math.PI * i) / 60;
  return { x: c.x + 260 * Math.cos(a), y: c.y + 70 * Math.sin(a), force: 0.6 };
});
await penStroke(app.cdp, ellipse);
await sleep(3000);
await frames(app.page, 3);
await screenshot(app.page, '/tmp/pose-0.png');
await app.page.keyboard.press('q');
await frames(app.page, 3);
await screenshot(app.page, '/tmp/pose-1.png');
await penStroke(app.cdp, line({ x: c.x - 220, y: c.y }, { x: c.x + 220, y: c.y }, 40).map((p) => ({ ...p, force: 0.5 })));
await sleep(1500);
await frames(app.page, 3);
console.log('camera', JSON.stringify(await camera(app.page)));
await screenshot(app.page, '/tmp/pose-2.png');
const bent = Array.from({ length: 41 }, (_, k) => {
  const s = k / 40;
  return { x: c.x - 220 + 440 * s, y: c.y - Math.max(0, s - 0.5) * 300, force: 0.5 };
});
await penStroke(app.cdp, bent);
await sleep(2500);
await frames(app.page, 3);
await screenshot(app.page, '/tmp/pose-3.png');
const session = await api(app.page, 'session');
console.log(String(session).slice(-400));
console.log(JSON.stringify(await api(app.page, 'notes')));
await browser.close();
