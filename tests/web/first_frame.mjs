// first_frame.mjs - the web's first frame (docs/performance.md, "The web's
// first frame"), of one build or of two interleaved in one browser so both
// see the same load.
// Usage: node tests/web/first_frame.mjs DIR [DIR_AFTER] [LOADS]
// Per build, LOADS (default 5) loads of ?mode=flag&seed=1..LOADS after one
// warm-up load (not counted), each a first visit (lib.mjs firstFrameLoad),
// and as many traced: the medians of the first frame and of each phase's
// wall time (untraced loads) and of its CPU (traced: the page's main
// thread, the GPU process, all of chromium).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { firstFrameLoad, firstFrameReport, launch, serve } from './lib.mjs';

const args = process.argv.slice(2);
const LOADS = /^\d+$/.test(args[args.length - 1] || '') ? +args.pop() : 5;
const dirs = args.map((d) => path.resolve(d));
if (!dirs.length || dirs.length > 2) {
  console.error('usage: node tests/web/first_frame.mjs DIR [DIR_AFTER] [LOADS]');
  process.exit(2);
}
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'holonomy-first-frame-'));

const builds = [];
for (const dir of dirs) {
  const td = path.join(tmp, 'serve' + builds.length);
  fs.mkdirSync(td);
  const gz = fs.readdirSync(dir).reduce((a, f) => a + zlib.gzipSync(fs.readFileSync(path.join(dir, f)), { level: 9 }).length, 0);
  builds.push({ dir, gz, server: await serve(dir, td), loads: [], traced: [] });
}
const browser = await launch(CHROMIUM, path.join(tmp, 'profile'), 800, 600);
try {
  for (let i = 0; i <= LOADS; i++) /* load 0 of each: warm-up, not counted */
    for (const b of builds)
      for (const trace of [false, true]) {
        const l = await firstFrameLoad(browser, b.server.base + '/?mode=flag&seed=' + Math.max(1, i), { trace });
        if (i) (trace ? b.traced : b.loads).push(l);
      }
  for (const b of builds) {
    console.log(`${b.dir}: ${(b.gz / 1024).toFixed(1)} KB gzip -9`);
    for (const line of firstFrameReport(b.loads, b.traced)) console.log(line);
  }
  console.log(`(machine: ${os.cpus().length} cores, load average ${os.loadavg().map((x) => x.toFixed(1)).join(' ')})`);
} finally {
  await browser.close();
  for (const b of builds) b.server.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
