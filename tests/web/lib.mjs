// lib.mjs - what the web tests and the web bench share: a static server on
// 127.0.0.1 for build/web (and /test/ for a run's own files), headless
// chromium on SwiftShader WebGL 2, pages in their own browser contexts with
// their console collected, iwer's Quest 3 or a gamepad shim installed, and
// reads of the page's game state and log store.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// hol_web_state's questions (platform/web/hol_web_main.c)
export const S = { FRAMES: 0, XR_FRAMES: 1, XR_TWO_VIEWS: 2, XR_FOCUSED: 3, APP_STATE: 4,
  PAUSED: 5, STEPS: 6, OVER: 7, FAILED: 8, HEAD_X: 9, HEAD_Z: 10, COL: 11, ROW: 12, CLOCK: 13,
  YAW: 14, DEVICE: 15, SOUNDS: 16 };

const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
  '.mjs': 'text/javascript', '.txt': 'text/plain', '.lvl': 'text/plain' };

export async function serve(web, testDir) {
  const server = http.createServer((req, res) => {
    const p = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    let f = p.startsWith('/test/') ? path.join(testDir, p.slice(6)) : path.join(web, p);
    if (f.endsWith('/')) f += 'index.html';
    if (!f.startsWith(web) && !f.startsWith(testDir)) { res.writeHead(403); res.end(); return; }
    fs.readFile(f, (err, data) => {
      if (err) { res.writeHead(404); res.end(); return; }
      res.writeHead(200, { 'Content-Type': types[path.extname(f)] || 'application/octet-stream' });
      res.end(data);
    });
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  return { base: `http://127.0.0.1:${server.address().port}`, close: () => server.close() };
}

// Headless chromium with SwiftShader's WebGL 2, a fresh profile in dir.
export function launch(chromium, dir, w, h) {
  return puppeteer.launch({
    executablePath: chromium,
    headless: true,
    userDataDir: dir,
    defaultViewport: { width: w, height: h },
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--no-first-run', '--no-default-browser-check', '--disable-default-apps', '--mute-audio',
      // a name for 127.0.0.1 that is not localhost: the page as a LAN
      // address serves it (http://, not a secure context: no WebXR)
      '--host-resolver-rules=MAP lan.holonomy.test 127.0.0.1',
      `--window-size=${w},${h}`],
  });
}

const iwerSource = fs.readFileSync(path.join(here, 'node_modules/iwer/build/iwer.min.js'), 'utf8');

// A page in its own browser context (its own IndexedDB), loaded and
// playing. Collects the console, page errors and failed requests.
export async function openPage(browser, url, { iwer = false, gamepad = false, touch = false,
  fail = false, bounds = null, syncCount = false } = {}) {
  const ctx = await browser.createBrowserContext();
  const page = await ctx.newPage();
  if (touch) {
    const v = page.viewport();
    await page.setViewport({ width: v.width, height: v.height, hasTouch: true });
  }
  const cdp = await page.createCDPSession();
  await cdp.send('Emulation.setFocusEmulationEnabled', { enabled: true });
  const log = [], errors = [];
  page.on('console', (m) => {
    log.push(m.text());
    if (m.type() === 'error') errors.push('console: ' + m.text());
  });
  page.on('pageerror', (e) => errors.push('page: ' + e.message));
  page.on('requestfailed', (r) => errors.push('request: ' + r.url() + ' ' + r.failure().errorText));
  page.on('response', (r) => { if (r.status() >= 400) errors.push(`response: ${r.status()} ${r.url()}`); });
  if (iwer)
    await page.evaluateOnNewDocument(iwerSource + `;
      window.xrDevice = new IWER.XRDevice(IWER.metaQuest3, { stereoEnabled: true });
      xrDevice.installRuntime({ forceInstall: true });`);
  // iwer 2.5 gives bounded-floor no boundsGeometry (its own TO-DO): a shim
  // with the polygon (x, z pairs, metres) the test names
  if (iwer && bounds)
    await page.evaluateOnNewDocument((b) => {
      Object.defineProperty(XRReferenceSpace.prototype, 'boundsGeometry', {
        configurable: true, get() { return b.map(([x, z]) => ({ x, y: 0, z, w: 1 })); } });
    }, bounds);
  // The calls that wait for the GPU (getError, finish, readPixels, every
  // get*: a synchronous round trip to the GPU process) made by the page's
  // code (holonomy.js and its wasm, page.js; not iwer's emulation), counted
  // by name in window.__sync from when __sync.on is set.
  if (syncCount)
    await page.evaluateOnNewDocument(() => {
      const sync = window.__sync = { on: false, n: 0, names: {} };
      const P = WebGL2RenderingContext.prototype;
      for (const k of Object.getOwnPropertyNames(P)) {
        if (!/^(get|finish$|readPixels$)/.test(k)) continue;
        const d = Object.getOwnPropertyDescriptor(P, k);
        if (typeof d.value !== 'function') continue;
        const f = d.value;
        P[k] = function (...a) {
          if (sync.on && /holonomy\.js|page\.js|wasm/.test(new Error().stack)) {
            sync.n++;
            sync.names[k] = (sync.names[k] || 0) + 1;
          }
          return f.apply(this, a);
        };
      }
    });
  if (gamepad)
    await page.evaluateOnNewDocument(() => {
      window.__pad = { axes: [0, 0, 0, 0], buttons: new Array(17).fill(0) };
      navigator.getGamepads = () => [{
        id: 'holonomy test pad (standard)', index: 0, connected: true, mapping: 'standard',
        timestamp: performance.now(), axes: window.__pad.axes.slice(),
        buttons: window.__pad.buttons.map((v) => ({ pressed: v > 0.5, touched: v > 0.5, value: v })),
      }];
    });
  await page.goto(url);
  // playing (or, where a failure is expected, the page's one line about it)
  await page.waitForFunction((f) => (f ? /^Failed/ : /^Playing/)
    .test(document.getElementById('status').textContent), { timeout: 30000 }, fail);
  const state = (what) => page.evaluate((w) => Module._hol_web_state(w), what);
  const until = async (fn, what, ms = 20000) => {
    const end = Date.now() + ms;
    for (;;) {
      const v = await fn();
      if (v) return v;
      if (Date.now() > end) throw new Error('timed out waiting for ' + what);
      await sleep(40);
    }
  };
  return { ctx, page, log, errors, state, until };
}

// A stream of the page's store (the session's logs) as bytes; null if none.
export async function stored(page, name) {
  const b64 = await page.evaluate((n) => {
    const b = window.holonomyStore.bytes(n);
    if (!b) return null;
    let s = '';
    for (let i = 0; i < b.length; i += 32768) s += String.fromCharCode.apply(null, b.subarray(i, i + 32768));
    return btoa(s);
  }, name);
  return b64 === null ? null : Buffer.from(b64, 'base64');
}

// Enter VR with the page's button; resolves once the XR session runs.
export async function enterVR(p) {
  await p.page.waitForSelector('#vr:not([hidden])', { timeout: 10000 });
  await p.page.click('#vr');
  await p.until(() => p.page.evaluate(() => !!Module.holXR.session), 'the XR session');
}
