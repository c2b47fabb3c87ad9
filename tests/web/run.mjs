// run.mjs - make web-test: the web build (build/web) served on 127.0.0.1 and
// played in headless chromium (SwiftShader WebGL 2), driven through the
// DevTools protocol (puppeteer-core), with a Meta Quest 3 emulated by iwer
// for WebXR. Each check prints "ok - NAME" or "not ok - NAME: why"; the exit
// status is 1 when any failed. Artifacts (the eyes read back, the OSMesa
// references, the browser's logs and recording, screenshots) go to
// WEB_TEST_OUT (default: a temporary folder, removed unless a check failed).
//
// Environment: HOLONOMY (the desktop binary: replay, render), WEB (the
// build), CHROMIUM (default /usr/bin/chromium), WEB_TEST_OUT.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { spawnSync } from 'node:child_process';
import crypto from 'node:crypto';
import { S, enterVR, launch, openPage as openPage_, serve, sleep, stored } from './lib.mjs';
import { decodePNG, encodePNG } from './png.mjs';

const HOLONOMY = path.resolve(process.env.HOLONOMY || 'build/holonomy');
const WEB = path.resolve(process.env.WEB || 'build/web');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'holonomy-web-test-'));
const OUT = process.env.WEB_TEST_OUT ? path.resolve(process.env.WEB_TEST_OUT) : path.join(tmp, 'out');
fs.mkdirSync(OUT, { recursive: true });
const t0 = Date.now();

// ---- checks ----------------------------------------------------------------
let passed = 0, failed = 0;
// WEB_TEST_ONLY=REGEX: only the checks whose names match (the rest skipped)
const ONLY = process.env.WEB_TEST_ONLY ? new RegExp(process.env.WEB_TEST_ONLY) : null;
async function check(name, fn) {
  if (ONLY && !ONLY.test(name)) return;
  const t = Date.now();
  try {
    await fn();
    passed++;
    console.log(`ok - ${name} (${((Date.now() - t) / 1000).toFixed(1)} s)`);
  } catch (e) {
    failed++;
    console.log(`not ok - ${name}: ${e.message}`);
  }
}
function assert(c, msg) {
  if (!c) throw new Error(msg);
}

// ---- the server, the browser ------------------------------------------------
const testDir = path.join(tmp, 'serve');
fs.mkdirSync(testDir);
const server = await serve(WEB, testDir);
const W = 512, H = 384; /* the XR eyes 256x384: quick under SwiftShader */
const browser = await launch(CHROMIUM, path.join(tmp, 'profile'), W, H);
const openPage = (query, opts) => openPage_(browser, server.base + '/' + query, opts);

// the room steps the page reported ("web: step N D cell C,R")
function steps(log) {
  return log.map((l) => /^web: step (\d+) ([NESW]) cell (\d),(\d)/.exec(l)).filter(Boolean)
    .map((m) => ({ index: +m[1], dir: m[2], col: +m[3], row: +m[4] }));
}

// The data rows of attempt 1's step log (live while the attempt runs), as
// objects by column name.
async function stepRows(page) {
  const t = (await stored(page, 'steps-001.csv')) || (await stored(page, 'steps-001.csv.live'));
  if (!t) return [];
  const [head, ...rows] = t.toString('utf8').trim().split('\n');
  const cols = head.split(',');
  return rows.map((r) => Object.fromEntries(r.split(',').map((v, i) => [cols[i], v])));
}

// environment.csv (docs/research.md, Session metadata): its header, the
// desktop's (tests/cli_meta.sh), and its rows as objects by column name
// (RFC 4180: a quoted field may hold commas and doubled quotes).
const ENV_HEADER = 'session,participant,session_no,study_sha256,platform,os,runtime,gl_renderer,controller,refresh_hz,width,height,meta,options';
function csvRows(text) {
  const rows = [];
  let row = [], f = '', q = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (q) {
      if (c === '"' && text[i + 1] === '"') { f += '"'; i++; } else if (c === '"') q = false; else f += c;
    } else if (c === '"') q = true;
    else if (c === ',') { row.push(f); f = ''; }
    else if (c === '\n') { row.push(f); rows.push(row); row = []; f = ''; }
    else f += c;
  }
  return rows;
}
async function envRows(page) {
  const b = await stored(page, 'environment.csv');
  if (!b) return null;
  const text = b.toString('utf8'), [head, ...rows] = csvRows(text);
  assert(text.split('\n')[0] === ENV_HEADER, 'environment.csv header: ' + text.split('\n')[0]);
  assert(text.endsWith('\n') && rows.every((r) => r.length === head.length), 'environment.csv rows: ' + text);
  return rows.map((r) => Object.fromEntries(r.map((v, i) => [head[i], v])));
}
const sessionOf = (p) => /web: session (\S+),/.exec(p.log.find((l) => l.startsWith('web: session ')))[1];

// ---- the core in wasm ------------------------------------------------------
if (process.env.MATH_CHECK)
  await check('the core\'s sin, cos, atan2, asin, log, acosh give the native bits in wasm (tests/math_golden.h)', async () => {
    const r = spawnSync(process.execPath, [process.env.MATH_CHECK], { encoding: 'utf8' });
    assert(r.status === 0, (r.stdout + r.stderr).trim());
  });

// ---- the transfer size (issue 25) ------------------------------------------
// Every file of build/web (the page loads them all), each gzipped at level
// 9 as a server sends it: at most 180 KB in all, as issue 37 asks with the
// lessons and both languages (docs/web.md, "The transfer size"). A
// regression fails here, not in a bench.
const BUDGET = 180 * 1024; /* issue 37: 177.3 KB measured after its last cuts (docs/web.md) */
await check(`the transfer size: build/web's files gzip -9 at most ${BUDGET / 1024} KB in all`, async () => {
  const sizes = fs.readdirSync(WEB).map((f) => [f, zlib.gzipSync(fs.readFileSync(path.join(WEB, f)), { level: 9 }).length]);
  const total = sizes.reduce((a, [, n]) => a + n, 0);
  assert(sizes.some(([f]) => f === 'holonomy.wasm') && total <= BUDGET,
    `${(total / 1024).toFixed(1)} KB: ${sizes.map(([f, n]) => `${f} ${(n / 1024).toFixed(1)}`).join(', ')}`);
  console.log(`  ${(total / 1024).toFixed(1)} KB (${sizes.map(([f, n]) => `${f} ${(n / 1024).toFixed(1)}`).join(', ')})`);
});

// ---- pancake ---------------------------------------------------------------
let p1 = null; /* the pancake page, kept for the touch and reload checks */
await check('page loads with no console error on WebGL 2 with 8 stencil bits; held keys walk one room step north', async () => {
  /* explore, not the default tutorial: its lessons turn the look to what
   * they name, and the touch check below walks back along the look */
  const p = p1 = await openPage('?mode=explore&seed=3', { touch: true });
  const gl = p.log.find((l) => l.startsWith('web: WebGL 2 context'));
  assert(gl && / 8 stencil bits/.test(gl), 'no WebGL 2 context with 8 stencil bits: ' + gl);
  await p.page.screenshot({ path: path.join(OUT, 'pancake-start.png') });
  await p.until(async () => (await p.state(S.FRAMES)) > 10, 'frames');
  await p.page.keyboard.down('KeyW');
  await p.until(async () => (await p.state(S.STEPS)) >= 1, 'a room step');
  await p.page.keyboard.up('KeyW');
  // the step row reaches the store within a second of play (the session's flush)
  const rows = await p.until(async () => { const r = await stepRows(p.page); return r.length && r; },
    'a step row in steps-001.csv', 10000);
  assert(rows.length === 1 && rows[0].dir === 'N' && rows[0].col === '1' && rows[0].row === '0',
    'step rows: ' + JSON.stringify(rows));
  const st = steps(p.log);
  assert(st.length === 1, 'steps: ' + JSON.stringify(st));
  await p.page.screenshot({ path: path.join(OUT, 'pancake-north.png') });
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
});

await check('touch: a finger dragged down on the left half walks one step back (south)', async () => {
  const p = p1;
  assert(p, 'no page');
  await p.page.touchscreen.touchStart(200, 300);
  await p.page.touchscreen.touchMove(200, 400); /* 100 px down: the stick full back */
  await p.until(async () => (await p.state(S.STEPS)) >= 2, 'a second room step');
  await p.page.touchscreen.touchEnd();
  const rows = await p.until(async () => { const r = await stepRows(p.page); return r.length >= 2 && r; },
    'the second step row', 10000);
  /* back from (1,0): S to (1,1), and on a slow machine maybe S to (1,2) before the finger lifts */
  assert(rows[1].dir === 'S' && rows[1].row === '1' && rows.slice(1).every((r) => r.dir === 'S'),
    'step rows: ' + JSON.stringify(rows));
});

