// frag_bench.mjs - the lit tiles' fragment shader alone under SwiftShader
// (docs/performance.md#lighting): `node tests/web/frag_bench.mjs [DIR...]`
// draws a tile lit by four lights full-screen at 800x600 with each folder's
// scene.vert.glsl, scene.frag.glsl and falloff.glsl (default
// render/shaders; give several to compare variants), the program of a night
// with fireflies and a shadow mask (FX=0 none, FX=2 spots; FLAT=1 {4,4}),
// then the day program; depth and stencil tests on as in the tile pass
// (STATE=0 off); ROOM=1: the lit room's program (its trees and hedges, lit
// per vertex) instead of the tiles'; FLOOR=1: the tiles' ground's (normal
// straight up); SPLIT=K: each draw as K draws of a horizontal strip each
// (scissored: the cost of a draw itself), UNI=1 with u_tx set before each.
// ROUNDS (default 5) rounds of DRAWS (default 60) draws, each folder in
// turn; the figure is all chromium processes' CPU per draw,
// the median of the rounds, and the picture's mean code (equal means: most
// likely the same picture). The preamble's constants are read from the
// headers (render/hol_program.c's hol_prog_preamble writes the real one).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launch, median, processTreeCpu } from './lib.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const dirs = process.argv.length > 2 ? process.argv.slice(2) : [path.join(root, 'render/shaders')];
const env = (k, d) => +(process.env[k] ?? d);
const ROUNDS = env('ROUNDS', 5), DRAWS = env('DRAWS', 60), FX = env('FX', 1), FLAT = env('FLAT', 0);
const STATE = env('STATE', 1), ROOM = env('ROOM', 0), FLOOR = env('FLOOR', 0);
const hdr = ['render/hol_light.h', 'core/hol_shadow.h', 'render/hol_program.h']
  .map((f) => fs.readFileSync(path.join(root, f), 'utf8')).join('\n');
const def = (n) => {
  const m = hdr.match(new RegExp(`#define ${n} ([-0-9.]+)`));
  if (!m) throw new Error('no ' + n);
  return m[1];
};
const f1 = (n) => (def(n).includes('.') ? def(n) : def(n) + '.0');
function src(dir, f) {
  return fs.readFileSync(path.join(dir, f), 'utf8').split('\n').map((l) =>
    l.startsWith('@include ') ? src(dir, l.slice(9).trim()) : l).join('\n');
}
function pre(lit) {
  const d = { LIT: lit ? (ROOM ? 2 : 1) : 0, FLAT: lit ? FLAT : 0, WEDGE: 0, VLIT: 0, NIGHT: lit ? 1 : 0, FX: lit ? FX : 0, TEXT: 0, FLOOR: lit && !ROOM ? FLOOR : 0,
    LAMPS: lit && ROOM ? 1 : 0, SPREAD: '8.0', SHD: lit && !ROOM ? 1 : 0, SHM_N: f1('HOL_SHADOW_MASK_N'),
    SHM_R: def('HOL_SHADOW_MASK_RANGE'), SHM_W: f1('HOL_SHADOW_ATLAS_COLS'),
    SHM_H: f1('HOL_SHADOW_ATLAS_ROWS'), TX_ROWS: def('HOL_PROG_TX_ROWS') };
  for (const k of ['D0_M', 'PHYS', 'RADIUS_M', 'HEIGHT_M', 'TONE_K']) d['LIGHT_' + k] = def('HOL_LIGHT_' + k);
  for (const k of 'ABCD') d['SRGB_' + k] = def('HOL_SRGB_' + k);
  return '#version 300 es\n' + Object.entries(d).map(([k, v]) => `#define HOL_${k} ${v}\n`).join('');
}
const progs = dirs.map((d) => ({ name: path.basename(path.resolve(d)), vs: pre(1) + src(d, 'scene.vert.glsl'),
  fs: pre(1) + src(d, 'scene.frag.glsl') }));
