import { launch, openApp, penStroke, frames, api, camera, line, sleep, screenshot } from './lib.mjs';
const url = 'http://127.0.0.1:8080/';
const browser = await launch('webgl2');
const { page, cdp, errors } = await openApp(browser, url, 'webgl2', { width: 1280, height: 720 });
const c = { x: 640, y: 400 };
const ellipse = Array.from({ length: 80 }, (_, k) => ({ x: c.x + 170 * Math.cos(k / 79 * 2 * Math.PI), y: c.y + 120 * Math.sin(k / 79 * 2 * Math.PI) }));
await penStroke(cdp, ellipse.map((p) => ({ ...p, force: 0.5 })));
await sleep(3000);
await page.keyboard.press('q');
await frames(page, 3);
await penStroke(cdp, line({ x: c.x - 130, y: c.y }, { x: c.x + 130, y: c.y }, 40).map((p) => ({ ...p, force: 0.5 })));
await sleep(1500);
await page.mouse.click(704, 59);
await frames(page, 4);
const shot = await screenshot(page, 'tests/out/look-spline.png');
// yellow control points
const yellow = [];
for (let y = 90; y < shot.height; y++) for (let x = 0; x < shot.width; x++) {
  const i = 4 * (y * shot.width + x);
  const [r, g, b] = [shot.data[i], shot.data[i + 1], shot.data[i + 2]];
  if (r > 230 && g > 190 && g < 230 && b < 110) yellow.push({ x, y });
}
console.log('yellow px', yellow.length, yellow.length && Math.max(...yellow.map((p) => p.x)));
const right = yellow.reduce((a, p) => (p.x > a.x ? p : a), { x: -1, y: 0 });
const grab = { x: right.x - 6, y: right.y };
const drag = line(grab, { x: grab.x, y: grab.y - 120 }, 30).map((p) => ({ ...p, force: 0.5 }));
await penStroke(cdp, drag);
await sleep(2000);
await frames(page, 3);
await screenshot(page, 'tests/out/look-spline-dragged.png');
const session = await api(page, 'session');
console.log(JSON.stringify(JSON.parse(session).ops.slice(-1)[0]).slice(0, 300));
// backdrop
const png = await page.evaluate(() => { const c = document.createElement('canvas'); c.width = 64; c.height = 48; const g = c.getContext('2d'); g.fillStyle = '#ff00ff'; g.fillRect(0, 0, 64, 48); return c.toDataURL('image/png').split(',')[1]; });
await page.mouse.click(822, 59);
await frames(page, 3);
await screenshot(page, 'tests/out/look-menu.png');
const chooser = page.waitForEvent('filechooser', { timeout: 5000 }).catch((e) => null);
await page.mouse.click(848, 117);
await frames(page, 3);
await screenshot(page, 'tests/out/look-after-click.png');
const fc = await chooser;
console.log('chooser', !!fc);
if (!fc) { await browser.close(); process.exit(0); }
await fc.setFiles({ name: 'frame.png', mimeType: 'image/png', buffer: Buffer.from(png, 'base64') });
await sleep(1500);
await frames(page, 3);
await screenshot(page, 'tests/out/look-backdrop.png');
console.log(errors);
await browser.close();