await check('a reload loses nothing: the attempt in play is kept (aborted at pagehide) and the next visit numbers on', async () => {
  const p = p1;
  assert(p, 'no page');
  const session1 = /web: session (\S+),/.exec(p.log.find((l) => l.startsWith('web: session ')))[1];
  const before = await p.state(S.STEPS);
  p.log.length = 0;
  await p.page.reload();
  await p.page.waitForFunction(() => /^Playing/.test(document.getElementById('status').textContent),
    { timeout: 30000 });
  const summary = (await stored(p.page, 'summary.csv'))?.toString('utf8').trim().split('\n') || [];
  assert(summary.length === 2 && summary[1].startsWith(session1 + ',') &&
    new RegExp(`,${before},-?\\d+,[\\d.]+,aborted,,,$`).test(summary[1]),
    `summary.csv (attempt 1, ${before} steps, aborted): ` + summary.join(' | '));
  const rows = await stepRows(p.page);
  assert(rows.length === before && rows[0].dir === 'N' && rows[1].dir === 'S', 'steps-001.csv: ' + JSON.stringify(rows));
  const j = p.log.find((l) => /journal/.test(l));
  console.log('# ' + (j ? j.replace(/^holonomy: /, '') : 'every change had committed before the reload (no journal)'));
  const names = await p.page.evaluate(() => window.holonomyStore.names());
  assert(names.includes(`session-${session1}.rec`), 'no recording of the first visit: ' + names.join(' '));
  assert(names.some((n) => /^attempt-002\.live$/.test(n)), 'the new visit is not attempt 002: ' + names.join(' '));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

// Every mode the desktop plays, played on the page and replayed on the
// desktop: the same final line, the same summary and step rows, byte for byte.
await check('every mode (flag, keys, explore, tutorial) plays on the page; its recording replays on the desktop to the same logs (summary, steps, head rows), byte for byte', async () => {
  for (const mode of ['flag', 'keys', 'explore', 'tutorial']) {
    const p = await openPage(`?mode=${mode}&seed=4`);
    await p.until(async () => (await p.state(S.FRAMES)) > 10, mode + ': frames');
    await p.page.keyboard.down('KeyW');
    await p.until(async () => (await p.state(S.STEPS)) >= 1, mode + ': a room step');
    await p.page.keyboard.up('KeyW');
    await p.page.keyboard.press('KeyQ');
    await p.until(() => p.page.evaluate(() => !document.getElementById('logs').hidden),
      mode + ': the session over, its logs offered');
    const names = await p.page.evaluate(() => window.holonomyStore.names());
    const rec = names.find((n) => /\.rec$/.test(n));
    assert(rec, mode + ': no recording among ' + names.join(', '));
    const dir = path.join(OUT, 'mode-' + mode);
    fs.rmSync(dir, { recursive: true, force: true });
    fs.mkdirSync(dir);
    fs.writeFileSync(path.join(dir, 'browser.rec'), await stored(p.page, rec));
    const r = spawnSync(HOLONOMY, ['replay', path.join(dir, 'browser.rec'), '--log', path.join(dir, 'logs')],
      { encoding: 'utf8' });
    assert(r.status === 0, mode + ': replay: ' + r.stderr);
    const end = p.log.filter((l) => l.startsWith('level ')).pop();
    assert(r.stdout.trim().split('\n').pop() === end,
      `${mode}: replay says '${r.stdout.trim()}', the page '${end}'`);
    const csv = names.filter((n) => /^(summary|steps-\d+|head-\d+)\.csv$/.test(n));
    assert(csv.includes('summary.csv') && csv.includes('steps-001.csv'), mode + ': ' + names.join(' '));
    for (const n of csv) {
      const b = await stored(p.page, n);
      assert(b.equals(fs.readFileSync(path.join(dir, 'logs', n))), `${mode}: ${n} differs from the replay's`);
    }
    const row = fs.readFileSync(path.join(dir, 'logs', 'summary.csv'), 'utf8').trim().split('\n')[1];
    assert(row.includes(`,${mode},`) && /,quit,,,$/.test(row), mode + ': summary row ' + row);
    assert(!p.errors.length, mode + ': errors: ' + p.errors.join('; '));
    await p.ctx.close();
  }
});

// ---- lessons (issue 37; docs/teaching.md) ------------------------------------
// A scripted pupil with keys: the predict item (Right/Left from the middle
// mark, Enter), the instructions (Enter), the route with W/A/S/D (yaw 0:
// north, west, south, east), lesson 3's pointing (Enter), the end and the
// check screens (Enter): every lesson in {4,5} predicted right, in {4,4}
// wrong; the prediction stored in answers.csv as entered.
const LESSONS = [ // route {4,5}, route {4,4}, presses right {4,5}, answer; presses wrong {4,4}, answer
  ['NESW', 'NESW', 1, 'No', 1, 'No'], ['NWSEN', 'NWSE', -1, '5', 0, '6'],
  ['NWSE', 'NWSE', -1, 'North', 0, 'East'], ['NESSWWNN', 'NESSWWNN', 1, '28', 0, '24'],
  ['NESWSWNN', 'NESWSWNN', -1, '4', 0, '5'], ['NESW'.repeat(5), 'NESW', 1, '5', 0, '4']];
async function hold(p, key, ms = 120) {
  await p.page.keyboard.down(key);
  await sleep(ms);
  await p.page.keyboard.up(key);
  await sleep(ms);
}
await check('lessons: a pupil with keys completes every lesson on the page, in {4,5} predicting right and in {4,4} wrong; answers.csv holds the predictions entered', async () => {
  const keys = { N: 'KeyW', S: 'KeyS', W: 'KeyA', E: 'KeyD' };
  for (const [q, k0] of [[5, 0], [4, 3]]) {
    for (let n = 1; n <= 6; n++) {
      const L = LESSONS[n - 1], route = L[k0 ? 1 : 0], presses = L[k0 ? 4 : 2], want = L[k0 ? 5 : 3];
      const what = `lesson ${n} {4,${q}}`;
      const p = await openPage(`?lesson=${n}&tiling=4,${q}`);
      await p.until(async () => (await p.state(S.APP_STATE)) === 6, what + ': the predict item');
      for (let i = 0; i < Math.abs(presses); i++) await hold(p, presses > 0 ? 'ArrowRight' : 'ArrowLeft');
      await hold(p, 'Enter');
      await p.until(async () => (await p.state(S.APP_STATE)) === 5, what + ': the instructions');
      await hold(p, 'Enter');
      await p.until(async () => (await p.state(S.APP_STATE)) === 1, what + ': playing');
      assert(Math.abs(await p.state(S.YAW)) < 1e-6, what + ': the look turned');
      for (let i = 0; i < route.length; i++) {
        await p.page.keyboard.down(keys[route[i]]);
        await p.until(async () => (await p.state(S.STEPS)) >= i + 1, `${what}: step ${i + 1}`);
        await p.page.keyboard.up(keys[route[i]]);
      }
      for (const st of n === 3 ? [4, 2, 5] : [2, 5]) {
        await p.until(async () => (await p.state(S.APP_STATE)) === st, `${what}: state ${st}`);
        await hold(p, 'Enter');
      }
      await p.until(async () => (await p.state(S.OVER)) === 1, what + ': the session over');
      const csv = (await stored(p.page, 'answers.csv')).toString('utf8').trim().split('\n');
      assert(csv.length === 2 && csv[1].split(',').slice(3, 8).join(',') ===
        `predict,before_level,lesson${n},${n === 1 || n === 3 ? 'choice' : 'likert'},${want}`,
      what + ': answers.csv ' + csv.join(' | '));
      const sum = (await stored(p.page, 'summary.csv')).toString('utf8');
      assert(new RegExp(`,lesson-${n},[0-9a-f]{64},explore,0,[0-9]+,"4,${q}",3x3,1,[0-9.]+,${route.length},-1,[0-9.]+,done,`).test(sum),
        what + ': summary ' + sum.trim());
      assert(!p.errors.length, what + ': errors: ' + p.errors.join('; '));
      await p.ctx.close();
    }
  }
});

// ---- lessons by touch and by hands (issue 37; docs/teaching.md) -------------
// Scripted pupils with no keyboard: every lesson in {4,5}, once predicting
// right and once wrong (the middle mark: Yes, 6, East, 24, 5, 4), each a
// participant of its own. By touch (the page's touch buttons and the left
// half's stick): the predict item by a swipe left or right a mark, OK by
// the on-screen button; walked standing with the stick (right) and seated
// with the on-screen arrows (wrong). By hands alone in seated XR (iwer's
// Quest 3, ?seated=1): the item chosen by pointing the right hand (its
// ray: the mark it points at), every screen by a right pinch, each room
// step by a pinch and flick (core/hol_body.h). Each attempt's answers.csv
// and summary.csv go to a pupil's folder of the class; `holonomy report
// --class` over it must give every item as entered.
const MARKS = [2, 7, 5, 11, 11, 8], LO = [0, 3, 0, 4, 0, 1], STEP = [1, 1, 1, 4, 1, 1];
const WRONG = ['Yes', '6', 'East', '24', '5', '4'];
const pupilsDir = path.join(OUT, 'pupils-class');
fs.rmSync(pupilsDir, { recursive: true, force: true });
fs.mkdirSync(pupilsDir, { recursive: true });
// the lesson's plan for a pupil: route, presses from the middle mark, answer
function lessonPlan(n, right) {
  const L = LESSONS[n - 1];
  return { route: L[0], presses: right ? L[2] : 0, want: right ? L[3] : WRONG[n - 1] };
}
// after the session: the attempt's files into the class, checked against
// what the pupil entered
async function keepAttempt(p, who, n, plan, what) {
  await p.until(async () => (await p.state(S.OVER)) === 1, what + ': the session over', 60000);
  const ans = await stored(p.page, 'answers.csv'), sum = await stored(p.page, 'summary.csv');
  const csv = ans.toString('utf8').trim().split('\n');
  assert(csv.length === 2 && csv[1].split(',')[1] === who && csv[1].split(',').slice(3, 8).join(',') ===
    `predict,before_level,lesson${n},${n === 1 || n === 3 ? 'choice' : 'likert'},${plan.want}`,
  what + ': answers.csv ' + csv.join(' | '));
  assert(new RegExp(`,lesson-${n},[0-9a-f]{64},explore,0,[0-9]+,"4,5",3x3,1,[0-9.]+,${plan.route.length},-1,[0-9.]+,done,`)
    .test(sum.toString('utf8')), what + ': summary ' + sum.toString('utf8').trim());
  const dir = path.join(pupilsDir, `${who}-lesson${n}`);
  fs.mkdirSync(dir, { recursive: true });
  fs.writeFileSync(path.join(dir, 'answers.csv'), ans);
  fs.writeFileSync(path.join(dir, 'summary.csv'), sum);
  assert(!p.errors.length, what + ': errors: ' + p.errors.join('; '));
}

await check('lessons by touch alone: a pupil completes every lesson in {4,5} predicting right (walking with the touch stick) and one predicting wrong (seated, the on-screen arrows); swipes choose, the OK button confirms (the prompt names it); answers.csv holds what was entered', async () => {
  const frames = async (p, n) => {
    const f0 = await p.state(S.FRAMES);
    await p.until(async () => (await p.state(S.FRAMES)) >= f0 + n || (await p.state(S.OVER)) === 1, n + ' frames');
  };
  const stick = async (p, dx, dy) => { /* the left half's stick pushed, kept */
    const box = await p.page.evaluate(() => { const r = document.getElementById('canvas').getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; });
    const x = box[0] + box[2] * 0.25, y = box[1] + box[3] * 0.6;
    await p.page.touchscreen.touchStart(x, y);
    await p.page.touchscreen.touchMove(x + dx, y + dy);
  };
  const ok = async (p) => { await p.page.tap('#touch button[data-btn="1"]'); await frames(p, 3); };
  const bits = { N: 256, E: 2048, S: 512, W: 1024 }, drag = { N: [0, -80], S: [0, 80], W: [-80, 0], E: [80, 0] };
  for (const right of [true, false]) {
    const who = right ? 'touch-right' : 'touch-wrong', seated = !right;
    for (let n = 1; n <= 6; n++) {
      const plan = lessonPlan(n, right), what = `${who} lesson ${n}`;
      const p = await openPage(`?lesson=${n}&tiling=4,5&participant=${who}${seated ? '&seated=1' : ''}`, { touch: true });
      await p.page.touchscreen.tap(5, 5); /* the first touch shows the touch buttons */
      await p.until(() => p.page.evaluate(() => document.body.classList.contains('touch')), what + ': the touch buttons');
      await p.until(async () => (await p.state(S.APP_STATE)) === 6, what + ': the predict item');
      for (let i = 0; i < Math.abs(plan.presses); i++) { /* a swipe a mark */
        await stick(p, plan.presses > 0 ? 80 : -80, 0);
        await frames(p, 3);
        await p.page.touchscreen.touchEnd();
        await frames(p, 3);
      }
      await ok(p);
      await p.until(async () => (await p.state(S.APP_STATE)) === 5, what + ': the instructions');
      /* touch the last input: the prompt names the on-screen button, not a key */
      const hint = await p.page.evaluate(() => UTF8ToString(Module._hol_web_hint()));
      assert(/^OK: /.test(hint) && !/ENTER/.test(hint), what + ': the prompt by touch: ' + hint);
      await ok(p);
      await p.until(async () => (await p.state(S.APP_STATE)) === 1, what + ': playing');
      for (let i = 0; i < plan.route.length; i++) {
        const d = plan.route[i];
        if (seated) {
          await p.page.tap(`#steps button[data-btn="${bits[d]}"]`);
        } else await stick(p, drag[d][0], drag[d][1]);
        await p.until(async () => (await p.state(S.STEPS)) >= i + 1, `${what}: step ${i + 1}`);
        if (!seated) await p.page.touchscreen.touchEnd();
        await frames(p, 2);
      }
      if (n === 1 && seated) await p.page.screenshot({ path: path.join(OUT, 'touch-seated-lesson1.png') });
      for (const st of n === 3 ? [4, 2, 5] : [2, 5]) {
        await p.until(async () => (await p.state(S.APP_STATE)) === st, `${what}: state ${st}`);
        if (st === 5 && n === 1) await p.page.screenshot({ path: path.join(OUT, `${who}-check.png`) });
        await ok(p);
      }
      await keepAttempt(p, who, n, plan, what);
      await p.ctx.close();
    }
  }
});

// The XR frames' times as a 72 Hz headset's, one frame apart each, though
// this machine (SwiftShader, two eyes) draws a few a second: a pinch's
// length and a flick's speed (core/hol_body.h) are then the frames the
// script holds them, not the machine's load (a tap is a frame or two, a
// long pinch 72).
async function xrTime72(p) {
  await p.page.evaluate(() => {
    const X = Module.holXR, f = X.frame;
    let v = null;
    X.frame = function (t, xrf) {
      v = v === null ? t : v + 1000 / 72;
      return f(v, xrf);
    };
  });
}
await check('lessons by hands alone, seated on a Quest 3 (iwer\'s hands, ?seated=1): a pupil completes every lesson in {4,5} predicting right and one predicting wrong; the item chosen by pointing, screens by a right pinch, every room step by a pinch and flick; answers.csv holds what was entered', async () => {
  for (const right of [true, false]) {
    const who = right ? 'hands-right' : 'hands-wrong';
    for (let n = 1; n <= 6; n++) {
      const plan = lessonPlan(n, right), what = `${who} lesson ${n}`;
      const p = await openPage(`?lesson=${n}&tiling=4,5&participant=${who}&seated=1`, { iwer: true });
      /* a quarter of the recommended size an eye: the frames the pupil
       * needs come 16 times the pixels cheaper on this machine */
      await p.page.evaluate(() => { xrDevice.primaryInputMode = 'hand'; Module.holXR.scale = 0.25; });
      await enterVR(p);
      await xrTime72(p);
      const frames = async (k) => {
        const f0 = await p.state(S.XR_FRAMES);
        await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + k ||
          (await p.state(S.OVER)) === 1, k + ' XR frames', 120000);
      };
      const setPinch = async (v) => { await p.page.evaluate((x) => xrDevice.hands.right.updatePinchValue(x), v); await frames(1); };
      const pinch = async () => { await setPinch(1); await setPinch(0); await frames(2); }; /* a tap */
      const inState = async (st, label) => {
        try {
          await p.until(async () => (await p.state(S.APP_STATE)) === st, `${what}: ${label}`, 30000);
        } catch (e) {
          throw new Error(`${e.message} (state ${await p.state(S.APP_STATE)}; ${p.log.slice(-4).join(' / ')})`);
        }
      };
      const home = await p.page.evaluate(() => { const q = xrDevice.hands.right.position; return [q.x, q.y, q.z]; });
      const handAt = (d) => p.page.evaluate((x, y, z) => xrDevice.hands.right.position.set(x, y, z),
        home[0] + d[0], home[1], home[2] + d[1]);
      await frames(5);
      assert((await p.state(S.DEVICE)) === 10, what + ': the device is not the hands');
      await inState(6, 'the predict item');
      /* point the right hand at the mark: the ray's 60 degrees across the
       * scale, centred on the look (north); turned until the item shows it */
      const k = n - 1, target = (MARKS[k] - 1 >> 1) + plan.presses;
      let yaw = -(((target + 0.5) / MARKS[k]) * 60 - 30), mark = -1;
      for (let tries = 0; tries < 8; tries++) {
        const a = yaw * Math.PI / 360;
        await p.page.evaluate((s, c) => xrDevice.hands.right.quaternion.set(0, s, 0, c), Math.sin(a), Math.cos(a));
        await frames(3);
        mark = ((await p.state(S.ASK)) - LO[k]) / STEP[k];
        if (mark === target) break;
        yaw += (mark - target) * 60 / MARKS[k];
      }
      assert(mark === target, `${what}: the ray points at mark ${mark}, want ${target}`);
      await pinch();
      await inState(5, 'the instructions');
      await p.page.evaluate(() => xrDevice.hands.right.quaternion.set(0, 0, 0, 1));
      await frames(2);
      await pinch();
      await inState(1, 'playing');
      const flick = { N: [0, -0.16], S: [0, 0.16], W: [-0.16, 0], E: [0.16, 0] };
      for (let i = 0; i < plan.route.length; i++) {
        await p.page.evaluate(() => xrDevice.hands.right.updatePinchValue(1)); /* pinched here, */
        await frames(1);
        await handAt(flick[plan.route[i]]); /* then 16 cm on */
        await p.until(async () => (await p.state(S.STEPS)) >= i + 1, `${what}: step ${i + 1}`, 30000);
        await setPinch(0);
        await handAt([0, 0]);
        await frames(2);
        assert((await p.state(S.STEPS)) === i + 1, `${what}: ${await p.state(S.STEPS)} steps after flick ${i + 1}`);
      }
      if (n === 1) {
        const at = (await p.state(S.XR_FRAMES)) + 2;
        await frames(3);
        await p.page.screenshot({ path: path.join(OUT, `hands-seated-lesson1-${who}.png`) });
        void at;
      }
      for (const st of n === 3 ? [4, 2, 5] : [2, 5]) {
        await inState(st, `state ${st}`);
        if (st === 5 && n === 1) await p.page.screenshot({ path: path.join(OUT, `${who}-check.png`) });
        await pinch();
      }
      await keepAttempt(p, who, n, plan, what);
      await p.ctx.close();
    }
  }
});

// The class over the pupils' attempts (touch and hands, right and wrong):
// every lesson's item answered 4 times in {4,5}, 2 of them right; each
// wrong answer as entered, twice.
await check('report --class over the touch and hands pupils\' stored answers: each lesson\'s item answered 4 times, right 2, the wrong answers as entered', async () => {
  const dirs = fs.readdirSync(pupilsDir);
  assert(dirs.length === 24, 'attempts kept: ' + dirs.length + ' (' + dirs.join(' ') + ')');
  const out = path.join(OUT, 'pupils-report');
  const r = spawnSync(HOLONOMY, ['report', '--class', pupilsDir, '--out', out], { encoding: 'utf8' });
  assert(r.status === 0, 'report --class: ' + r.stdout + r.stderr);
  const items = fs.readFileSync(path.join(out, 'class_items.csv'), 'utf8');
  const wrong = fs.readFileSync(path.join(out, 'class_wrong.csv'), 'utf8');
  for (let n = 1; n <= 6; n++) {
    const row = `predict,lesson${n}_q5,lesson ${n},${LESSONS[n - 1][3]},4,2,0.5000000000`;
    assert(items.split('\n').includes(row), `lesson ${n}: no row ${row} in class_items.csv: ${items}`);
    const rows = wrong.split('\n').filter((l) => l.startsWith(`predict,lesson${n}_q5,`));
    assert(rows.length === 1 && rows[0] === `predict,lesson${n}_q5,${WRONG[n - 1]},2,0.5000000000`,
      `lesson ${n}: class_wrong.csv ${rows.join(' | ')}`);
  }
  console.log('  ' + r.stdout.trim());
});

// ---- seated play and a class's tests (issue 37; docs/teaching.md) ---------
// Lesson 1 {4,5} seated: one push of W, D, S, A a step (held keys take one
// step each); then with touch, the on-screen arrows; the panel names the
// mode, the recording replays on the desktop to the same summary and steps.
// The pre-test and post-test with keys; the stored answers, read by
// `holonomy report --class`, give the rates of what was entered.
await check('seated: lesson 1 with keys and with the on-screen arrows, one room step a push; the recording replays on the desktop; the class tests with keys, report --class over the stored answers', async () => {
  for (const how of ['keys', 'touch']) {
    const what = `seated lesson 1 (${how})`;
    const p = await openPage('?lesson=1&seated=1');
    if (how === 'touch') await p.page.evaluate(() => document.body.classList.add('touch'));
    assert(await p.page.evaluate(() => document.getElementById('seated').checked), what + ': the box');
    await p.until(async () => (await p.state(S.APP_STATE)) === 6, what + ': the predict item');
    await hold(p, 'ArrowRight');
    await hold(p, 'Enter');
    await p.until(async () => (await p.state(S.APP_STATE)) === 5, what + ': the instructions');
    await hold(p, 'Enter');
    await p.until(async () => (await p.state(S.APP_STATE)) === 1, what + ': playing');
    const keys = { N: 'KeyW', E: 'KeyD', S: 'KeyS', W: 'KeyA' }, bits = { N: 256, E: 2048, S: 512, W: 1024 };
    for (const [i, d] of ['N', 'E', 'S', 'W'].entries()) {
      if (how === 'keys') await hold(p, keys[d], 400); /* held 0.4 s: still one step */
      else await p.page.click(`#steps button[data-btn="${bits[d]}"]`);
      await p.until(async () => (await p.state(S.STEPS)) >= i + 1, `${what}: step ${i + 1}`);
      await sleep(300);
      assert((await p.state(S.STEPS)) === i + 1, `${what}: more than one step a push`);
    }
    for (const st of [2, 5]) {
      await p.until(async () => (await p.state(S.APP_STATE)) === st, `${what}: state ${st}`);
      await hold(p, 'Enter');
    }
    await p.until(async () => (await p.state(S.OVER)) === 1, what + ': the session over');
    const names = await p.page.evaluate(() => window.holonomyStore.names());
    const rec = names.find((n) => /\.rec$/.test(n));
    const dir = path.join(OUT, 'seated-' + how);
    fs.rmSync(dir, { recursive: true, force: true });
    fs.mkdirSync(dir);
    const recText = await stored(p.page, rec);
    assert(/ f=100[0-9a-f] /.test(recText.toString('utf8')), what + ': no seated record');
    fs.writeFileSync(path.join(dir, 'browser.rec'), recText);
    const r = spawnSync(HOLONOMY, ['replay', path.join(dir, 'browser.rec'), '--log', path.join(dir, 'logs')],
      { encoding: 'utf8' });
    assert(r.status === 0 && /^level lesson-1 done steps 4 /m.test(r.stdout), what + ': replay: ' + r.stdout + r.stderr);
    for (const n of ['summary.csv', 'steps-001.csv', 'answers.csv']) {
      const b = await stored(p.page, n);
      assert(b.equals(fs.readFileSync(path.join(dir, 'logs', n))), `${what}: ${n} differs from the replay's`);
    }
    assert(!p.errors.length, what + ': errors: ' + p.errors.join('; '));
    await p.ctx.close();
  }
  // a key held over two frames and let go over two more: a press that a
  // slow frame cannot merge with the next (the items' Left/Right are axis
  // edges: the app must see the key up between two presses). The frames
  // are counted from after the key's event is handled: counted from
  // before it, frames stepped while a loaded machine delivered the event
  // could count, and a release no step saw merged two presses into one
  // (a CI run: the pre-test's growth item 11 for 12)
  const tap = async (p, key) => {
    for (const down of [true, false]) {
      await (down ? p.page.keyboard.down(key) : p.page.keyboard.up(key));
      const f0 = await p.state(S.FRAMES);
      await p.until(async () => (await p.state(S.FRAMES)) >= f0 + 2, key + ': two frames');
    }
  };
  const rows = async (p) => ((await stored(p.page, 'answers.csv'))?.toString('utf8').trim().split('\n').length || 1) - 1;
  const cls = path.join(OUT, 'class');
  fs.rmSync(cls, { recursive: true, force: true });
  fs.mkdirSync(cls);
  let i = 0;
  for (const [quiz, presses] of [['pre', [1, -1, 2, 0]], ['post', [1, 0, 1, -2]]]) {
    const what = `quiz ${quiz}`;
    const p = await openPage(`?quiz=${quiz}&participant=P01`);
    for (const [k, n] of presses.entries()) {
      await p.until(async () => (await p.state(S.APP_STATE)) === 6 && (await rows(p)) === k, `${what}: item ${k + 1}`);
      for (let j = 0; j < Math.abs(n); j++) await tap(p, n > 0 ? 'ArrowRight' : 'ArrowLeft');
      await tap(p, 'Enter');
    }
    await p.until(async () => (await p.state(S.APP_STATE)) === 2, what + ': the end');
    await tap(p, 'Enter');
    await p.until(async () => (await p.state(S.APP_STATE)) === 5, what + ': the closing screen');
    fs.writeFileSync(path.join(cls, `p01-${++i}.csv`), await stored(p.page, 'answers.csv'));
    assert(!p.errors.length, what + ': errors: ' + p.errors.join('; '));
    await p.ctx.close();
  }
  const r = spawnSync(HOLONOMY, ['report', '--class', cls, '--out', path.join(OUT, 'class-report')], { encoding: 'utf8' });
  assert(r.status === 0 && /^report --class: 1 pupils, 1 with both tests/.test(r.stdout), 'report --class: ' + r.stdout + r.stderr);
  const pupils = fs.readFileSync(path.join(OUT, 'class-report', 'class_pupils.csv'), 'utf8');
  assert(pupils.includes('P01,0.7500000000,1.0000000000,0.2500000000'), 'class_pupils.csv: ' + pupils);
});

await check('a level file chosen on the page plays at the next load, the participant in the logs', async () => {
  const lv = path.join(testDir, 'my-flag.lvl');
  fs.writeFileSync(lv, 'mode flag\nseed 9\nflag-distance 3\n');
  const p = await openPage('?participant=P07');
  const input = await p.page.$('#file');
  await Promise.all([p.page.waitForNavigation({ timeout: 30000 }), input.uploadFile(lv)]);
  await p.page.waitForFunction(() => /^Playing/.test(document.getElementById('status').textContent),
    { timeout: 30000 });
  const st = await p.page.evaluate(() => document.getElementById('status').textContent);
  assert(st === 'Playing my-flag', 'status: ' + st);
  const live = await p.until(async () => {
    const names = await p.page.evaluate(() => window.holonomyStore.names());
    const n = names.filter((x) => /^attempt-\d+\.live$/.test(x)).sort().pop();
    return n && (await stored(p.page, n)).toString('utf8');
  }, 'the attempt in play');
  assert(/,P07,/.test(live) && /,my-flag,/.test(live) && /,flag,9,/.test(live), 'attempt row: ' + live.trim());
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('a bad level file is refused with one line naming its line, and nothing plays', async () => {
  fs.writeFileSync(path.join(testDir, 'bad.lvl'), 'mode flag\nseed 5\nflag Nzz\n');
  const p = await openPage('?level=/test/bad.lvl', { fail: true });
  const st = await p.page.evaluate(() => document.getElementById('status').textContent);
  assert(/^Failed: bad: line 3: /.test(st), 'status: ' + st);
  assert((await p.page.evaluate(() => Module._hol_web_state(0))) === 0, 'frames were stepped');
  await p.ctx.close();
});

await check('sound: after a click, an AudioContext runs and a level with sound all plays its sources; nothing before the click, nothing with ?sound=0, ?sound=2 refused', async () => {
  fs.writeFileSync(path.join(testDir, 'sound.lvl'), 'mode flag\nseed 9\nflag-distance 3\nsound all\n');
  const audio = (p) => p.page.evaluate(() => Module.holAudioState());
  const p = await openPage('?level=/test/sound.lvl');
  await p.until(async () => (await p.state(S.FRAMES)) > 10, 'frames');
  assert((await p.state(S.SOUNDS)) === 0 && (await audio(p)) === '',
    `before a gesture: ${await p.state(S.SOUNDS)} sources, AudioContext '${await audio(p)}'`);
  await p.page.mouse.click(W / 2, H / 2);
  await p.until(async () => (await p.state(S.SOUNDS)) > 0, 'sources playing after the click');
  await p.until(async () => (await audio(p)) === 'running', 'the AudioContext running');
  // the player's looping sources are WebAudio's (hol_web_al.js): as many
  // looping AudioBufferSourceNodes playing as the player's voices, through
  // HRTF panners, at gains above 0 (read in one turn of the page's loop)
  const [voices, nodes] = await p.page.evaluate(() => [Module._hol_web_state(16), Module.holAudioNodes()]);
  assert(voices > 0 && nodes.loops === voices && nodes.models.join() === 'HRTF' &&
    nodes.gains.every((g) => g > 0 && g <= 1),
    `${voices} voices against WebAudio's ${JSON.stringify(nodes)}`);
  assert(p.log.some((l) => /^web: sound: OpenAL on WebAudio, HRTF$/.test(l)),
    'no sound line: ' + p.log.join(' | '));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
  const q = await openPage('?level=/test/sound.lvl&sound=0');
  await q.until(async () => (await q.state(S.FRAMES)) > 10, 'frames (sound=0)');
  await q.page.mouse.click(W / 2, H / 2);
  const f = await q.state(S.FRAMES);
  await q.until(async () => (await q.state(S.FRAMES)) > f + 10, 'frames after the click (sound=0)');
  assert((await q.state(S.SOUNDS)) === 0 && (await audio(q)) === '',
    `sound=0: ${await q.state(S.SOUNDS)} sources, AudioContext '${await audio(q)}'`);
  assert(!q.errors.length, 'errors (sound=0): ' + q.errors.join('; '));
  await q.ctx.close();
  const r = await openPage('?level=/test/sound.lvl&sound=2', { fail: true });
  const st = await r.page.evaluate(() => document.getElementById('status').textContent);
  assert(st === 'Failed: sound is not 0 or 1', 'status: ' + st);
  await r.ctx.close();
});

await check('a night level with lanterns draws on WebGL 2 (the lit shader compiles, no console error), much darker than the same level at day', async () => {
  const mean = async (name, text) => {
    fs.writeFileSync(path.join(testDir, name), text);
    const p = await openPage('?level=/test/' + name);
    await p.until(async () => (await p.state(S.FRAMES)) > 5, 'frames');
    const shot = path.join(OUT, name + '.png');
    /* the view alone: the page's header above it is the same at night */
    await (await p.page.$('#canvas')).screenshot({ path: shot });
    assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
    await p.ctx.close();
    const img = decodePNG(fs.readFileSync(shot));
    const bpp = img.rgba.length / (img.w * img.h);
    let sum = 0;
    for (let i = 0; i < img.rgba.length; i += bpp) sum += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2];
    return sum / (3 * img.w * img.h);
  };
  const day = await mean('day.lvl', 'mode explore\nseed 3\nminimap off\n');
  const night = await mean('night.lvl', 'mode explore\nseed 3\nminimap off\nlighting night\nplace lantern O\nplace lantern N\n');
  /* the trunks beside the two lanterns take their light by the floor's law
   * (issue 38) and fill much of this view; the lanterns' sum is tone-mapped
   * (docs/lighting.md#tone-map), so they glow but stay under their colour:
   * the view's mean 0.51 of day's (39.3 against 77.4; of the whole page
   * with its header, as this check measured before: 0.64 with the white
   * level 1/3, 0.87 with the sum unbounded, 0.5 when only the floor was
   * lit) */
  assert(night < 0.6 * day && night > 2, `mean brightness: day ${day.toFixed(1)}, night ${night.toFixed(1)}`);
});

await check('snap turn (?snap=90): a tap of Left turns the look by 90 degrees; ?snap=7 is refused', async () => {
  const p = await openPage('?mode=explore&seed=2&snap=90');
  await p.until(async () => (await p.state(S.FRAMES)) > 5, 'frames');
  await p.page.keyboard.press('ArrowLeft');
  const yaw = await p.until(async () => { const y = await p.state(S.YAW); return y > 1 && y; }, 'a snap');
  assert(Math.abs(yaw - 90) < 1e-6, 'yaw ' + yaw);
  await p.ctx.close();
  const q = await openPage('?snap=7', { fail: true });
  const st = await q.page.evaluate(() => document.getElementById('status').textContent);
  assert(/snap/.test(st), 'status: ' + st);
  await q.ctx.close();
});

await check('?tiling=4,6&room=4x4&cell=0.6 play (every level in them), the campaign in ?tiling=4,4 plays; a bad tiling, room or cell is refused with one line, and nothing plays', async () => {
  const p = await openPage('?mode=explore&seed=2&tiling=4,6&room=4x4&cell=0.6');
  await p.until(async () => (await p.state(S.FRAMES)) > 5, 'frames');
  assert(p.log.includes('web: geometry from the page: tiling 4,6, room 4x4, cell 0.6'),
    'no geometry line: ' + p.log.filter((l) => l.startsWith('web:')).join(' | '));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
  // the default campaign made for the flat {4,4} (its objectives on the room's tiles) plays
  const f = await openPage('?tiling=4,4');
  await f.until(async () => (await f.state(S.FRAMES)) > 5, 'frames in {4,4}');
  assert(f.log.includes('web: geometry from the page: tiling 4,4, room -, cell -'),
    'no {4,4} geometry line: ' + f.log.filter((l) => l.startsWith('web:')).join(' | '));
  assert(!f.errors.length, '{4,4} errors: ' + f.errors.join('; '));
  await f.ctx.close();
  for (const [q, re] of [['tiling=4,9', /^Failed: tiling '4,9' is not 4,Q/],
    ['room=2x2', /^Failed: room '2x2' is not CxR/], ['room=4', /^Failed: room '4' is not CxR/],
    ['cell=2', /^Failed: cell '2' is not a size in metres from 0.5 to 1.5$/],
    ['cell=0.6m', /^Failed: cell '0.6m'/], ['cell=.5', /^Failed: cell '.5'/]]) {
    const r = await openPage('?' + q, { fail: true });
    const st = await r.page.evaluate(() => document.getElementById('status').textContent);
    assert(re.test(st), q + ': status ' + st);
    assert((await r.page.evaluate(() => Module._hol_web_state(0))) === 0, q + ': frames were stepped');
    await r.ctx.close();
  }
});

await check('fit on entry: a 2.6 x 2.6 m bounded-floor (iwer, a boundsGeometry shim) plays the room that fits (4 x 4 cells of 0.6 m) at once, said on the panel; a reset with a 3.6 x 3.6 m area fits again (5 x 5 of 0.65 m); with ?room= named the fit is told, not played', async () => {
  const sq = [[-1.3, -1.3], [1.3, -1.3], [1.3, 1.3], [-1.3, 1.3]];
  const p = await openPage('?mode=explore&seed=2', { iwer: true, bounds: sq });
  await enterVR(p);
  const want = 'Room 4 x 4 cells of 0.6 m fits your 2.6 x 2.6 m play area';
  await p.until(() => p.log.includes('web: ' + want), 'the fit line: ' + want);
  await p.until(async () => (await p.state(S.COLS)) === 4 && (await p.state(S.ROWS)) === 4 &&
    Math.abs((await p.state(S.CELL)) - 0.6) < 1e-9, 'the fitted room in play', 20000);
  assert(p.log.some((l) => /^web: the room fitted to the play area \(4x4 of 0\.6 m\): a new session plays it/.test(l)),
    'no refit line');
  const lines = await p.page.evaluate(() => { const r = []; for (let i = 0; i < 8; i++) r.push(UTF8ToString(Module._hol_web_xr_panel_line(i))); return r; });
  console.log('# panel: ' + JSON.stringify(lines.filter((l) => l)));
  assert(lines.includes('ROOM 4 X 4 OF 0.6 M') && lines.includes('FITS YOUR 2.6 X 2.6 M AREA'), 'panel lines: ' + JSON.stringify(lines));
  const st = await p.page.evaluate(() => document.getElementById('status').textContent);
  assert(st === want, 'status: ' + st);
  // the play area changes (a new boundary): the space's reset fits again
  const big = [[-1.8, -1.8], [1.8, -1.8], [1.8, 1.8], [-1.8, 1.8]];
  await p.page.evaluate((g) => {
    Object.defineProperty(XRReferenceSpace.prototype, 'boundsGeometry', {
      configurable: true, get: () => g.map(([x, z]) => new DOMPointReadOnly(x, 0, z, 1)) });
    Module.holXR.space.dispatchEvent(new Event('reset'));
  }, big);
  await p.until(async () => (await p.state(S.COLS)) === 5 && (await p.state(S.ROWS)) === 5, 'the room fitted again after the reset', 20000);
  const fit2 = p.log.filter((l) => /^web: the room fitted to the play area/.test(l)).pop();
  console.log('# ' + fit2);
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
  // the page names the room: the fit is told, not played nor offered
  const n = await openPage('?mode=explore&seed=2&room=3x3', { iwer: true, bounds: sq });
  await enterVR(n);
  await n.until(() => n.log.includes('web: ' + want), 'the fit line (named room)');
  await n.until(() => n.log.includes('web: the page names the room or cell: the fit is not offered'), 'not offered');
  await sleep(500);
  assert((await n.state(S.COLS)) === 3, 'the named room was replaced');
  assert(await n.page.evaluate(() => document.getElementById('fitlink').hidden), 'a link was offered');
  await n.ctx.close();
});

await check('a study (study=URL, participant=P02) plays the participant\'s order: the levels fetched beside it, labelled in the logs', async () => {
  fs.mkdirSync(path.join(testDir, 'st', 'lv'), { recursive: true });
  fs.writeFileSync(path.join(testDir, 'st', 'lv', 'f.lvl'), 'mode flag\nseed 5\nflag Wrf\n');
  fs.writeFileSync(path.join(testDir, 'st', 's.study'),
    'study web # three conditions\ncondition a\nlevel lv/f.lvl\ncondition b\nlevel lv/f.lvl # again\n' +
    'set minimap hand\ncondition c\nset mode explore\n');
  const p = await openPage('?study=/test/st/s.study&participant=P02');
  // Williams, three conditions: participant 2 plays row 2, b c a
  const line = p.log.find((l) => l.startsWith('web: study '));
  assert(line === 'web: study web, participant P02 (number 2): b c a', 'order line: ' + line);
  const live = (await stored(p.page, 'attempt-001.live'))?.toString('utf8') || '';
  assert(/^[^,]*,P02,[^,]*,[^,]*,1,web,b,1,f,[0-9a-f]{64},flag,/.test(live), 'attempt 1: ' + live);
  const names = await p.page.evaluate(() => window.holonomyStore.names());
  assert(names.filter((n) => /^level-[0-9a-f]{64}\.txt$/.test(n)).length === 3,
    'the levels\' texts: ' + names.join(' '));
  // the study's SHA-256 in the row's study_sha256 (session_no and meta
  // empty), and its text kept as study-HASH.txt, as play --study keeps it
  const text = fs.readFileSync(path.join(testDir, 'st', 's.study'));
  const sha = crypto.createHash('sha256').update(text).digest('hex');
  assert(live.split('\n')[0].endsWith(`,,${sha},`), 'attempt 1\'s study_sha256: ' + live);
  const kept = await stored(p.page, `study-${sha}.txt`);
  assert(kept && kept.equals(text), 'study-HASH.txt: ' + names.join(' '));
  // the provenance files, as play --study writes them (docs/logs.md,
  // Provenance and codebook): provenance.csv's row for the session,
  // order.csv the whole order with each level's hash, codebook.csv
  const session = live.split(',')[0];
  const prov = (await stored(p.page, 'provenance.csv'))?.toString('utf8') || '';
  assert(prov.split('\n')[0] === 'session,participant,version,commit,build_date' &&
    new RegExp(`^${session},P02,[0-9.]+,[^,]+,[^,]+$`).test(prov.trim().split('\n')[1]),
    'provenance.csv: ' + prov);
  const order = (await stored(p.page, 'order.csv'))?.toString('utf8').trim().split('\n') || [];
  assert(order[0] === 'session,participant,study,position,condition,level,level_file,level_sha256' &&
    order.slice(1).map((r) => r.split(',').slice(0, 5).join(',')).join(' ') ===
      `${session},P02,web,1,b ${session},P02,web,2,c ${session},P02,web,3,a` &&
    order.slice(1).every((r) => names.includes(`level-${r.split(',')[7]}.txt`)),
    'order.csv: ' + order.join(' | '));
  const book = (await stored(p.page, 'codebook.csv'))?.toString('utf8') || '';
  assert(book.startsWith('file,column,type,unit,allowed,meaning\n') &&
    book.includes('\nanswers.csv,answered_ms,') && book.includes('\nenvironment.csv,platform,'),
    'codebook.csv: ' + book.slice(0, 200));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('a study without the participant\'s number is refused with one line', async () => {
  const p = await openPage('?study=/test/st/s.study', { fail: true });
  const st = await p.page.evaluate(() => document.getElementById('status').textContent);
  assert(/^Failed: a study needs participant=ID ending in the participant's number/.test(st), 'status: ' + st);
  await p.ctx.close();
});

await check('a gamepad (a getGamepads shim, standard mapping) walks one room step north', async () => {
  const p = await openPage('?seed=3', { gamepad: true });
  await p.until(async () => (await p.state(S.FRAMES)) > 10, 'frames');
  await p.page.evaluate(() => { window.__pad.axes[1] = -1; });
  await p.until(async () => (await p.state(S.STEPS)) >= 1, 'a room step');
  await p.page.evaluate(() => { window.__pad.axes[1] = 0; });
  const rows = await p.until(async () => { const r = await stepRows(p.page); return r.length && r; },
    'a step row in steps-001.csv', 10000);
  assert(rows.length === 1 && rows[0].dir === 'N' && rows[0].row === '0',
    'step rows: ' + JSON.stringify(rows));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('environment.csv (issue 26): a pancake session writes one row, platform web: the desktop\'s header, the browser, the GL renderer, the gamepad\'s id, the measured refresh rate, the canvas size, the query string', async () => {
  const p = await openPage('?seed=3&participant=P05', { gamepad: true });
  const rows = await p.until(async () => { const r = await envRows(p.page); return r && r.length && r; },
    'a row in environment.csv', 90000);
  const r = rows[0], session = sessionOf(p);
  const [cw, ch] = await p.page.evaluate(() => [canvas.width, canvas.height]);
  console.log('# ' + JSON.stringify(r));
  assert(rows.length === 1 && r.session === session && r.participant === 'P05' && r.platform === 'web',
    `rows (one, session ${session}, P05, web): ` + JSON.stringify(rows));
  assert(r.session_no === '' && r.study_sha256 === '' && r.meta === '', 'session_no, study_sha256, meta: ' + JSON.stringify(r));
  assert(/Linux/.test(r.os) && /^HeadlessChrome\/\d+\.[\d.]+$/.test(r.runtime) && /SwiftShader/.test(r.gl_renderer),
    `os '${r.os}', runtime '${r.runtime}', gl_renderer '${r.gl_renderer}'`);
  assert(r.controller === 'holonomy test pad (standard)', 'controller: ' + r.controller);
  assert(/^\d+\.\d{3}$/.test(r.refresh_hz) && +r.refresh_hz > 0, 'refresh_hz: ' + r.refresh_hz);
  assert(+r.width === cw && +r.height === ch && cw > 0, `size ${r.width}x${r.height}, canvas ${cw}x${ch}`);
  assert(r.options === 'seed=3&participant=P05', 'options: ' + r.options);
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

// ---- the frame path waits for nothing; entering VR walks nothing; the page's states ----
const statusOf = (p) => p.page.evaluate(() => document.getElementById('status').textContent);
const vrButton = (p) => p.page.evaluate(() => {
  const b = document.getElementById('vr'), a = document.getElementById('again');
  return { text: b.textContent, hidden: b.hidden, disabled: b.disabled, again: !a.hidden };
});
async function exitVR(p) {
  await p.until(async () => (await vrButton(p)).text === 'Exit VR', 'the Exit VR button');
  // (iwer's emulator lays its full-page container over the page: the
  // button is clicked as a script, as the browser's click event would)
  await p.page.evaluate(() => document.getElementById('vr').click());
  await p.until(() => p.page.evaluate(() => !Module.holXR.session), 'the XR session to end');
  // iwer leaves its (empty) full-page container over the page
  await p.page.evaluate(() => document.querySelector('[data-webxr_runtime]')?.remove());
}

// 120 frames of each (300 before issue 24's CI budget: the check is the
// same, a sync call in the frame path shows once a frame; the desktop's
// tests/cli_gl_sync.sh still counts 300)
const SYNC_FRAMES = 120;
await check(`no GPU sync in the frame path: 0 getError, finish, readPixels or get* calls over ${SYNC_FRAMES} pancake frames and ${SYNC_FRAMES} XR frames`, async () => {
  const p = await openPage('?mode=explore&seed=2', { iwer: true, syncCount: true });
  const count = async (what, frames, n) => {
    await p.until(async () => (await frames()) >= 5, what + ': first frames', 60000);
    await p.page.evaluate(() => { __sync.n = 0; __sync.names = {}; __sync.on = true; });
    const f0 = await frames(), t = Date.now();
    await p.until(async () => (await frames()) >= f0 + n, `${n} ${what} frames`, 240000);
    const r = await p.page.evaluate(() => { __sync.on = false; return { n: __sync.n, names: __sync.names }; });
    console.log(`# ${what}: ${r.n} sync calls over ${n} frames (${((Date.now() - t) / n).toFixed(1)} ms a frame) ${JSON.stringify(r.names)}`);
    return r;
  };
  const pan = await count('pancake', () => p.state(S.FRAMES), SYNC_FRAMES);
  await enterVR(p);
  const xrc = await count('XR', () => p.state(S.XR_FRAMES), SYNC_FRAMES);
  assert(pan.n === 0, 'pancake: ' + JSON.stringify(pan.names));
  assert(xrc.n === 0, 'XR: ' + JSON.stringify(xrc.names));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('entering, leaving and entering VR again walks nothing: walk a step in pancake, Enter VR, Exit VR, walk a step, Enter VR: the log holds the two walked steps', async () => {
  const p = await openPage('?mode=explore&seed=2', { iwer: true });
  const walk = async () => {
    const n = await p.state(S.STEPS);
    await p.page.keyboard.down('KeyW');
    await p.until(async () => (await p.state(S.STEPS)) > n, 'a room step');
    await p.page.keyboard.up('KeyW');
  };
  const xrFor = async (n) => {
    await enterVR(p);
    const f0 = await p.state(S.XR_FRAMES);
    await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n, n + ' XR frames', 120000);
  };
  await p.until(async () => (await p.state(S.FRAMES)) > 10, 'frames');
  await walk();
  await xrFor(30);
  await exitVR(p);
  await walk();
  await xrFor(30);
  await exitVR(p);
  const f0 = await p.state(S.FRAMES);
  await p.until(async () => (await p.state(S.FRAMES)) >= f0 + 10, 'pancake frames');
  const st = steps(p.log);
  assert(st.length === 2 && st.every((x) => x.dir === 'N'), 'steps: ' + JSON.stringify(st));
  const rows = await p.until(async () => { const r = await stepRows(p.page); return r.length >= 2 && r; },
    'two step rows', 10000);
  assert(rows.length === 2 && rows.every((r) => r.dir === 'N'), 'step rows: ' + JSON.stringify(rows));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('environment.csv (issue 26): without XRSession.frameRate the XR rate is measured over 60 XR frames; every Enter VR writes its own webxr row', async () => {
  const p = await openPage('?mode=explore&seed=2', { iwer: true });
  await p.page.evaluate(() => Object.defineProperty(XRSession.prototype, 'frameRate',
    { configurable: true, get() { return undefined; } }));
  const xrRows = async (n) => p.until(async () => {
    const r = ((await envRows(p.page)) || []).filter((x) => x.platform === 'webxr');
    return r.length >= n && r;
  }, n + ' webxr row(s)', 120000);
  for (const n of [1, 2]) {
    await enterVR(p);
    await xrRows(n);
    await exitVR(p);
  }
  const rows = await envRows(p.page), vr = rows.filter((x) => x.platform === 'webxr');
  console.log('# ' + vr.map((r) => r.refresh_hz + ' Hz ' + r.controller).join(', '));
  assert(vr.length === 2 && rows.every((r) => r.session === sessionOf(p)), 'rows: ' + JSON.stringify(rows));
  assert(vr.every((r) => /^\d+\.\d{3}$/.test(r.refresh_hz) && +r.refresh_hz > 0 && r.refresh_hz !== '90.000' &&
    r.controller === 'webxr-touch' && r.width === String(W / 2)), 'webxr rows: ' + JSON.stringify(vr));
  assert(p.log.some((l) => /^web: environment webxr \d+\.\d{3} Hz/.test(l)), 'no console line');
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('the page in every state: why VR is unavailable (no headset; plain http from a LAN address), Enter and Exit VR (the first seconds name Y for the menu), the pause\'s reason (window not focused, headset off, menu), F2\'s frame time, over: no Enter VR, Play again', async () => {
  // no headset: chromium's WebXR with no device
  const a = await openPage('?mode=explore&seed=2');
  let b = await vrButton(a);
  await a.until(async () => (b = await vrButton(a)) && !b.hidden, 'the VR button');
  assert(b.text === 'No VR headset found' && b.disabled, 'no headset: ' + JSON.stringify(b));
  await a.page.screenshot({ path: path.join(OUT, 'page-no-headset.png') });
  // the window loses the focus: paused, and the status says why
  await a.page.evaluate(() => { document.hasFocus = () => false; });
  await a.until(async () => (await statusOf(a)) === 'Paused: the window is not focused', 'the focus pause');
  await a.page.evaluate(() => { delete document.hasFocus; });
  await a.until(async () => (await statusOf(a)) === 'Playing', 'playing again');
  await a.page.keyboard.press('KeyP');
  await a.until(async () => (await statusOf(a)) === 'Paused: the menu is open', 'the menu pause');
  await a.page.keyboard.press('KeyP');
  await a.until(async () => (await statusOf(a)) === 'Playing', 'the menu closed');
  // F2: the frame time on the view, as the desktop's
  const overlay = () => a.page.evaluate(() => {
    const q = Module._hol_web_overlay();
    if (!q) return null;
    let s = '';
    for (let i = q; HEAPU8[i]; i++) s += String.fromCharCode(HEAPU8[i]);
    return s;
  });
  assert((await overlay()) === null, 'an overlay before F2');
  await a.page.keyboard.press('F2');
  const line = await a.until(async () => { const o = await overlay(); return o && /^FPS \d/.test(o) && o; },
    'the frame time', 10000);
  assert(/^FPS \d+\.\d CPU \d+\.\d MS$/.test(line), 'overlay: ' + line);
  await a.page.screenshot({ path: path.join(OUT, 'page-f2.png') });
  await a.page.keyboard.press('F2');
  assert((await overlay()) === null, 'F2 again leaves the overlay on');
  assert(!a.errors.length, 'errors: ' + a.errors.join('; '));
  await a.ctx.close();
  // a LAN address over plain http: no secure context, no WebXR
  const lan = await openPage_(browser, server.base.replace('127.0.0.1', 'lan.holonomy.test') + '/?mode=explore&seed=2', { iwer: false });
  const lb = await vrButton(lan);
  assert(lb.text === 'VR needs https:// or localhost' && lb.disabled && !lb.hidden, 'http LAN: ' + JSON.stringify(lb));
  await lan.page.screenshot({ path: path.join(OUT, 'page-http-lan.png') });
  await lan.ctx.close();
  // a headset (iwer): Enter VR, the headset off and on, Exit VR, quit, Play again
  const p = await openPage('?mode=explore&seed=2', { iwer: true });
  await enterVR(p);
  await p.until(async () => (await vrButton(p)).text === 'Exit VR', 'Exit VR');
  assert((await statusOf(p)) === 'In VR', 'status in VR: ' + (await statusOf(p)));
  // the first seconds with the Quest's controllers: the panel names Y
  const firstHint = await p.until(() => p.page.evaluate(() => UTF8ToString(Module._hol_web_hint())),
    'a prompt in the first seconds', 10000);
  assert(firstHint === 'Y: menu', 'the first seconds\' prompt with controllers: ' + firstHint);
  await p.page.evaluate(() => xrDevice.updateVisibilityState('hidden'));
  await p.until(async () => (await statusOf(p)) === 'Paused: the headset is off', 'the headset-off pause');
  await p.page.evaluate(() => xrDevice.updateVisibilityState('visible'));
  await p.until(async () => (await statusOf(p)) === 'In VR', 'in VR again');
  await exitVR(p);
  await p.until(async () => (await statusOf(p)) === 'Playing', 'playing after Exit VR');
  b = await vrButton(p);
  assert(b.text === 'Enter VR' && !b.disabled && !b.hidden && !b.again, 'after Exit VR: ' + JSON.stringify(b));
  await p.page.keyboard.press('KeyQ');
  await p.until(async () => /^Session over/.test(await statusOf(p)), 'the session over');
  b = await vrButton(p);
  assert(b.hidden && b.again, 'over: ' + JSON.stringify(b));
  await sleep(200);
  await p.page.screenshot({ path: path.join(OUT, 'page-over.png') });
  await Promise.all([p.page.waitForNavigation({ timeout: 30000 }), p.page.click('#again')]);
  await p.page.waitForFunction(() => /^Playing/.test(document.getElementById('status').textContent),
    { timeout: 30000 });
  await p.until(async () => (await p.state(S.FRAMES)) > 3, 'frames after Play again');
  b = await vrButton(p);
  assert(!b.again && b.text === 'Enter VR', 'after Play again: ' + JSON.stringify(b));
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('a failed Enter VR: the status says why while the pancake game plays on, and says Playing again at the game\'s restart (R)', async () => {
  const p = await openPage('?mode=explore&seed=2', { iwer: true });
  try {
    await p.page.evaluate(() => {
      navigator.xr.requestSession = () => Promise.reject(new Error('refused by the test'));
    });
    await p.page.waitForSelector('#vr:not([hidden])', { timeout: 10000 });
    await p.page.click('#vr');
    await p.until(async () => (await statusOf(p)) === 'VR failed: refused by the test', 'the failure told');
    const f0 = await p.state(S.FRAMES);
    await p.until(async () => (await p.state(S.FRAMES)) > f0 + 10, 'pancake frames after the failure');
    assert((await statusOf(p)) === 'VR failed: refused by the test', 'status: ' + (await statusOf(p)));
    await p.page.keyboard.press('KeyR');
    await p.until(async () => (await statusOf(p)) === 'Playing', 'Playing after the restart (status: ' +
      (await statusOf(p)) + ')', 10000);
    assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  } finally {
    await p.ctx.close();
  }
});

await check('at every width from 280 to 1280 px, with and without the touch buttons, the Logs overlay (shown when the session is over) covers no button of the bar (Play again)', async () => {
  const p = await openPage('?mode=explore&seed=2');
  try {
    await p.page.setViewport({ width: 320, height: 480 });
    await p.until(async () => (await p.state(S.FRAMES)) > 5, 'frames');
    await p.page.keyboard.press('KeyQ');
    await p.until(async () => /^Session over/.test(await statusOf(p)), 'the session over');
    await p.until(() => p.page.evaluate(() => !document.getElementById('logs').hidden), 'the logs shown');
    const covered = [];
    for (const touch of [false, true]) {
      await p.page.evaluate((t) => document.body.classList.toggle('touch', t), touch);
      for (const [w, h] of [[280, 420], [320, 480], [360, 640], [414, 736], [600, 400], [768, 1024], [1024, 600], [1280, 720]]) {
        await p.page.setViewport({ width: w, height: h });
        await sleep(200); /* the bar's reflow */
        const r = await p.page.evaluate(() => {
          const box = (e) => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
          const logs = box(document.getElementById('logs'));
          const under = [];
          for (const e of document.querySelectorAll('#bar button, #bar label, #bar a')) {
            if (!e.offsetParent && getComputedStyle(e).position !== 'fixed') continue; /* hidden */
            const b = box(e);
            if (b[2] > logs[0] && b[0] < logs[2] && b[3] > logs[1] && b[1] < logs[3])
              under.push((e.id || e.textContent.trim()) + ' ' + b.map(Math.round).join(','));
          }
          return { logs: logs.map(Math.round), under, again: !document.getElementById('again').hidden };
        });
        if (w === 320 && !touch) await p.page.screenshot({ path: path.join(OUT, 'page-320-logs.png') });
        if (!r.again || r.under.length)
          covered.push(`${w}x${h}${touch ? ' touch' : ''}: logs ${r.logs.join(',')} over ${r.under.join('; ') || '(Play again hidden)'}`);
      }
    }
    console.log('# ' + (covered.length ? covered.join(' | ') : '16 sizes: no button under the overlay'));
    assert(!covered.length, covered.join(' | '));
    assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  } finally {
    await p.ctx.close();
  }
});

await check('hands without controllers (iwer\'s hand mode): two hand input sources; the panel names the menu\'s gesture; a left pinch opens the menu, a right pinch restarts there, a long pinch quits', async () => {
  const p = await openPage('?mode=explore&seed=2', { iwer: true });
  await p.page.evaluate(() => { xrDevice.primaryInputMode = 'hand'; });
  await enterVR(p);
  const frames = async (n) => {
    const f0 = await p.state(S.XR_FRAMES);
    await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n ||
      (await p.state(S.OVER)) === 1, n + ' XR frames', 120000);
  };
  const hint = () => p.page.evaluate(() => UTF8ToString(Module._hol_web_hint()));
  await frames(5);
  const srcs = await p.page.evaluate(() => Array.from(Module.holXR.session.inputSources)
    .map((x) => x.handedness + (x.hand ? ' hand' : '')));
  assert(srcs.length === 2 && srcs.every((x) => / hand$/.test(x)), 'input sources: ' + JSON.stringify(srcs));
  // the first seconds: the world panel's prompt names the gesture (hands: webxr-hand, 10)
  assert((await p.state(S.DEVICE)) === 10, 'device ' + (await p.state(S.DEVICE)));
  assert((await hint()) === 'LEFT PINCH: menu', 'the first seconds\' prompt: ' + (await hint()));
  // a pinch: on, one frame, off (a tap: its action when it ends)
  const pinch = async (hand, holdMs) => {
    await p.page.evaluate((h) => xrDevice.hands[h].updatePinchValue(1), hand);
    const t = Date.now();
    await frames(1);
    if (holdMs) {
      while (Date.now() - t < holdMs) await sleep(100);
      await frames(1);
    }
    await p.page.evaluate((h) => xrDevice.hands[h].updatePinchValue(0), hand);
    await frames(2);
  };
  assert((await p.state(S.PAUSED)) === 0, 'paused before the pinch');
  await pinch('left');
  assert((await p.state(S.PAUSED)) === 1, 'a left pinch did not open the menu');
  const menuHint = await hint();
  assert(menuHint === 'LEFT PINCH: resume, PINCH: restart, LONG PINCH: quit', 'the menu\'s prompt: ' + menuHint);
  const clock = await p.state(S.CLOCK);
  await pinch('right');
  assert((await p.state(S.PAUSED)) === 0 && (await p.state(S.CLOCK)) < clock, 'a right pinch did not restart');
  await pinch('left');
  assert((await p.state(S.PAUSED)) === 1, 'a left pinch did not open the menu again');
  await pinch('right', 1500); /* held 1.5 s: back, which quits in the menu */
  await p.until(async () => (await p.state(S.OVER)) === 1, 'the session over after a long pinch', 30000);
  await p.until(() => p.page.evaluate(() => !Module.holXR.session), 'the XR session to end');
  await p.until(async () => /^Session over/.test(await statusOf(p)), 'the page says the session is over');
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

await check('hands-only recentre (iwer\'s hands): both hands\' 25 joints reach the app and are drawn; both palms up and open, held 1 s, re-place the room around the head as the left stick does (the head in the middle, no step), not before', async () => {
  const p = await openPage('?mode=explore&seed=2', { iwer: true });
  await p.page.evaluate(() => { xrDevice.primaryInputMode = 'hand'; });
  await enterVR(p);
  const frames = async (n) => {
    const f0 = await p.state(S.XR_FRAMES);
    await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n, n + ' XR frames', 120000);
  };
  await frames(5);
  assert(((await p.state(S.HANDS)) & 3) === 3, 'joints of both hands: ' + (await p.state(S.HANDS)));
  assert((await p.state(S.BODY)) === 2, 'body parts drawn: ' + (await p.state(S.BODY)));
  // each hand's turn with its palm up and one with it down (iwer's hand
  // pose is its own: try quarter and half turns)
  const turns = [[0, 0, 0, 1], [0, 0, 1, 0], [1, 0, 0, 0], [0, 0, 0.7071, 0.7071],
    [0, 0, -0.7071, 0.7071], [0.7071, 0, 0, 0.7071], [-0.7071, 0, 0, 0.7071]];
  const turn = (h, q) => p.page.evaluate((hh, qq) => xrDevice.hands[hh].quaternion.set(qq[0], qq[1], qq[2], qq[3]), h, q);
  const found = {};
  for (const [h, bit] of [['left', 4], ['right', 8]]) {
    found[h] = {};
    for (const q of turns) {
      await turn(h, q);
      await frames(3);
      const up = ((await p.state(S.HANDS)) & bit) !== 0;
      if (up && !found[h].up) found[h].up = q;
      if (!up && !found[h].down) found[h].down = q;
      if (found[h].up && found[h].down) break;
    }
    assert(found[h].up && found[h].down, h + ': turns ' + JSON.stringify(found[h]));
  }
  await turn('left', found.left.down);
  await turn('right', found.right.down);
  await p.page.evaluate(() => xrDevice.position.set(0.4, 1.6, 0.3)); /* in the same cell */
  await frames(10);
  const hx0 = await p.state(S.HEAD_X), hz0 = await p.state(S.HEAD_Z), steps0 = await p.state(S.STEPS);
  assert(Math.hypot(hx0 - 1.5, hz0 - 1.5) > 0.3, `head at ${hx0},${hz0}`);
  await turn('left', found.left.up);
  await turn('right', found.right.up);
  const t0 = Date.now();
  await frames(3);
  await sleep(400);
  const hxe = await p.state(S.HEAD_X);
  assert(Math.abs(hxe - hx0) < 0.01 || Date.now() - t0 > 900, `recentred after ${Date.now() - t0} ms`);
  await p.until(async () => Math.abs((await p.state(S.HEAD_X)) - 1.5) < 0.02 &&
    Math.abs((await p.state(S.HEAD_Z)) - 1.5) < 0.02, 'the room re-placed around the head', 10000);
  const took = Date.now() - t0;
  console.log(`# hands-only recentre after ${took} ms; turns ${JSON.stringify(found)}`);
  assert(took >= 900, `recentred after ${took} ms (held 1 s)`);
  assert((await p.state(S.STEPS)) === steps0, 'steps with the recentre');
  assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  await p.ctx.close();
});

// Store-like (issue 36): every level type completed with hands alone (iwer's
// hand mode, no controller): the scripted head walks the app's own walk to
// the objective (hol_app_walk; the tutorial's first lesson, which has none,
// one step towards the room's middle row), screens and the end screen
// confirmed with a right pinch; the summary says done.
await check('store: every level type (tutorial, flag, keys) completed by scripted hands alone (iwer\'s hands): walked, confirmed with pinches, the summary says done', async () => {
  for (const mode of ['tutorial', 'flag', 'keys']) {
    const p = await openPage(`?mode=${mode}&seed=4`, { iwer: true });
    await p.page.evaluate(() => { xrDevice.primaryInputMode = 'hand'; });
    await enterVR(p);
    const frames = async (n) => {
      const f0 = await p.state(S.XR_FRAMES);
      await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n ||
        (await p.state(S.OVER)) === 1, n + ' XR frames', 120000);
    };
    const pinch = async () => {
      await p.page.evaluate(() => xrDevice.hands.right.updatePinchValue(1));
      await frames(2);
      await p.page.evaluate(() => xrDevice.hands.right.updatePinchValue(0));
      await frames(3);
    };
    await frames(5);
    const D = { 78: [0, -1], 69: [1, 0], 83: [0, 1], 87: [-1, 0] }; /* N E S W */
    let moves = 0;
    for (; moves < 120 && (await p.state(S.OVER)) !== 1; moves++) {
      const st = await p.state(S.APP_STATE);
      if (st === 2 || st === 5 || st === 6) { await pinch(); continue; } /* end screen, screens */
      const col = await p.state(S.COL), row = await p.state(S.ROW), cols = await p.state(S.COLS),
        rows = await p.state(S.ROWS), m = await p.state(S.CELL);
      let d = D[await p.state(S.WALK)];
      if (!d) d = row > (rows - 1) / 2 ? [0, -1] : [0, 1]; /* no walk known: towards the middle */
      const at = (c, r) => [(c + 0.5) * m - cols * m / 2, (r + 0.5) * m - rows * m / 2];
      const [x0, z0] = at(col, row), [x1, z1] = at(col + d[0], row + d[1]);
      const n0 = await p.state(S.STEPS);
      for (const k of [0.5, 1]) {
        await p.page.evaluate((x, z) => xrDevice.position.set(x, 1.6, z), x0 + (x1 - x0) * k, z0 + (z1 - z0) * k);
        await frames(3);
      }
      await p.until(async () => (await p.state(S.STEPS)) !== n0 || (await p.state(S.APP_STATE)) !== 1,
        `${mode}: the step ${JSON.stringify(d)} from ${col},${row}`, 20000);
    }
    await p.until(async () => (await p.state(S.OVER)) === 1, mode + ': the session over', 30000);
    const sum = ((await stored(p.page, 'summary.csv')) || '').toString().trim().split('\n');
    console.log(`# ${mode}: ${moves} moves; ${sum[sum.length - 1]}`);
    assert(sum.some((r) => r.includes(`,${mode},`) && r.includes(',done,')), mode + ': no done row: ' + sum.join(' | '));
    assert((await p.state(S.DEVICE)) === 10, mode + ': the device is not the hands');
    assert(!p.errors.length, mode + ': errors: ' + p.errors.join('; '));
    await p.ctx.close();
  }
});

await check('haptics on the web: a controller into the hedge gets one short pulse (0.8, 40 ms) on that hand; haptics=0 gives none', async () => {
  const run = async (query) => {
    const p = await openPage(query, { iwer: true });
    await enterVR(p);
    const frames = async (n) => {
      const f0 = await p.state(S.XR_FRAMES);
      await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n, n + ' XR frames', 120000);
    };
    await frames(5);
    // count the pulses at the actuators the page is given
    await p.page.evaluate(() => {
      window.__pulses = [];
      for (const src of Module.holXR.session.inputSources) {
        const a = src.gamepad && src.gamepad.hapticActuators[0];
        if (!a) continue;
        const orig = a.pulse.bind(a);
        a.pulse = (v, d) => { window.__pulses.push([src.handedness, v, d]); return orig(v, d); };
      }
    });
    // the right controller 2 m to the right of the head (the room, 3 x 3 m,
    // is centred on the head at the session's start): into the east hedge
    await p.page.evaluate(() => {
      const c = xrDevice.controllers.right, hp = xrDevice.position;
      c.position.set(hp.x + 2.0, 1.0, hp.z);
    });
    await frames(10);
    const pulses = await p.page.evaluate(() => window.__pulses);
    assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
    await p.ctx.close();
    return pulses;
  };
  const on = await run('?mode=explore&seed=2');
  assert(on.length === 1 && on[0][0] === 'right' && Math.abs(on[0][1] - 0.8) < 1e-6 && on[0][2] === 40,
    'pulses: ' + JSON.stringify(on));
  const off = await run('?mode=explore&seed=2&haptics=0');
  assert(off.length === 0, 'pulses with haptics=0: ' + JSON.stringify(off));
});

// The world panel as a WebXR quad layer (issue 36): iwer's headset with the
// 'layers' feature and Meta's layers polyfill (lib.mjs, layers), as the
// Quest Browser offers them. Every draw of the panel (the C side's, when
// its content changed) is read back from the layer's texture (the
// polyfill's getSubImage colorTexture, through a framebuffer) and compared
// with the same panel drawn into a texture of the test's own: equal, and
// not the image before it. A static layer (isStatic: true) may be drawn
// only while needsRedraw is set: there getSubImage throws at each change
// after the first, and the panel froze.
await check('the world panel as a WebXR quad layer (iwer with the layers polyfill): >= 20 content changes (steps, menu, end screen), each drawn into the layer\'s texture (read back: the panel\'s current image), 0 exceptions; out of the room the panel still (readable), and back in; transparent in front of a trunk nearer than the panel can come (the panel in the eyes, depth-tested), the quad again back in the middle', async () => {
  // a level of 35 s: its end screen ("Time up") is the last change
  fs.writeFileSync(path.join(testDir, 'quad.lvl'), 'mode explore\nseed 2\ntime-limit 35\n');
  const p = await openPage('?level=/test/quad.lvl', { iwer: true, layers: true });
  try {
    await p.page.evaluate(() => {
      const Q = window.__quad = { calls: 0, throws: [], draws: 0, same: 0, stale: 0, repeats: 0, last: null };
      const B = XRWebGLBinding.prototype, get = B.getSubImage;
      B.getSubImage = function (layer, frame, eye) {
        Q.calls++;
        try {
          const sub = get.call(this, layer, frame, eye);
          Q.tex = sub.colorTexture;
          Q.w = sub.viewport.width;
          Q.h = sub.viewport.height;
          return sub;
        } catch (e) {
          Q.throws.push(e.message);
          throw e;
        }
      };
      // a texture's pixels through a framebuffer of the test's own
      const gl = GLctx;
      Q.read = (tex) => {
        const prev = gl.getParameter(gl.FRAMEBUFFER_BINDING), fb = gl.createFramebuffer();
        gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
        gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
        const px = new Uint8Array(Q.w * Q.h * 4);
        gl.readPixels(0, 0, Q.w, Q.h, gl.RGBA, gl.UNSIGNED_BYTE, px);
        gl.bindFramebuffer(gl.FRAMEBUFFER, prev);
        gl.deleteFramebuffer(fb);
        return px;
      };
      // (emscripten's first call of an export replaces Module's function
      // with the wasm's: the wrapper stays, the new function goes under it)
      let inner = Module._hol_web_xr_panel_draw;
      const draw = (fb, w, h) => inner(fb, w, h);
      // the panel of the last step drawn into the test's own texture
      Q.reference = () => {
        if (!Q.ref) {
          Q.ref = gl.createTexture();
          gl.bindTexture(gl.TEXTURE_2D, Q.ref);
          gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, Q.w, Q.h);
          Q.refFb = gl.createFramebuffer();
          Q.refName = GL.getNewId(GL.framebuffers);
          Q.refFb.name = Q.refName;
          GL.framebuffers[Q.refName] = Q.refFb;
          gl.bindFramebuffer(gl.FRAMEBUFFER, Q.refFb);
          gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, Q.ref, 0);
        }
        draw(Q.refName, Q.w, Q.h);
        return Q.read(Q.ref);
      };
      const eq = (a, b) => a && b && a.length === b.length && a.every((v, i) => v === b[i]);
      // the layer's texture right after each of the page's draws
      const wrapper = function (fb, w, h) {
        const r = draw(fb, w, h);
        Q.draws++;
        const got = Q.read(Q.tex);
        if (eq(got, Q.reference())) Q.same++;
        else Q.stale++;
        if (eq(got, Q.last)) Q.repeats++;
        Q.last = got;
        return r;
      };
      Object.defineProperty(Module, '_hol_web_xr_panel_draw', { configurable: true,
        get: () => wrapper, set: (f) => { inner = f; } });
      // the layer's texture now (between frames) against the panel now
      Q.now = () => eq(Q.read(Q.tex), Q.reference());
    });
    await enterVR(p);
    const frames = async (n) => {
      const f0 = await p.state(S.XR_FRAMES);
      await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n, n + ' XR frames', 120000);
    };
    const press = async (hand, id) => {
      await p.page.evaluate((h, b) => xrDevice.controllers[h].updateButtonValue(b, 1), hand, id);
      await frames(3);
      await p.page.evaluate((h, b) => xrDevice.controllers[h].updateButtonValue(b, 0), hand, id);
      await frames(3);
    };
    await frames(5);
    const line = p.log.find((l) => l.startsWith('web: panel '));
    assert(/^web: panel as a WebXR quad layer/.test(line || ''), 'panel line: ' + line);
    // a trunk nearer than the panel can come (issue 36): 0.2 m south of the
    // trunk at the middle cell's north-west corner, looking north, the
    // panel stays at 0.5 m with bark 0.08 m away; the quad (no depth) is
    // transparent and the eyes draw the panel, depth-tested (said once);
    // back at the middle, the quad again
    // (first, while the level plays: the end screen's view no longer walks)
    const alphaNow = () => p.page.evaluate(() => {
      const px = window.__quad.read(window.__quad.tex);
      let a = 0;
      for (let i = 3; i < px.length; i += 4) a = Math.max(a, px[i]);
      return a;
    });
    await p.page.evaluate(() => xrDevice.position.set(-0.45, 1.6, -0.3));
    await frames(40); // the panel's re-centring eases in
    const tAlpha = await alphaNow();
    /* cleared: the draw back in may repeat the image before (no repeat) */
    await p.page.evaluate(() => { window.__quad.last = null; });
    const said = p.log.filter((l) => /^web: xr frame \d+: panel in the scene \(depth-tested\)/.test(l)).length;
    await p.page.evaluate(() => xrDevice.position.set(0, 1.6, 0));
    await frames(40);
    const tBack = await p.page.evaluate(() => window.__quad.now());
    const again = p.log.some((l) => /^web: xr frame \d+: panel as the quad layer again/.test(l));
    console.log(`# behind a trunk: the quad's largest alpha ${tAlpha}, said ${said}; back: the panel's image ${tBack}, said ${again}`);
    assert(tAlpha === 0 && said === 1 && tBack && again,
      `behind a trunk: alpha ${tAlpha}, said ${said}; back: ${tBack}, said ${again}`);
    // walks: 0.8 m north and back, each a room step
    for (const z of [-0.8, 0, -0.8, 0]) {
      const n = await p.state(S.STEPS);
      await p.page.evaluate((zz) => xrDevice.position.set(0, 1.6, zz), z);
      await p.until(async () => (await p.state(S.STEPS)) > n, 'a room step', 30000);
      await frames(3);
    }
    // the menu opened and closed: two changes each
    for (let i = 0; i < 12; i++) await press('left', 'y-button');
    // the level's end screen
    await p.until(async () => (await p.state(S.APP_STATE)) === 2, 'the end screen (time up)', 90000);
    await frames(3);
    const r = await p.page.evaluate(() => {
      const Q = window.__quad;
      return { calls: Q.calls, throws: Q.throws, draws: Q.draws, same: Q.same, stale: Q.stale,
        repeats: Q.repeats, now: Q.now(), redraws: Module._hol_web_xr_panel_redraws() };
    });
    console.log('# ' + JSON.stringify(r));
    if (p.errors.length) console.log('# errors: ' + p.errors.slice(0, 3).join('; '));
    assert(!r.throws.length, `${r.throws.length} getSubImage exceptions: ${r.throws[0]}`);
    assert(r.redraws >= 20, `${r.redraws} content changes`);
    assert(r.draws === r.redraws && r.same === r.draws && !r.stale && !r.repeats,
      `${r.redraws} changes, ${r.draws} draws: ${r.same} the panel's image, ${r.stale} not, ${r.repeats} the image before`);
    assert(r.now, 'the layer\'s texture is not the panel\'s current image');
    // out of the room (issue 36: the view dimmed, not faded out) the quad
    // keeps the panel, readable; back in, the panel again
    await p.page.evaluate(() => xrDevice.position.set(2.6, 1.6, 0));
    await frames(5);
    const outNow = await p.page.evaluate(() => window.__quad.now());
    await p.page.evaluate(() => xrDevice.position.set(0, 1.6, 0));
    await frames(5);
    const back = await p.page.evaluate(() => window.__quad.now());
    console.log(`# out of the room: the quad the panel's image: ${outNow}; back in: ${back}`);
    assert(outNow && back, `out of the room: the panel ${outNow}; back in, the panel: ${back}`);
    assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  } finally {
    await p.ctx.close();
  }
});

// Seated on a Quest 3 (iwer): the head's walk of 0.8 m north takes no step,
// a push of the right thumbstick forward one (held: still one), of the left
// thumbstick right one more; the recording replays on the desktop.
await check('seated on a Quest 3 (?seated=1, iwer): the head walks nothing, each thumbstick push is one room step; the recording replays on the desktop to the same steps', async () => {
  fs.writeFileSync(path.join(testDir, 'seat.lvl'), 'mode explore\nseed 3\n');
  const p = await openPage('?level=/test/seat.lvl&seated=1', { iwer: true });
  try {
    await enterVR(p);
    const frames = async (n) => {
      const f0 = await p.state(S.XR_FRAMES);
      await p.until(async () => (await p.state(S.XR_FRAMES)) >= f0 + n, n + ' XR frames', 120000);
    };
    await frames(5);
    await p.page.evaluate(() => xrDevice.position.set(0, 1.6, -0.8));
    await frames(10);
    assert((await p.state(S.STEPS)) === 0, 'the head walked seated');
    await p.page.evaluate(() => xrDevice.position.set(0, 1.6, 0));
    for (const [hand, x, y, want] of [['right', 0, -1, 1], ['left', 1, 0, 2]]) {
      await p.page.evaluate((h, xx, yy) => xrDevice.controllers[h].updateAxes('thumbstick', xx, yy), hand, x, y);
      await p.until(async () => (await p.state(S.STEPS)) >= want, `step ${want}`, 30000);
      await frames(10);
      await p.page.evaluate((h) => xrDevice.controllers[h].updateAxes('thumbstick', 0, 0), hand);
      await frames(5);
      assert((await p.state(S.STEPS)) === want, `a held push took ${await p.state(S.STEPS)} steps, want ${want}`);
    }
    const dir = path.join(OUT, 'seated-quest');
    fs.rmSync(dir, { recursive: true, force: true });
    fs.mkdirSync(dir);
    for (const [hand, b] of [['left', 'y-button'], ['right', 'b-button']]) { /* the menu, quit */
      await p.page.evaluate((h, bb) => xrDevice.controllers[h].updateButtonValue(bb, 1), hand, b);
      await sleep(300);
      await p.page.evaluate((h, bb) => xrDevice.controllers[h].updateButtonValue(bb, 0), hand, b);
      await sleep(300);
    }
    await p.until(async () => (await p.state(S.OVER)) === 1, 'the session over', 30000);
    const names = await p.page.evaluate(() => window.holonomyStore.names());
    const recName = names.find((n) => /\.rec$/.test(n));
    assert(recName, 'no recording: ' + names.join(' '));
    const rec = await stored(p.page, recName);
    assert(/ f=1[13579bdf][0-9a-f]{2} /.test(rec.toString('utf8')), 'no seated headset record');
    fs.writeFileSync(path.join(dir, 'browser.rec'), rec);
    const r = spawnSync(HOLONOMY, ['replay', path.join(dir, 'browser.rec'), '--log', path.join(dir, 'logs')],
      { encoding: 'utf8' });
    assert(r.status === 0 && / steps 2 /.test(r.stdout), 'replay: ' + r.stdout + r.stderr);
    for (const n of ['summary.csv', 'steps-001.csv']) {
      const b = await stored(p.page, n);
      assert(b.equals(fs.readFileSync(path.join(dir, 'logs', n))), `${n} differs from the replay's`);
    }
    assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
  } finally {
    await p.ctx.close();
  }
});

// ---- WebXR on iwer's Quest 3 -------------------------------------------------
// explore, no minimap: the eyes are the world alone (as `holonomy render` draws it)
const XR_SEED = 11;
fs.writeFileSync(path.join(testDir, 'xr.lvl'), `mode explore\nseed ${XR_SEED}\nminimap off\n`);
const xrOn = !ONLY || ONLY.test('Quest 3');
const xr = xrOn ? await openPage('?level=/test/xr.lvl', { iwer: true }) : {};
const xrState = xr.state, xrPage = xr.page;
const xrFrames = () => xrState(S.XR_FRAMES);
// n more XR frames, or the session's end
async function waitFrames(n) {
  const f0 = await xrFrames();
  await xr.until(() => xrPage.evaluate((f) => !Module.holXR.session ||
    Module._hol_web_state(1) >= f, f0 + n), `${n} XR frames`, 60000);
}
// press an iwer controller button for a few frames (fewer when the press
// ends the session)
async function press(hand, id) {
  await xrPage.evaluate((h, b) => xrDevice.controllers[h].updateButtonValue(b, 1), hand, id);
  await waitFrames(3);
  await xrPage.evaluate((h, b) => xrDevice.controllers[h].updateButtonValue(b, 0), hand, id);
  await waitFrames(2);
}
const xrCounts = () => xrPage.evaluate(() => [1, 2, 3].map((w) => Module._hol_web_state(w)));

await check('Enter VR on a Quest 3 (iwer, stereo): visible and focused, >= 120 XR frames drawn in two viewports', async () => {
  await enterVR(xr);
  await xr.until(async () => (await xrFrames()) >= 120, '120 XR frames', 150000);
  const vis = await xrPage.evaluate(() => Module.holXR.session.visibilityState);
  const [frames, two, focused] = await xrCounts();
  assert(vis === 'visible', 'visibility ' + vis);
  assert(two === frames && focused === frames, `${frames} frames, ${two} with two views, ${focused} focused`);
  assert((await xrState(S.PAUSED)) === 0, 'the game is paused');
  const space = xr.log.find((l) => l.startsWith('web: xr reference space'));
  assert(/bounded-floor|local-floor/.test(space || ''), 'reference space: ' + space);
  await xrPage.screenshot({ path: path.join(OUT, 'xr-stereo.png') });
});

// The world panel (issue 25): iwer 2.5.0's Quest 3 grants no 'layers' (and
// without its polyfill its XRWebGLBinding has no createQuadLayer), so the
// page falls back to the panel in the scene and says why (the quad path:
// the polyfill's check below, and tests/web/quad_check.mjs on stubs).
await check('the world panel on the Quest 3 (iwer has no XRQuadLayer): in the scene, said on the console', async () => {
  const line = xr.log.find((l) => l.startsWith('web: panel '));
  console.log('# ' + line);
  assert(/^web: panel in the scene: (the browser has no XRWebGLBinding.createQuadLayer|the session was not granted the layers feature)$/.test(line || ''),
    'panel line: ' + line);
});

// The tolerance of the eyes against OSMesa: SwiftShader (the browser) and
// llvmpipe (OSMesa) rasterise the same triangles with other rounding; a
// pixel differs when a colour channel is off by more than 12 of 255, and at
// most 1 % of an eye's pixels may differ (a wrong pose, field of view,
// viewport or cell moves far more: tens of percent).
const TOL = 12, MAX_PCT = 1.0;
await check(`each eye read back equals the OSMesa render of the same eye (channel within ${TOL}/255 on ${100 - MAX_PCT} % of pixels)`, async () => {
  // look down 30 degrees and 20 degrees to the left: portals on the floor
  await xrPage.evaluate(() => {
    const y = 20 * Math.PI / 360, p = -30 * Math.PI / 360;
    xrDevice.quaternion.set(Math.cos(y) * Math.sin(p), Math.sin(y) * Math.cos(p),
      -Math.sin(y) * Math.sin(p), Math.cos(y) * Math.cos(p));
  });
  await waitFrames(3);
  const at = (await xrFrames()) + 2;
  await xrPage.evaluate((f) => Module._hol_web_check_request(f), at);
  await xr.until(async () => (await xrFrames()) > at, 'the check frame', 30000);
  const walk = steps(xr.log).map((s) => s.dir).join('') || '-';
  for (let e = 0; e < 2; e++) {
    const line = xr.log.find((l) => l.startsWith(`web: check eye ${e} frame ${at} `));
    assert(line, 'no check line for eye ' + e);
    const m = / render (.*) --size (\d+)x(\d+) cell (\d),(\d)$/.exec(line);
    const w = +m[2], h = +m[3];
    const b64 = await xrPage.evaluate((eye, n) => {
      const p = Module._hol_web_check_pixels(eye);
      let s = '';
      const px = HEAPU8.subarray(p, p + n);
      for (let i = 0; i < px.length; i += 32768) s += String.fromCharCode.apply(null, px.subarray(i, i + 32768));
      return btoa(s);
    }, e, w * h * 4);
    const gl = Buffer.from(b64, 'base64'), got = Buffer.alloc(gl.length);
    for (let y = 0; y < h; y++) gl.copy(got, (h - 1 - y) * w * 4, y * w * 4, (y + 1) * w * 4); // rows top to bottom
    fs.writeFileSync(path.join(OUT, `xr-eye${e}.png`), encodePNG(got, w, h));
    const ref = path.join(OUT, `osmesa-eye${e}.png`);
    const args = ['render', '--walk', walk, '--seed', String(XR_SEED), ...m[1].split(' '),
      '--size', `${w}x${h}`, '--out', ref];
    const r = spawnSync(HOLONOMY, args, { encoding: 'utf8' });
    assert(r.status === 0, `holonomy ${args.join(' ')}: ${r.stderr}`);
    const want = decodePNG(fs.readFileSync(ref));
    assert(want.w === w && want.h === h, 'reference size');
    let bad = 0, worst = 0;
    for (let i = 0; i < w * h; i++) {
      let d = 0;
      for (let k = 0; k < 3; k++) d = Math.max(d, Math.abs(got[i * 4 + k] - want.rgba[i * 4 + k]));
      worst = Math.max(worst, d);
      bad += d > TOL;
    }
    const pct = 100 * bad / (w * h);
    console.log(`# eye ${e} ${w}x${h} (walk ${walk}): ${bad} pixels differ by more than ${TOL}/255 (${pct.toFixed(3)} %), largest ${worst}`);
    assert(pct <= MAX_PCT, `eye ${e}: ${pct.toFixed(2)} % of pixels differ`);
  }
});

// The UI panel (issue 25): at a check frame with the head level, each eye is
// read back without the HUD (slots 0, 1) and as shown (slots 2, 3); the
// pixels that differ are the panel's. Against a pinhole model of the eye's
// pose and tangents and the panel's pose (printed by the page) and its
// documented layout (docs/headset.md: the text block 136 font pixels wide,
// the map 6 + 64 beside it, their tops 32 above the centre).
function turnQ(q, v) {
  const [x, y, z, w] = q;
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]),
    v[2] + w * t[2] + (x * t[1] - y * t[0])];
}
await check('the UI panel in both eyes read back: its left edge where its pose projects and its offset between the eyes its depth\'s, within 1 px; all of it within 20 degrees of each eye\'s axis', async () => {
  /* turned 60 degrees, then level again: the panel re-centres on each
   * (the glide ends within a second), so it stands ahead of the level head */
  await xrPage.evaluate(() => xrDevice.quaternion.set(0, 0.5, 0, Math.sqrt(0.75)));
  await waitFrames(60);
  await xrPage.evaluate(() => xrDevice.quaternion.set(0, 0, 0, 1));
  await waitFrames(60);
  const at = (await xrFrames()) + 2;
  await xrPage.evaluate((f) => Module._hol_web_check_request(f), at);
  await xr.until(async () => (await xrFrames()) > at, 'the check frame', 30000);
  const left = [], pred = [];
  for (let e = 0; e < 2; e++) {
    const eyeLine = xr.log.find((l) => l.startsWith(`web: check eye ${e} frame ${at} `));
    const panLine = xr.log.find((l) => l.startsWith(`web: check panel eye ${e} frame ${at} `));
    assert(eyeLine && panLine, 'no check lines for eye ' + e);
    const m = / --eye (\S+) --orient (\S+) --tan (\S+) --size (\d+)x(\d+)/.exec(eyeLine);
    const eye = m[1].split(',').map(Number), q = m[2].split(',').map(Number);
    const [tl, tr, td, tu] = m[3].split(',').map(Number), w = +m[4], h = +m[5];
    const pm = / pos (\S+) orient (\S+) px (\S+) map (\d)$/.exec(panLine);
    const pos = pm[1].split(',').map(Number), pq = pm[2].split(',').map(Number), px = +pm[3];
    const read = async (slot) => Buffer.from(await xrPage.evaluate((k, n) => {
      const p = Module._hol_web_check_pixels(k);
      let s = '';
      const b = HEAPU8.subarray(p, p + n);
      for (let i = 0; i < b.length; i += 32768) s += String.fromCharCode.apply(null, b.subarray(i, i + 32768));
      return btoa(s);
    }, slot, w * h * 4), 'base64');
    const bare = await read(e), shown = await read(2 + e);
    const img = Buffer.alloc(w * h * 4);
    let n = 0, top = -1, lft = w, worst = 0;
    for (let y = 0; y < h; y++) { /* y from the top; GL's rows bottom to top */
      const r = h - 1 - y;
      shown.copy(img, y * w * 4, r * w * 4, (r + 1) * w * 4);
      for (let x = 0; x < w; x++) {
        const i = (r * w + x) * 4;
        if (bare[i] === shown[i] && bare[i + 1] === shown[i + 1] && bare[i + 2] === shown[i + 2]) continue;
        n++;
        if (top < 0) top = y;
        if (y <= top + 3) lft = Math.min(lft, x); /* the block's first rows, whole pixels across: the first glyph's leftmost column (a T has it only in its top row) */
        const tx = tl + (x + 0.5) / w * (tr - tl), ty = tu - (y + 0.5) / h * (tu - td);
        worst = Math.max(worst, Math.abs(Math.atan(tx)), Math.abs(Math.atan(ty)));
      }
    }
    fs.writeFileSync(path.join(OUT, `xr-panel-eye${e}.png`), encodePNG(img, w, h));
    const u = -(136 + (+pm[4] ? 70 : 0)) / 2 * px, v = 32 * px;
    const rx = turnQ(pq, [1, 0, 0]), up = turnQ(pq, [0, 1, 0]);
    const d = [0, 1, 2].map((k) => pos[k] + u * rx[k] + v * up[k] - eye[k]);
    const c = turnQ([-q[0], -q[1], -q[2], q[3]], d);
    const p = ((c[0] / -c[2]) - tl) / (tr - tl) * w;
    const deg = worst * 180 / Math.PI;
    console.log(`# panel eye ${e} ${w}x${h}: ${n} pixels, left edge ${lft} px (predicted ${p.toFixed(2)}), at most ${deg.toFixed(1)} degrees from the axis`);
    assert(n > 100, `eye ${e}: ${n} panel pixels`);
    assert(c[2] < 0 && Math.abs(lft - p) <= 1, `eye ${e}: left edge ${lft}, predicted ${p.toFixed(2)}`);
    assert(deg <= 20, `eye ${e}: a panel pixel ${deg.toFixed(1)} degrees from the axis`);
    left.push(lft);
    pred.push(p);
  }
  const dm = left[0] - left[1], dp = pred[0] - pred[1];
  console.log(`# panel offset between the eyes ${dm} px (predicted ${dp.toFixed(2)})`);
  assert(dp > 3 && Math.abs(dm - dp) <= 1, `offset ${dm} px, predicted ${dp.toFixed(2)}`);
});

await check('a scripted head walk makes one room step north', async () => {
  await xrPage.evaluate(() => xrDevice.quaternion.set(0, 0, 0, 1));
  const before = steps(xr.log).length;
  // walk 0.8 m north at 0.5 m/s
  await xrPage.evaluate(() => new Promise((done) => {
    const t0 = performance.now();
    const id = setInterval(() => {
      const z = -Math.min(0.8, 0.5 * (performance.now() - t0) / 1000);
      xrDevice.position.set(0, 1.6, z);
      if (z <= -0.8) { clearInterval(id); done(); }
    }, 20);
  }));
  await xr.until(async () => steps(xr.log).length > before, 'a room step', 20000);
  await waitFrames(3);
  const st = steps(xr.log).slice(before);
  assert(st.length === 1 && st[0].dir === 'N' && st[0].row === 0, 'steps: ' + JSON.stringify(st));
  assert(Math.abs((await xrState(S.HEAD_Z)) - 0.7) < 0.02, 'head z ' + (await xrState(S.HEAD_Z)));
});

await check('the reference space\'s reset (the browser\'s recentre) re-places the room: a head jump with it walks no step, the same jump without it does', async () => {
  const before = steps(xr.log).length;
  const has = await xrPage.evaluate(() => {
    const sp = Module.holXR.space;
    if (!sp || !sp.dispatchEvent) return false;
    xrDevice.position.set(0, 1.6, 0.8); /* 1.6 m south in one frame, with the reset */
    sp.dispatchEvent(new Event('reset'));
    return true;
  });
  assert(has, 'the page keeps no reference space with events');
  await waitFrames(10);
  assert(xr.log.some((l) => /reference space reset/.test(l)), 'the reset was not seen');
  assert(steps(xr.log).length === before, 'steps with the reset: ' + JSON.stringify(steps(xr.log).slice(before)));
  await xrPage.evaluate(() => xrDevice.position.set(0, 1.6, -0.8)); /* back, no reset */
  await xr.until(async () => steps(xr.log).length > before, 'steps of the jump without a reset', 20000);
});

// Steps only from a worn, focused, tracked headset (issue 36): a 1.2 m walk
// east with the headset off (hidden), under a system menu (visible-blurred)
// or with the position emulated (tracking lost: the viewer pose's
// emulatedPosition) takes no room step; back in view the room is re-based
// (events.csv: relocated 1.200); the walk back in view is one step west.
await check('Quest 3: a walk while the headset is off, under a system menu or untracked walks no step; the room is re-based and events.csv says relocated 1.200; the walk back in view walks one step', async () => {
  const relocated = async () => ((await stored(xrPage, 'events.csv')) || '').toString()
    .split('\n').filter((l) => /,relocated,/.test(l));
  const walkEast = async () => {
    for (let i = 1; i <= 12; i++) {
      await xrPage.evaluate((x) => xrDevice.position.set(x, 1.6, 0), i / 10);
      await sleep(40);
    }
  };
  const set = {
    hidden: (on) => xrDevice.updateVisibilityState(on ? 'hidden' : 'visible'),
    blurred: (on) => xrDevice.updateVisibilityState(on ? 'visible-blurred' : 'visible'),
    emulated: (on) => {
      const P = XRFrame.prototype;
      if (on) {
        const g = window.__getViewerPose = P.getViewerPose;
        P.getViewerPose = function (sp) {
          const p = g.call(this, sp);
          return p && new Proxy(p, { get: (t, k) => k === 'emulatedPosition' ? true : Reflect.get(t, k) });
        };
      } else {
        P.getViewerPose = window.__getViewerPose;
      }
    },
  };
  await xrPage.evaluate(() => { xrDevice.quaternion.set(0, 0, 0, 1); xrDevice.position.set(0, 1.6, 0); });
  await waitFrames(10);
  for (const how of Object.keys(set)) {
    const before = steps(xr.log).length, ev0 = (await relocated()).length;
    await xrPage.evaluate(`(${set[how].toString()})(true)`);
    await sleep(200);
    await walkEast();
    await sleep(200);
    await xrPage.evaluate(`(${set[how].toString()})(false)`);
    await waitFrames(10);
    const st = steps(xr.log).slice(before), ev = (await relocated()).slice(ev0);
    console.log(`# ${how}: ${st.length} steps, events ${JSON.stringify(ev)}`);
    assert(st.length === 0, `${how}: steps ${JSON.stringify(st)}`);
    assert(ev.length === 1 && /,relocated,1\.200$/.test(ev[0]), `${how}: relocated rows ${JSON.stringify(ev)}`);
    assert((await xrState(S.COL)) === 2, `${how}: the cell's column ${await xrState(S.COL)}`);
    await xrPage.evaluate(() => xrDevice.position.set(0, 1.6, 0)); /* back west, in view */
    await xr.until(async () => steps(xr.log).length > before, `${how}: the walk back's step`, 20000);
    await waitFrames(5);
    const back = steps(xr.log).slice(before);
    assert(back.length === 1 && back[0].dir === 'W', `${how}: back: ${JSON.stringify(back)}`);
  }
  assert(!xr.errors || !xr.errors.length, 'errors: ' + (xr.errors || []).join('; '));
});

// Outside the room (issue 36): the forest dims, the panel stays, an arrow
// on the floor points back in (core decides: hol_app_view.outside);
// events.csv says outside and inside.
await check('Quest 3: outside the room the app says so (the view from the head where it is, dimmed), the floor arrow points back in (west), events.csv says outside once and inside once back in', async () => {
  const rows = async (k) => ((await stored(xrPage, 'events.csv')) || '').toString()
    .split('\n').filter((l) => new RegExp(',' + k + ',').test(l));
  const o0 = (await rows('outside')).length, i0 = (await rows('inside')).length;
  await xrPage.evaluate(() => { xrDevice.quaternion.set(0, 0, 0, 1); xrDevice.position.set(0, 1.6, 0); });
  await waitFrames(10);
  for (const x of [0.6, 1.2, 1.9]) { /* east, out through the east hedge (1.5 m) */
    await xrPage.evaluate((xx) => xrDevice.position.set(xx, 1.6, 0), x);
    await waitFrames(4);
  }
  await waitFrames(5);
  const on = await xrState(S.OUTSIDE), yaw = await xrState(S.ARROW_YAW);
  const o1 = (await rows('outside')).slice(o0);
  await xrPage.screenshot({ path: path.join(OUT, 'xr-outside.png') });
  await xrPage.evaluate(() => xrDevice.position.set(0, 1.6, 0));
  await waitFrames(10);
  const off = await xrState(S.OUTSIDE), i1 = (await rows('inside')).slice(i0);
  console.log(`# outside ${on}, arrow yaw ${yaw}, rows ${JSON.stringify(o1)} / back: ${off}, ${JSON.stringify(i1)}`);
  assert(on === 1 && Math.abs(yaw - 90) < 20, `outside ${on}, arrow yaw ${yaw} (west: 90)`);
  assert(o1.length === 1 && /,outside,0\.4\d\d$/.test(o1[0]), 'outside rows ' + JSON.stringify(o1));
  assert(off === 0 && i1.length === 1 && /,inside,\d+\.\d{3}$/.test(i1[0]), `back in: ${off}, inside rows ${JSON.stringify(i1)}`);
});

// Store-like checks (issue 36; Meta's published rules a page can meet)
await check('store: the first head-tracked frame within 4 s of Enter VR', async () => {
  const line = xr.log.find((l) => /^web: xr first head-tracked frame \d+ ms after Enter VR$/.test(l));
  const ms = line ? +line.split(' ')[5] : NaN;
  console.log('# ' + line);
  assert(ms >= 0 && ms <= 4000, 'first tracked frame: ' + line);
});

await check('store: the frame rate chosen from supportedFrameRates (the highest up to 90 Hz), the session running at it', async () => {
  const r = await xrPage.evaluate(() => {
    const s = Module.holXR.session;
    return { rates: s.supportedFrameRates ? Array.from(s.supportedFrameRates) : null, now: s.frameRate };
  });
  const line = xr.log.find((l) => /^web: xr frame rate/.test(l));
  console.log('# ' + JSON.stringify(r) + ' ' + line);
  assert(r.rates && r.rates.length, 'the session lists no supportedFrameRates');
  const best = Math.max(...r.rates.filter((x) => x <= 90));
  assert(line === `web: xr frame rate ${best} Hz` && r.now === best, `chose ${line}, runs at ${r.now}, want ${best}`);
});

await check('store: pause on hidden: while the session is hidden the level clock stands still and no step is taken; visible again it runs', async () => {
  await xrPage.evaluate(() => xrDevice.position.set(0, 1.6, 0));
  await waitFrames(5);
  const c0 = await xrState(S.CLOCK), s0 = await xrState(S.STEPS);
  await xrPage.evaluate(() => xrDevice.updateVisibilityState('hidden'));
  await sleep(300);
  const c1 = await xrState(S.CLOCK);
  await xrPage.evaluate(() => xrDevice.position.set(0, 1.6, -0.8));
  await sleep(1200);
  const c2 = await xrState(S.CLOCK), s2 = await xrState(S.STEPS);
  await xrPage.evaluate(() => { xrDevice.position.set(0, 1.6, 0); xrDevice.updateVisibilityState('visible'); });
  await waitFrames(20);
  const c3 = await xrState(S.CLOCK);
  console.log(`# clock ${c0} -> hidden ${c1} .. ${c2} (steps ${s0} -> ${s2}) -> visible ${c3}`);
  assert(Math.abs(c2 - c1) < 0.05 && s2 === s0, `hidden: clock ${c1} -> ${c2}, steps ${s0} -> ${s2}`);
  assert(c3 > c2, `visible again: the clock ${c2} -> ${c3}`);
});

await check('controllers reach the app: left stick press recentres, Y opens the menu, the trigger restarts there', async () => {
  await press('left', 'thumbstick');
  const hx = await xrState(S.HEAD_X), hz = await xrState(S.HEAD_Z);
  assert(Math.abs(hx - 1.5) < 0.02 && Math.abs(hz - 1.5) < 0.02, `recentred head at ${hx},${hz}`);
  await press('left', 'y-button');
  assert((await xrState(S.PAUSED)) === 1, 'Y did not open the menu');
  const clock = await xrState(S.CLOCK);
  await press('right', 'trigger');
  assert((await xrState(S.STEPS)) === 0 && (await xrState(S.CLOCK)) < clock, 'the trigger did not restart');
  assert((await xrState(S.PAUSED)) === 0, 'still paused after the restart');
});

let recording = null;
await check('quitting from a controller (Y, then B) ends the session and the logs are offered', async () => {
  await press('left', 'y-button');
  await press('right', 'b-button');
  await xr.until(async () => (await xrState(S.OVER)) === 1, 'the session over');
  await xr.until(() => xrPage.evaluate(() => !Module.holXR.session), 'the XR session to end');
  const offered = await xrPage.evaluate(() => ({
    shown: !document.getElementById('logs').hidden,
    links: Array.from(document.querySelectorAll('#loglist a')).map((a) => a.textContent),
    names: window.holonomyStore.names(),
  }));
  assert(offered.shown && offered.links.length > 0, 'logs not offered: ' + JSON.stringify(offered));
  // over in VR: the status says so after the XR session ended; no Enter VR, Play again
  const st = await xrPage.evaluate(() => document.getElementById('status').textContent);
  const vb = await vrButton(xr);
  assert(/^Session over/.test(st) && vb.hidden && vb.again, `over in VR: status '${st}', ` + JSON.stringify(vb));
  const rec = offered.names.find((n) => /\.rec$/.test(n));
  assert(rec, 'no recording among ' + offered.names.join(', '));
  recording = Buffer.from(await xrPage.evaluate((n) => {
    const b = window.holonomyStore.bytes(n); /* by parts: apply() takes no 100 KB array */
    let s = '';
    for (let i = 0; i < b.length; i += 32768) s += String.fromCharCode.apply(null, b.subarray(i, i + 32768));
    return btoa(s);
  }, rec), 'base64');
  fs.writeFileSync(path.join(OUT, 'browser.rec'), recording);
  // iwer leaves its (empty) full-page container over the page
  await xrPage.evaluate(() => document.querySelector('[data-webxr_runtime]')?.remove());
  await sleep(200);
  await xrPage.screenshot({ path: path.join(OUT, 'xr-over.png') });
  assert(!xr.errors.length, 'errors: ' + xr.errors.join('; '));
});

await check('environment.csv (issue 26): Enter VR on the Quest 3 writes a row, platform webxr: the emulated controller (webxr-touch), the refresh rate, the eye\'s size, the page\'s session', async () => {
  const rows = (await envRows(xrPage)) || [];
  const session = sessionOf(xr), vr = rows.filter((r) => r.platform === 'webxr');
  console.log('# ' + JSON.stringify(vr));
  assert(vr.length === 1 && rows.every((r) => r.session === session && /^webx?r?$/.test(r.platform)) &&
    rows.length <= 2, `rows (one webxr, session ${session}): ` + JSON.stringify(rows));
  const r = vr[0];
  assert(r.controller === 'webxr-touch', 'controller: ' + r.controller);
  assert(/^\d+\.\d{3}$/.test(r.refresh_hz) && +r.refresh_hz > 0, 'refresh_hz: ' + r.refresh_hz);
  assert(r.width === String(W / 2) && r.height === String(H), `eye ${r.width}x${r.height}`);
  // iwer gives the page the Quest 3's user agent (OculusBrowser/33.0.0.x.x.x)
  // and XRSession.frameRate (its nominal 90 Hz)
  assert(/Quest 3/.test(r.os) && r.runtime === 'OculusBrowser/33.0.0' && r.refresh_hz === '90.000' &&
    /SwiftShader/.test(r.gl_renderer) && r.options === 'level=/test/xr.lvl',
    'os, runtime, refresh_hz, gl_renderer, options: ' + JSON.stringify(r));
});

await check('the browser recording replays on the desktop to the same step rows and summary, byte for byte', async () => {
  assert(recording, 'no recording');
  const end = xr.log.find((l) => l.startsWith('level '));
  const logs = path.join(OUT, 'replay-logs');
  fs.rmSync(logs, { recursive: true, force: true });
  fs.mkdirSync(logs);
  const r = spawnSync(HOLONOMY, ['replay', path.join(OUT, 'browser.rec'), '--log', logs],
    { encoding: 'utf8' });
  assert(r.status === 0, 'replay: ' + r.stderr);
  assert(r.stdout.trim() === end, `replay says '${r.stdout.trim()}', the browser '${end}'`);
  // the provenance files (docs/logs.md, Provenance and codebook): the page
  // writes them as the desktop does, codebook.csv the same bytes;
  // provenance.csv names each one's build, so it is not compared
  const own = new Set(['provenance.csv']);
  const names = fs.readdirSync(logs).filter((n) => /\.csv$/.test(n) && !own.has(n)).sort();
  assert(names.includes('summary.csv') && names.includes('steps-001.csv') &&
    names.includes('steps-002.csv'), 'replay logs: ' + names.join(' '));
  const dir = path.join(OUT, 'browser-logs');
  fs.mkdirSync(dir, { recursive: true });
  for (const n of names) {
    const b = await stored(xrPage, n);
    assert(b, 'the browser has no ' + n);
    fs.writeFileSync(path.join(dir, n), b);
    assert(b.equals(fs.readFileSync(path.join(logs, n))), n + ' differs from the replay\'s');
  }
  const summary = fs.readFileSync(path.join(logs, 'summary.csv'), 'utf8').trim().split('\n');
  assert(summary.length === 3 && /,restart,,,$/.test(summary[1]) && /,quit,,,$/.test(summary[2]),
    'summary: ' + summary.join(' | '));
  console.log(`# ${names.length} log files equal: ${names.join(' ')}`);
});
if (xrOn) await xr.ctx.close();

// ---- dusk and night in WebXR (issue 27) ---------------------------------------
// A level with a lantern on N at dusk and at night, in {4,5} and {4,6}, on
// iwer's headset looking north 25 degrees down: both eyes read back (saved
// as xr-light-*.png with the page's screenshot) and checked against a
// pinhole of each eye's printed pose (the glass 1.3 m over N's centre, at
// 1.5, 1.3, 0.5) and against `holonomy render` of the same eye.
function lightLuma(px, w, h) {
  let sum = 0;
  for (let i = 0; i < w * h; i++) sum += 0.299 * px[4 * i] + 0.587 * px[4 * i + 1] + 0.114 * px[4 * i + 2];
  return sum / (w * h);
}
function lightProject(p, eye, q, [tl, tr, td, tu], w, h) {
  const c = turnQ([-q[0], -q[1], -q[2], q[3]], [p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]]);
  if (c[2] >= 0) return null;
  return [(c[0] / -c[2] - tl) / (tr - tl) * w, (tu - c[1] / -c[2]) / (tu - td) * h];
}
const dayRenders = new Map(); /* holonomy render --lighting day, by its arguments */
for (const q of [5, 6]) for (const sky of ['dusk', 'night']) {
  await check(`WebXR {4,${q}} at ${sky} with a lantern, both eyes: the glass glows where each eye's pose projects it, further right in the left eye by the projections' offset (within 1 px); ` +
    `the eyes darker than the day render of the same pose${sky === 'night' ? ' by half' : ''}; each equals holonomy render --lighting ${sky} --lantern N of its eye (channel within ${TOL}/255 on ${100 - MAX_PCT} % of pixels)`, async () => {
    const name = `light-q${q}-${sky}`;
    fs.writeFileSync(path.join(testDir, name + '.lvl'),
      `mode explore\nseed 5\nminimap off\ncues none\ntiling 4 ${q}\nlighting ${sky}\nplace lantern N\n`);
    const p = await openPage(`?level=/test/${name}.lvl`, { iwer: true });
    try {
      await enterVR(p);
      const a = Math.sin(-12.5 * Math.PI / 180), b = Math.cos(-12.5 * Math.PI / 180);
      await p.page.evaluate((x, w) => xrDevice.quaternion.set(x, 0, 0, w), a, b);
      await p.until(async () => (await p.state(S.XR_FRAMES)) >= 10, '10 XR frames', 60000);
      const at = (await p.state(S.XR_FRAMES)) + 2;
      await p.page.evaluate((f) => Module._hol_web_check_request(f), at);
      await p.until(async () => (await p.state(S.XR_FRAMES)) > at, 'the check frame', 30000);
      await p.page.screenshot({ path: path.join(OUT, `xr-${name}-page.png`) });
      const glass = [], proj = [];
      for (let e = 0; e < 2; e++) {
        const line = p.log.find((l) => l.startsWith(`web: check eye ${e} frame ${at} `));
        assert(line, 'no check line for eye ' + e);
        const m = / render (--fireflies \S+ --eye (\S+) --orient (\S+) --tan (\S+)) --size (\d+)x(\d+) cell (\d),(\d)$/.exec(line);
        const w = +m[5], h = +m[6];
        assert(m[7] === '1' && m[8] === '1', 'not in the middle cell: ' + line);
        const b64 = await p.page.evaluate((eye, n) => {
          const px = HEAPU8.subarray(Module._hol_web_check_pixels(eye), Module._hol_web_check_pixels(eye) + n);
          let s = '';
          for (let i = 0; i < px.length; i += 32768) s += String.fromCharCode.apply(null, px.subarray(i, i + 32768));
          return btoa(s);
        }, e, w * h * 4);
        const gl = Buffer.from(b64, 'base64'), got = Buffer.alloc(gl.length);
        for (let y = 0; y < h; y++) gl.copy(got, (h - 1 - y) * w * 4, y * w * 4, (y + 1) * w * 4);
        fs.writeFileSync(path.join(OUT, `xr-${name}-eye${e}.png`), encodePNG(got, w, h));
        const render = (lighting, out) => {
          const args = ['render', '--walk', '-', '--seed', '5', '--tiling', `4,${q}`, ...m[1].split(' '),
            '--size', `${w}x${h}`, '--lighting', lighting, '--lantern', 'N', '--out', out];
          // the day render of a pose is made once (dusk's and night's checks share it)
          const key = lighting === 'day' ? args.slice(0, -1).join(' ') : null;
          if (key && dayRenders.has(key)) return dayRenders.get(key);
          const r = spawnSync(HOLONOMY, args, { encoding: 'utf8' });
          assert(r.status === 0, `holonomy ${args.join(' ')}: ${r.stderr}`);
          const img = decodePNG(fs.readFileSync(out));
          assert(img.w === w && img.h === h, 'reference size');
          if (key) dayRenders.set(key, img.rgba);
          return img.rgba;
        };
        const want = render(sky, path.join(OUT, `osmesa-${name}-eye${e}.png`));
        const day = render('day', path.join(OUT, `osmesa-${name}-day-eye${e}.png`));
        let bad = 0;
        for (let i = 0; i < w * h; i++) {
          let d = 0;
          for (let k = 0; k < 3; k++) d = Math.max(d, Math.abs(got[i * 4 + k] - want[i * 4 + k]));
          bad += d > TOL;
        }
        const pct = 100 * bad / (w * h);
        const mean = lightLuma(got, w, h), dayMean = lightLuma(day, w, h);
        const pr = lightProject([1.5, 1.3, 0.5], m[2].split(',').map(Number), m[3].split(',').map(Number),
          m[4].split(',').map(Number), w, h);
        assert(pr, `eye ${e}: the glass is behind the eye`);
        let n = 0, sx = 0;
        for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
          const i = 4 * (y * w + x);
          if (Math.hypot(x + 0.5 - pr[0], y + 0.5 - pr[1]) <= 16 &&
            0.299 * got[i] + 0.587 * got[i + 1] + 0.114 * got[i + 2] >= 200) { n++; sx += x + 0.5; }
        }
        glass.push(n ? sx / n : NaN);
        proj.push(pr[0]);
        console.log(`# ${name} eye ${e} ${w}x${h}: mean luma ${mean.toFixed(1)} (day ${dayMean.toFixed(1)}), glass ${n} px at x ${(sx / n).toFixed(2)} (projected ${pr[0].toFixed(2)},${pr[1].toFixed(2)}), ${pct.toFixed(3)} % off the render`);
        assert(pct <= MAX_PCT, `eye ${e}: ${pct.toFixed(2)} % of pixels differ from the render`);
        assert(mean < (sky === 'night' ? 0.5 : 0.9) * dayMean, `eye ${e}: mean luma ${mean.toFixed(1)}, day ${dayMean.toFixed(1)}`);
        assert(n >= 5 && Math.abs(sx / n - pr[0]) <= 2, `eye ${e}: ${n} glowing pixels at x ${sx / n}, projected ${pr[0]}`);
      }
      const dm = glass[0] - glass[1], dp = proj[0] - proj[1];
      assert(dp > 0.5 && dm > 0 && Math.abs(dm - dp) <= 1, `offset between the eyes ${dm}, projected ${dp}`);
      assert(!p.errors.length, 'errors: ' + p.errors.join('; '));
    } finally {
      await p.ctx.close();
    }
  });
}

await browser.close();
server.close();
const secs = (Date.now() - t0) / 1000;
console.log(`web-test: ${passed} passed, ${failed} failed in ${secs.toFixed(0)} s` +
  (failed ? ` (artifacts in ${OUT})` : ''));
if (!failed && !process.env.WEB_TEST_OUT) fs.rmSync(tmp, { recursive: true, force: true });
else fs.rmSync(path.join(tmp, 'profile'), { recursive: true, force: true });
process.exit(failed ? 1 : 0);