progs.push({ name: 'day', vs: pre(0) + src(dirs[0], 'scene.vert.glsl'), fs: pre(0) + src(dirs[0], 'scene.frag.glsl') });
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'holonomy-frag-bench-'));
const browser = await launch(process.env.CHROMIUM || '/usr/bin/chromium', path.join(tmp, 'profile'), 800, 600);
try {
  const page = await browser.newPage();
  await page.setContent('<canvas id=c width=800 height=600></canvas>');
  await page.evaluate(([sp, un]) => { window.SPLIT = sp; window.UNI = un; }, [+(process.env.SPLIT || 0), +(process.env.UNI || 0)]);
  const means = await page.evaluate((progs, state, flat, ROOM_) => {
    const gl = document.getElementById('c').getContext('webgl2',
      { antialias: false, depth: true, stencil: true, alpha: false, premultipliedAlpha: false });
    const P = progs.map((p) => {
      const mk = (t, s) => {
        const sh = gl.createShader(t);
        gl.shaderSource(sh, s);
        gl.compileShader(sh);
        if (!gl.getShaderParameter(sh, gl.COMPILE_STATUS)) throw new Error(p.name + ': ' + gl.getShaderInfoLog(sh));
        return sh;
      };
      const pr = gl.createProgram();
      gl.attachShader(pr, mk(gl.VERTEX_SHADER, p.vs));
      gl.attachShader(pr, mk(gl.FRAGMENT_SHADER, p.fs));
      gl.linkProgram(pr);
      if (!gl.getProgramParameter(pr, gl.LINK_STATUS)) throw new Error(p.name + ': ' + gl.getProgramInfoLog(pr));
      return pr;
    });
    // the tile's floor as an 8 x 8 grid over its square, normal up
    const N = 8, pos = [], idx = [];
    for (let j = 0; j <= N; j++)
      for (let i = 0; i <= N; i++) pos.push(-0.5 + i / N, 0, -0.5 + j / N, 0, 1, 0, 0.4, 0.35, 0.3, 1);
    for (let j = 0; j < N; j++)
      for (let i = 0; i < N; i++) {
        const a = j * (N + 1) + i;
        idx.push(a, a + 1, a + N + 1, a + 1, a + N + 2, a + N + 1);
      }
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(pos), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint16Array(idx), gl.STATIC_DRAW);
    [[0, 3, 0], [1, 3, 12], [2, 4, 24]].forEach(([l, n, o]) => {
      gl.enableVertexAttribArray(l);
      gl.vertexAttribPointer(l, n, gl.FLOAT, false, 40, o);
    });
    // a mask texture of the atlas's size, any bytes
    gl.bindTexture(gl.TEXTURE_2D, gl.createTexture());
    const tb = new Uint8Array(1024 * 512 * 4);
    for (let i = 0; i < tb.length; i++) tb[i] = (i * 37) & 255;
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1024, 512, 0, gl.RGBA, gl.UNSIGNED_BYTE, tb);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    // {4,5} with 1 m cells (flat: {4,4}): four lights at floor distances
    // 0.3, 2.0, 1.5 and 0.8 units, the last a firefly
    const rin = flat ? 0 : 0.5306, kl = flat ? 1 : Math.tanh(rin) / 0.5, mpu = flat ? 1 : 1 / 1.0613;
    const tl = new Float32Array(16);
    [[0.3, 0.2], [2.0, 1.0], [1.5, 2.2], [0.8, -3.0]].forEach(([r, a], i) => {
      tl[i] = (flat ? r : Math.sinh(r)) * Math.cos(a);
      tl[4 + i] = (flat ? r : Math.sinh(r)) * Math.sin(a);
      tl[8 + i] = flat ? 0.5 * r * r : Math.cosh(r);
    });
    tl.set([0.1, 0.05, flat ? 0.00625 : Math.sqrt(1.0125)], 12);
    const tx = new Float32Array(28);
    // rows 3..6 of u_tx: a spot's sin(tilt) (-2: none; slot 1 a spot),
    // heights (the firefly 0.6 m), lanterns' and fireflies' weights
    tx.set([-2, 0.7, -2, -2, 1.3, 1.3, 1.3, 0.6, 1, 1, 1, 0, 0, 0, 0, 0.15], 12);
    const set = (pr) => {
      gl.useProgram(pr);
      const u = (n) => gl.getUniformLocation(pr, n);
      gl.uniformMatrix4fv(u('u_vp'), false, [2, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0, 1]);
      gl.uniformMatrix4fv(u('u_model'), false, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
      gl.uniform1i(u('u_mode'), 0);
      gl.uniform3f(u('u_eye'), 0.1, 1.6, 0.2);
      gl.uniform3f(u('u_fog'), 0.03, 0.04, 0.08);
      gl.uniform1f(u('u_fogd'), 0.15);
      gl.uniform1i(u('u_lin'), 0);
      gl.uniform1i(u('u_light'), ROOM_ ? 2 : 1);
      gl.uniform1f(u('u_klein'), kl);
      gl.uniform1f(u('u_mpu2'), mpu * mpu);
      gl.uniform4fv(u('u_tl'), tl);
      gl.uniform1f(u('u_eyeh'), 1.6);
      gl.uniform1i(u('u_lonly'), 0);
      gl.uniform4fv(u('u_tx'), tx);
      gl.uniform4f(u('u_shr'), 1 / (2 * (flat ? 0.5 : Math.tanh(rin))), 0.5 / 1024, 0.5 / 512, 0);
      gl.uniform1i(u('u_shm'), 0);
    };
    const px = new Uint8Array(4);
    if (state) {
      gl.enable(gl.DEPTH_TEST);
      gl.depthFunc(gl.LEQUAL);
      gl.enable(gl.STENCIL_TEST);
      gl.stencilFunc(gl.EQUAL, 0, 0xff);
      gl.clear(gl.DEPTH_BUFFER_BIT | gl.STENCIL_BUFFER_BIT | gl.COLOR_BUFFER_BIT);
    }
    window.draw = (i, n) => {
      set(P[i]);
      for (let k = 0; k < n; k++) {
        if (!window.SPLIT) gl.drawElements(gl.TRIANGLES, idx.length, gl.UNSIGNED_SHORT, 0);
        else {
          gl.enable(gl.SCISSOR_TEST);
          for (let j = 0; j < window.SPLIT; j++) {
            gl.scissor(0, Math.floor(600 * j / window.SPLIT), 800, Math.floor(600 * (j + 1) / window.SPLIT) - Math.floor(600 * j / window.SPLIT));
            if (window.UNI) gl.uniform4fv(gl.getUniformLocation(P[i], 'u_tx'), new Float32Array(28).fill(0.5));
            gl.drawElements(gl.TRIANGLES, idx.length, gl.UNSIGNED_SHORT, 0);
          }
          gl.disable(gl.SCISSOR_TEST);
        }
      }
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    };
    return P.map((pr, i) => {
      window.draw(i, 2);
      const b = new Uint8Array(800 * 600 * 4);
      gl.readPixels(0, 0, 800, 600, gl.RGBA, gl.UNSIGNED_BYTE, b);
      let s = 0;
      for (let k = 0; k < b.length; k += 4) s += b[k] + b[k + 1] + b[k + 2];
      return s / (800 * 600 * 3);
    });
  }, progs, STATE, FLAT, ROOM);
  const pid = browser.process().pid, ms = progs.map(() => []);
  for (let r = 0; r < ROUNDS; r++)
    for (let i = 0; i < progs.length; i++) {
      const c0 = processTreeCpu(pid);
      await page.evaluate((i, n) => window.draw(i, n), i, DRAWS);
      ms[i].push((processTreeCpu(pid) - c0) * 1000 / DRAWS);
    }
  const day = median(ms[ms.length - 1]);
  progs.forEach((p, i) => console.log(`${p.name.padEnd(20)} ${median(ms[i]).toFixed(1).padStart(6)} ms CPU a draw ` +
    `(${Math.min(...ms[i]).toFixed(1)}-${Math.max(...ms[i]).toFixed(1)}), over day ${(median(ms[i]) - day).toFixed(1)}, mean code ${means[i].toFixed(3)}`));
  console.log(`(FX ${FX}, FLAT ${FLAT}, ROOM ${ROOM}, STATE ${STATE}; ${ROUNDS} rounds of ${DRAWS} draws; load average ${os.loadavg()[0].toFixed(1)})`);
} finally {
  await browser.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
