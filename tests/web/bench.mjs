// bench.mjs - the web build's figures for make bench (README: Performance):
// - the app step and the navigator's table build, the same C natively and in
//   wasm under node (tests/bench_web.c), and their ratio;
// - the first frame from the navigation's start in headless chromium
//   (SwiftShader): the median of FIRST_LOADS (default 5) first visits, its
//   phases' wall time and (traced loads) CPU;
// - the compressed transfer size of build/web (gzip -9 and brotli);
// - the main thread per pancake and XR frame with the per-frame glGetError
//   (?gldebug=1, as before it was taken out of the frame path) and without;
// - CPU per XR frame at 800x600 on iwer's Quest 3 under SwiftShader: the
//   page's main thread (step and both eyes' GL calls issued) and all of
//   chromium's processes together (/proc: browser, renderer, GPU process
//   where SwiftShader rasterises);
// - the same per XR frame at night (eight lanterns) against day, one level
//   each, in the same run.
// - with WEB_BEFORE (another build's folder): the XR frame's main thread of
//   this build against that one's, interleaved (XR_PAIRS pairs).
// Environment: BENCH_NATIVE, BENCH_WASM (the two builds of bench_web), WEB,
// CHROMIUM, FIRST_LOADS, NIGHT_ONLY (night against day alone, after the
// wasm and transfer figures), NIGHT_PAIRS, NIGHT_FRAMES, WEB_BEFORE, XR_PAIRS.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { spawnSync } from 'node:child_process';
import { enterVR, firstFrameLoad, firstFrameReport, launch, median, openPage, processTreeCpu, serve } from './lib.mjs';

const WEB = path.resolve(process.env.WEB || 'build/web');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'holonomy-web-bench-'));

