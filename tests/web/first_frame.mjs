// first_frame.mjs - the first frame from page load of two builds of the web,
// interleaved in one browser so both see the same load (issue 25: the
// figures of docs/performance.md, "The transfer size and the first frame").
// Usage: node tests/web/first_frame.mjs DIR_BEFORE DIR_AFTER [LOADS]
// For each build, per load of ?mode=flag&seed=1..LOADS (default 5): the
// page's own line (web: first frame N ms ...: its phases) and the CPU of all
// chromium's processes for the load; prints the medians.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { launch, openPage, serve } from './lib.mjs';

const [dirA, dirB] = process.argv.slice(2, 4).map((d) => path.resolve(d));
const LOADS = +(process.argv[4] || 5);
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const median = (a) => a.slice().sort((x, y) => x - y)[a.length >> 1];
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'holonomy-first-frame-'));

function chromiumCpu(root) {
  const kids = new Map();
  for (const d of fs.readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const st = fs.readFileSync(`/proc/${d}/stat`, 'utf8');
      const f = st.slice(st.lastIndexOf(')') + 2).split(' ');
      kids.set(+d, { ppid: +f[1], cpu: (+f[11] + +f[12]) / 100 });
    } catch (e) { /* gone */ }
  }
  let total = 0;
  for (const [pid, k] of kids) {
    for (let p = pid, n = 0; p > 1 && n < 64; n++, p = kids.get(p)?.ppid)
      if (p === root) { total += k.cpu; break; }
  }
  return total;
}

const builds = [];
for (const dir of [dirA, dirB]) {
  const td = path.join(tmp, 'serve' + builds.length);
  fs.mkdirSync(td);
  const gz = fs.readdirSync(dir).reduce((a, f) => a + zlib.gzipSync(fs.readFileSync(path.join(dir, f)), { level: 9 }).length, 0);
  builds.push({ dir, gz, server: await serve(dir, td), first: [], parts: [[], [], [], [], []], cpu: [] });
}
const browser = await launch(CHROMIUM, path.join(tmp, 'profile'), 800, 600);
try {
  const pid0 = browser.process().pid;
  for (let i = 0; i <= LOADS; i++) { /* load 0 of each: warm-up, not counted */
    for (const b of builds) {
      const c0 = chromiumCpu(pid0);
      const p = await openPage(browser, b.server.base + '/?mode=flag&seed=' + Math.max(1, i));
      await p.until(() => p.log.find((l) => l.startsWith('web: first frame')), 'the first frame', 120000);
      const cpu = chromiumCpu(pid0) - c0;
      const line = p.log.find((l) => l.startsWith('web: first frame'));
      await p.ctx.close();
      if (i === 0) continue;
      b.first.push(+/(\d+) ms/.exec(line)[1]);
      b.cpu.push(cpu);
      const m = /main at (\d+) ms .* GL context (\d+) ms, the game .* (\d+) ms, the renderer (\d+) ms, the first frame (\d+) ms/.exec(line);
      if (m) for (let k = 0; k < 5; k++) b.parts[k].push(+m[k + 1]);
    }
  }
  for (const b of builds)
    console.log(`${b.dir}: ${(b.gz / 1024).toFixed(1)} KB gzip -9; first frame median ${median(b.first)} ms ` +
      `(loads ${b.first.join(', ')}); main at ${median(b.parts[0])}, GL ${median(b.parts[1])}, the game ${median(b.parts[2])}, ` +
      `the renderer ${median(b.parts[3])}, the frame ${median(b.parts[4])} ms; chromium CPU ${(median(b.cpu) * 1000).toFixed(0)} ms a load ` +
      `(loads ${b.cpu.map((c) => (c * 1000).toFixed(0)).join(', ')})`);
} finally {
  await browser.close();
  for (const b of builds) b.server.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
