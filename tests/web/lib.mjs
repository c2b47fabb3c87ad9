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
  YAW: 14, DEVICE: 15, SOUNDS: 16, OUTSIDE: 17, ARROW_YAW: 18, COLS: 19, ROWS: 20, CELL: 21,
  WALK: 22, HANDS: 23, BODY: 24, ASK: 25 };

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
// Meta's WebXR Layers polyfill (npm's webxr-layers-polyfill: XRWebGLBinding
// with createQuadLayer and getSubImage, the layers drawn into the session's
// WebGL layer), as a Quest Browser's layers stand-in on iwer
const layersSource = fs.readFileSync(path.join(here,
  'node_modules/webxr-layers-polyfill/build/webxr-layers-polyfill.js'), 'utf8');

// A page in its own browser context (its own IndexedDB), loaded and
// playing. Collects the console, page errors and failed requests. layers
// (with iwer): the Quest 3 grants the 'layers' feature, as the Quest
// Browser does, and the layers polyfill gives the page its XRWebGLBinding.
export async function openPage(browser, url, { iwer = false, gamepad = false, touch = false,
  fail = false, bounds = null, syncCount = false, layers = false } = {}) {
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
  if (iwer && !layers)
    await page.evaluateOnNewDocument(iwerSource + `;
      window.xrDevice = new IWER.XRDevice(IWER.metaQuest3, { stereoEnabled: true });
      xrDevice.installRuntime({ forceInstall: true });`);
  if (iwer && layers)
    await page.evaluateOnNewDocument(iwerSource + `;
      window.xrDevice = new IWER.XRDevice(Object.assign({}, IWER.metaQuest3,
        { supportedFeatures: IWER.metaQuest3.supportedFeatures.concat(['layers']) }), { stereoEnabled: true });
      xrDevice.installRuntime({ forceInstall: true });
      ` + layersSource + `;
      new WebXRLayersPolyfill();`);
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

// CPU seconds of a process and its descendants (/proc; chromium's browser
// process: its renderers, the GPU process where SwiftShader draws).
export function processTreeCpu(root) {
  const procs = new Map();
  for (const d of fs.readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const st = fs.readFileSync(`/proc/${d}/stat`, 'utf8');
      const f = st.slice(st.lastIndexOf(')') + 2).split(' ');
      procs.set(+d, { ppid: +f[1], cpu: (+f[11] + +f[12]) / 100 }); /* USER_HZ */
    } catch (e) { /* gone */ }
  }
  let total = 0;
  for (const [pid, k] of procs)
    for (let p = pid, n = 0; p > 1 && n < 64; n++, p = procs.get(p)?.ppid)
      if (p === root) { total += k.cpu; break; }
  return total;
}

// The first frame (docs/performance.md, "The web's first frame"): from the
// navigation's start to the end of the animation frame in which the app
// drew its first frame on the canvas, the page's User Timing mark
// holonomy-first-frame (performance.now() is time since the navigation
// began). The phases end at the marks the page sets: the store is open
// (holonomy-store) and the wasm compiled (holonomy-wasm) in parallel, then
// main begins (holonomy-main), the GL context (holonomy-gl), the game
// (holonomy-game: the session, the app, the navigator's table, the world,
// the level), the renderer (holonomy-renderer: buffers, the day shader),
// the first frame (holonomy-first-frame).
export const FIRST_FRAME_PHASES = ['main', 'gl', 'game', 'renderer', 'first-frame'];

// One load of url in a new tab of the browser's default context (a new
// context would open a window, and with it chromium's omnibox WebUI, about
// 0.7 s of CPU beside the page), the origin's storage cleared first (a
// first visit: no logs, nothing cached). Returns { at: mark -> ms since the
// navigation began, wasmFetch: the wasm's request to its last byte (ms),
// chromium: CPU ms of all chromium's processes from the navigation to the
// first frame (/proc), and with trace (chromium traces its tasks, which
// costs CPU and wall time itself) cpu: phase -> { main: the page's main
// thread, gpu: the GPU process's main thread (GL calls, SwiftShader), all:
// every chromium thread } in ms of thread time (CPU: the other helpers'
// load does not count) }.
export async function firstFrameLoad(browser, url, { trace = false } = {}) {
  const page = await browser.newPage();
  try {
    const cdp = await page.createCDPSession();
    await cdp.send('Storage.clearDataForOrigin', { origin: new URL(url).origin, storageTypes: 'all' });
    await sleep(300); /* the last tab's teardown */
    const c0 = processTreeCpu(browser.process().pid);
    /* the CPU from here to the first frame is mostly the load's */
    if (trace) await page.tracing.start({ categories: ['__metadata', 'toplevel', 'blink.user_timing'] });
    await page.goto(url);
    await page.waitForFunction(() => performance.getEntriesByName('holonomy-first-frame').length ||
      /^Failed/.test(document.getElementById('status').textContent), { timeout: 120000, polling: 50 });
    const chromium = (processTreeCpu(browser.process().pid) - c0) * 1000;
    const r = await page.evaluate(() => {
      const at = {};
      for (const m of performance.getEntriesByType('mark')) if (/^holonomy-/.test(m.name)) at[m.name.slice(9)] = m.startTime;
      const w = performance.getEntriesByType('resource').find((e) => /holonomy\.wasm$/.test(e.name));
      return { at, wasmFetch: w ? w.responseEnd - w.startTime : NaN, status: document.getElementById('status').textContent };
    });
    const t = trace ? JSON.parse(Buffer.from(await page.tracing.stop()).toString('utf8')) : null;
    if (!r.at['first-frame']) throw new Error(url + ': ' + r.status);
    return { ...r, cpu: t && traceCpu(t.traceEvents || t, r.at), chromium };
  } finally {
    await page.close();
  }
}