function figures(cmd, args) {
  const r = spawnSync(cmd, args, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${cmd}: ${r.stderr}`);
  return Object.fromEntries(r.stdout.trim().split('\n').map((l) => l.split(' ')))
}

console.log('== web: the app step and the navigator, native and wasm (node ' + process.version + '), in one run');
const runs = { native: [], wasm: [] };
for (let i = 0; i < 3; i++) { /* interleaved: both see the same load */
  runs.native.push(figures(process.env.BENCH_NATIVE, []));
  runs.wasm.push(figures(process.execPath, [process.env.BENCH_WASM]));
}
const hash = new Set([...runs.native, ...runs.wasm].map((f) => f.view_hash));
const pick = (k, which) => median(runs[which].map((f) => +f[k]));
for (const k of ['nav_build_ms', 'step_cpu_mean_us', 'step_p99_us', 'step_max_us']) {
  const n = pick(k, 'native'), w = pick(k, 'wasm');
  console.log(`  ${k.padEnd(16)} native ${n.toFixed(2).padStart(9)}  wasm ${w.toFixed(2).padStart(9)}  wasm/native ${(w / n).toFixed(2)}`);
}
console.log(`  (medians of 3 runs; ${runs.native[0].frames} frames, ${runs.native[0].room_steps} room steps after a warm-up walk; ` +
  `target for the step: 2x or better) the same final view natively and in wasm: ${hash.size === 1 ? 'yes' : 'NO'}`);

console.log('== web: transfer size of build/web');
let raw = 0, gz = 0, br = 0;
for (const f of fs.readdirSync(WEB)) {
  const b = fs.readFileSync(path.join(WEB, f));
  raw += b.length;
  gz += zlib.gzipSync(b, { level: 9 }).length;
  br += zlib.brotliCompressSync(b, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11 } }).length;
}
console.log(`  ${fs.readdirSync(WEB).length} files: ${(raw / 1024).toFixed(0)} KB, gzip -9 ${(gz / 1024).toFixed(0)} KB, ` +
  `brotli ${(br / 1024).toFixed(0)} KB (target and make web-test's budget: at most 180 KB gzip -9)`);

const chromiumCpu = processTreeCpu;

console.log('== web: headless chromium ' + spawnSync(CHROMIUM, ['--version'], { encoding: 'utf8' }).stdout.trim() + ', SwiftShader');
const server = await serve(WEB, tmp);
const browser = await launch(CHROMIUM, path.join(tmp, 'profile'), 800, 600);
try {
  if (!process.env.WEB_BEFORE) { /* the comparison alone with WEB_BEFORE */
    const pid = browser.process().pid;
    if (!process.env.NIGHT_ONLY) { /* NIGHT_ONLY=1: night against day alone */
    // the first frame (lib.mjs firstFrameLoad): FIRST_LOADS first visits of
    // ?mode=flag&seed=1..N after a warm-up load, and three traced for the
    // phases' CPU
    const N = +(process.env.FIRST_LOADS || 5), loads = [], traced = [];
    await firstFrameLoad(browser, server.base + '/?mode=flag&seed=1');
    for (let i = 0; i < N; i++) {
      loads.push(await firstFrameLoad(browser, server.base + '/?mode=flag&seed=' + (i + 1)));
      if (i < 3) traced.push(await firstFrameLoad(browser, server.base + '/?mode=flag&seed=' + (i + 1), { trace: true }));
    }
    for (const line of firstFrameReport(loads, traced)) console.log(line);
    // the main thread per frame with the frame path's error check (?gldebug=1:
    // glGetError after every eye, as every frame did before it was taken out)
    // and without (normal running), pancake and XR, in this one run
    for (const [label, q] of [['with glGetError per frame (before)', '&gldebug=1'], ['normal running (after)', '']]) {
      const d = await openPage(browser, server.base + '/?mode=flag&seed=1' + q, { iwer: true });
      const mean = async (frames, n) => {
        await d.until(async () => (await frames()) >= 10, 'warm-up frames', 120000);
        await d.page.evaluate(() => Module._hol_web_cpu_mean_ms(1));
        const f0 = await frames();
        await d.until(async () => (await frames()) >= f0 + n, n + ' frames', 240000);
        return d.page.evaluate(() => Module._hol_web_cpu_mean_ms(1));
      };
      const pan = await mean(() => d.state(0), 60);
      await enterVR(d);
      const xrm = await mean(() => d.state(1), 60);
      console.log(`  main thread per frame, ${label}: pancake ${pan.toFixed(2)} ms, XR (both eyes) ${xrm.toFixed(2)} ms (means of 60 frames)`);
      await d.ctx.close();
    }
    const p = await openPage(browser, server.base + '/?mode=flag&seed=1', { iwer: true });
    await enterVR(p);
    await p.until(async () => (await p.state(1)) >= 60, 'warm-up XR frames', 120000);
    const c0 = chromiumCpu(pid), f0 = await p.state(1), t0 = Date.now();
    await p.page.evaluate(() => Module._hol_web_xr_cpu_reset());
    await p.until(async () => (await p.state(1)) >= f0 + 120, '120 XR frames', 180000);
    const c1 = chromiumCpu(pid), f1 = await p.state(1), secs = (Date.now() - t0) / 1000;
    const [n, med, p99] = await p.page.evaluate(() => [0, 1, 2].map((w) => Module._hol_web_xr_cpu_ms(w)));
    const size = await p.page.evaluate(() => [Module.canvas.width, Module.canvas.height]);
    console.log(`  XR frames at ${size[0]}x${size[1]} (two eyes of ${size[0] / 2}x${size[1]}): ${((f1 - f0) / secs).toFixed(1)} frames/s`);
    console.log(`  main thread per XR frame (app step, both eyes' GL calls issued): median ${med.toFixed(2)} ms, p99 ${p99.toFixed(2)} ms over ${n} frames`);
    console.log(`  all chromium processes per XR frame (incl. SwiftShader rasterising): ${((c1 - c0) / (f1 - f0) * 1000).toFixed(1)} ms CPU`);
    await p.ctx.close();
    }
    // night against day in this run (issue 27): the same explore level with
    // eight lanterns, at day (lanterns not drawn) and at night, on iwer's
    // Quest 3 at 800x600, interleaved day, night, day, night so both see the
    // same load: the main thread per XR frame and all chromium's processes
    // (SwiftShader runs the lit fragment shader on the CPU)
    const lanterns = ['O', 'N', 'E', 'S', 'W', 'Nf', 'Ef', 'Sf'].map((a) => `place lantern ${a}\n`).join('');
    for (const sky of ['day', 'night'])
      fs.writeFileSync(path.join(tmp, `bench-${sky}.lvl`), `mode explore\nseed 3\nminimap off\nlighting ${sky}\n${lanterns}`);
    const sky = { day: { main: [], all: [] }, night: { main: [], all: [] } };
    // NIGHT_PAIRS (default 2) pairs of a day run then a night run
    const pairs = Math.max(1, +(process.env.NIGHT_PAIRS || 2));
    // NIGHT_FRAMES (default 90) XR frames a run after the warm-up: more
    // frames, less noise from the page's start
    const nightFrames = Math.max(30, +(process.env.NIGHT_FRAMES || 90));
    for (const s of Array.from({ length: 2 * pairs }, (_, i) => (i % 2 ? 'night' : 'day'))) {
      const q = await openPage(browser, server.base + `/?level=/test/bench-${s}.lvl`, { iwer: true });
      await enterVR(q);
      await q.page.evaluate(() => xrDevice.quaternion.set(-0.2164, 0, 0, 0.9763)); /* 25 degrees down: the lit floor */
      await q.until(async () => (await q.state(1)) >= 30, 'warm-up XR frames', 120000);
      const a0 = chromiumCpu(pid), g0 = await q.state(1);
      await q.page.evaluate(() => Module._hol_web_xr_cpu_reset());
      await q.until(async () => (await q.state(1)) >= g0 + nightFrames, nightFrames + ' XR frames', 600000);
      const a1 = chromiumCpu(pid), g1 = await q.state(1);
      sky[s].main.push(await q.page.evaluate(() => Module._hol_web_xr_cpu_ms(1)));
      sky[s].all.push((a1 - a0) / (g1 - g0) * 1000);
      await q.ctx.close();
    }
    const avg = (a) => a.reduce((x, y) => x + y, 0) / a.length;
    for (const [k, label] of [['main', 'main thread per XR frame (median of each run)'], ['all', 'all chromium processes per XR frame (CPU)']])
      console.log(`  night (8 lanterns) against day, ${label}: day ${avg(sky.day[k]).toFixed(2)} ms, night ${avg(sky.night[k]).toFixed(2)} ms, ` +
        `night/day ${(avg(sky.night[k]) / avg(sky.day[k])).toFixed(2)} (runs: day ${sky.day[k].map((v) => v.toFixed(1)).join(', ')}; night ${sky.night[k].map((v) => v.toFixed(1)).join(', ')})`);
    const ratios = sky.night.all.map((v, i) => v / sky.day.all[i]);
    console.log(`  night/day of all chromium's CPU, each pair: ${ratios.map((v) => v.toFixed(2)).join(', ')}; median ${median(ratios).toFixed(2)}`);
  }
  // WEB_BEFORE=DIR (another build of the page, e.g. an older tree's
  // build/web; the browser's figures above are then left out): the XR
  // frame's main thread of this build against that one's, interleaved
  // (before, after, before, after, ...: each pair sees the same load),
  // XR_PAIRS pairs (default 8), each the mean of XR_FRAMES (default 120)
  // XR frames of ?mode=flag&seed=1 on iwer's Quest 3 after 60 warm-up
  // frames (the page's clock has 0.1 ms steps: a mean of many frames, not
  // a median); the median of the pairs' ratios is the figure (a pair hit
  // by another process's burst is one ratio of many)
  if (process.env.WEB_BEFORE) {
    const before = await serve(path.resolve(process.env.WEB_BEFORE), tmp);
    const runs = { before: [], after: [] };
    const xrPairs = Math.max(1, +(process.env.XR_PAIRS || 8));
    const xrFrames = Math.max(30, +(process.env.XR_FRAMES || 120));
    try {
      for (let i = 0; i < 2 * xrPairs; i++) {
        const which = i % 2 ? 'after' : 'before';
        const q = await openPage(browser, (i % 2 ? server : before).base + '/?mode=flag&seed=1', { iwer: true });
        await enterVR(q);
        await q.until(async () => (await q.state(1)) >= 60, 'warm-up XR frames', 120000);
        await q.page.evaluate(() => Module._hol_web_cpu_mean_ms(1));
        const f0 = await q.state(1);
        await q.until(async () => (await q.state(1)) >= f0 + xrFrames, xrFrames + ' XR frames', 300000);
        runs[which].push(await q.page.evaluate(() => Module._hol_web_cpu_mean_ms(1)));
        await q.ctx.close();
      }
    } finally {
      before.close();
    }
    const ratios = runs.after.map((v, i) => v / runs.before[i]);
    console.log(`  main thread per XR frame, this build against WEB_BEFORE (${process.env.WEB_BEFORE}), interleaved: ` +
      `after/before ${median(ratios).toFixed(3)} (median of ${ratios.length} pairs: ${ratios.map((v) => v.toFixed(2)).join(', ')}); ` +
      `medians before ${median(runs.before).toFixed(3)} ms, after ${median(runs.after).toFixed(3)} ms ` +
      `(each a mean of ${xrFrames} frames; runs: before ${runs.before.map((v) => v.toFixed(3)).join(', ')}; after ${runs.after.map((v) => v.toFixed(3)).join(', ')}; ` +
      `load average ${os.loadavg()[0].toFixed(1)})`);
  }
  console.log(`  (machine: ${os.cpus().length} cores, load average ${os.loadavg()[0].toFixed(1)})`);
} finally {
  await browser.close();
  server.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
