// Scratch driver: the touch layout in each tool on a phone (DPR 3), screenshots to /tmp/look.
import { api, frames, launch, openApp, screenshot, sleep, touchGesture } from './lib.mjs';
const url = process.env.SKETCHMESH_URL;
const browser = await launch('webgl2', { deviceScaleFactor: 3 });
const phone = await openApp(browser, url, 'webgl2', { width: 390, height: 844, deviceScaleFactor: 3 });
const c = { x: 195, y: 400 };
const outline = Array.from({ length: 13 }, (_, i) => { const a = (2 * Math.PI * i) / 12; return { x: c.x + 120 * Math.cos(a), y: c.y + 90 * Math.sin(a) }; });
await touchGesture(phone.cdp, [outline], 16);
await sleep(2000);
for (const key of ['q', 'm', 'd', 'l', 'o']) {
  await phone.page.keyboard.press(key);
  await frames(phone.page, 3);
  await screenshot(phone.page, `/tmp/look/phone-${key}.png`);
}
console.log(JSON.stringify(await api(phone.page, 'stats')), phone.errors);
await browser.close();