// Per phase, the CPU (trace thread time) of the page's main thread, of the
// GPU process's main thread and of all chromium's threads; a task that
// spans a phase's end is split in proportion to its wall time, but for the
// page's main thread after main begins, where the marks carry the thread's
// clock (main runs the GL context, the game and the renderer in one task).
function traceCpu(ev, at) {
  const marks = new Map(ev.filter((e) => /^holonomy-/.test(e.name || '') && e.ph !== 'X').map((e) => [e.name.slice(9), e]));
  const main = marks.get('main');
  const t0 = main.ts - at.main * 1000; /* the navigation's start on the trace's clock */
  const gpuPid = ev.find((e) => e.ph === 'M' && e.name === 'process_name' && e.args.name === 'GPU Process')?.pid;
  const gpuTid = ev.find((e) => e.ph === 'M' && e.name === 'thread_name' && e.pid === gpuPid && e.args.name === 'CrGpuMain')?.tid;
  const bounds = [t0, ...FIRST_FRAME_PHASES.map((p) => marks.get(p).ts)];
  const out = Object.fromEntries(FIRST_FRAME_PHASES.map((p) => [p, { main: 0, gpu: 0, all: 0 }]));
  for (const e of ev) {
    if (e.ph !== 'X' || e.tdur === undefined || !/^(ThreadControllerImpl::RunTask|ThreadPool_RunTask)$/.test(e.name) || !e.dur)
      continue;
    for (let k = 0; k < FIRST_FRAME_PHASES.length; k++) {
      const ov = Math.min(e.ts + e.dur, bounds[k + 1]) - Math.max(e.ts, bounds[k]);
      if (ov <= 0) continue;
      const ms = e.tdur / 1000 * ov / e.dur, o = out[FIRST_FRAME_PHASES[k]];
      if (e.pid === main.pid && e.tid === main.tid) {
        if (k === 0) o.main += ms;
        continue;
      }
      o.all += ms;
      if (e.pid === gpuPid && e.tid === gpuTid) o.gpu += ms;
    }
  }
  for (let k = 1; k < FIRST_FRAME_PHASES.length; k++) /* the marks' thread clock */
    out[FIRST_FRAME_PHASES[k]].main = (marks.get(FIRST_FRAME_PHASES[k]).tts - marks.get(FIRST_FRAME_PHASES[k - 1]).tts) / 1000;
  for (const p of FIRST_FRAME_PHASES) out[p].all += out[p].main;
  return out;
}

export const median = (a) => a.slice().sort((x, y) => x - y)[a.length >> 1];

// The medians of loads (firstFrameLoad's: wall figures) and of traced
// loads (CPU figures), as lines of text.
export function firstFrameReport(loads, traced, indent = '  ') {
  const f = (x) => Math.round(x);
  const med = (ls, fn) => f(median(ls.map(fn)));
  const lines = [`${indent}first frame ${med(loads, (l) => l.at['first-frame'])} ms after the navigation began ` +
    `(median of ${loads.length} loads: ${loads.map((l) => f(l.at['first-frame'])).join(', ')})`];
  const names = { main: 'before main (the page, the store, the wasm)', gl: 'the GL context', game: 'the game',
    renderer: 'the renderer', 'first-frame': 'the first frame itself' };
  FIRST_FRAME_PHASES.forEach((p, k) => {
    const wall = med(loads, (l) => l.at[p] - (k ? l.at[FIRST_FRAME_PHASES[k - 1]] : 0));
    lines.push(`${indent}  ${names[p].padEnd(43)} wall ${String(wall).padStart(5)} ms` + (traced.length
      ? `; CPU (traced): page main thread ${String(med(traced, (l) => l.cpu[p].main)).padStart(4)}, ` +
        `GPU process ${String(med(traced, (l) => l.cpu[p].gpu)).padStart(4)}, all chromium ${String(med(traced, (l) => l.cpu[p].all)).padStart(5)} ms`
      : ''));
  });
  lines.push(`${indent}  (the store open at ${med(loads, (l) => l.at.store)} ms, the wasm compiled at ` +
    `${med(loads, (l) => l.at.wasm ?? NaN)} ms, its download ${med(loads, (l) => l.wasmFetch)} ms; ` +
    `all chromium's processes ${med(loads, (l) => l.chromium)} ms CPU a load (/proc)` +
    (traced.length ? `, traced ${med(traced, (l) => l.at['first-frame'])} ms to the first frame)` : ')'));
  return lines;
}
