// quad_check.mjs - the web glue's choice for the world panel
// (platform/web/hol_web_lib.js: HolXR.panelMode, HolXR.quadSetup), on stubs,
// without a browser: the fallback (the panel in the scene) where the
// binding lacks createQuadLayer (iwer 2.5.0, most browsers today) or the
// session was not granted 'layers'; and, on a stub binding that has it, the
// quad layer made as asked (its space, texture size, a mono layer that is not static)
// and put after the projection layer in renderState.layers (back to
// front). The quad path in a browser: make web-test (iwer with the layers polyfill).
// Run: node tests/web/quad_check.mjs (exit 0: every check passed).
import fs from 'node:fs';
import path from 'node:path';
import vm from 'node:vm';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const src = fs.readFileSync(path.join(root, 'platform/web/hol_web_lib.js'), 'utf8');
const calls = [];
const logs = [];
const ctx = {
  console: { log: (s) => logs.push(s) },
  mergeInto: () => {}, autoAddDeps: () => {}, LibraryManager: { library: {} },
  Module: { _hol_web_xr_panel_quad: (on) => calls.push(['panel_quad', on]) },
};
vm.createContext(ctx);
vm.runInContext(src + '\nthis.HolWebLib = HolWebLib;', ctx);
const HolXR = ctx.HolWebLib.$HolXR;
// the functions run in the library's scope: HolXR and Module as globals
ctx.HolXR = HolXR;

let failed = 0;
function check(name, ok) {
  console.log(`${ok ? 'ok' : 'FAIL'}: ${name}`);
  if (!ok) failed = 1;
}

function session(features) {
  return {
    enabledFeatures: features,
    states: [],
    updateRenderState(st) { this.states.push(st); },
  };
}
const gl = { createFramebuffer: () => ({ fb: 1 }) };
const base = { kind: 'projection' };

// iwer 2.5.0: XRWebGLBinding without createQuadLayer
class NoQuad { constructor(s, g) { this.s = s; this.g = g; } getSubImage() {} }
let s = session(['local-floor', 'layers']);
let m = HolXR.panelMode(s, NoQuad, undefined);
check('no createQuadLayer: the panel in the scene', m.mode === 'scene' && /createQuadLayer/.test(m.why));
check('no XRWebGLBinding at all: the panel in the scene', HolXR.panelMode(s, null).mode === 'scene');
HolXR.space = { space: 'local-floor' };
check('quadSetup without createQuadLayer: scene, the render state untouched, C told 0',
  HolXR.quadSetup(s, gl, base, NoQuad) === 'scene' && s.states.length === 0 &&
  HolXR.quad === null && calls.at(-1)[1] === 0 &&
  logs.at(-1) === 'web: panel in the scene: the browser has no XRWebGLBinding.createQuadLayer');

// a stub binding with createQuadLayer that records the call
const made = [];
class WithQuad {
  constructor(sess, g) { this.sess = sess; this.g = g; }
  createQuadLayer(init) { const l = { kind: 'quad', init, needsRedraw: true }; made.push(l); return l; }
  getSubImage() {}
}
s = session(['local-floor']);
check('createQuadLayer but layers not granted: the panel in the scene',
  HolXR.panelMode(s, WithQuad).mode === 'scene' && HolXR.quadSetup(s, gl, base, WithQuad) === 'scene' &&
  made.length === 0 && s.states.length === 0);
s = session(['local-floor', 'layers']);
check('?panel=scene: the panel in the scene though a quad is offered',
  HolXR.quadSetup(s, gl, base, WithQuad, 'scene') === 'scene' && made.length === 0 &&
  /\?panel=scene/.test(logs.at(-1)));
s = session(['local-floor', 'layers']);
const mode = HolXR.quadSetup(s, gl, base, WithQuad);
const q = made[0];
check('createQuadLayer offered and layers granted: the quad layer', mode === 'quad' && made.length === 1);
check('the quad: in the session\'s reference space, 824x372 texels (the widest panel box), mono, not static (redrawn on each change)',
  q && q.init.space === HolXR.space && q.init.viewPixelWidth === 824 &&
  q.init.viewPixelHeight === 372 && q.init.layout === 'mono' && q.init.isStatic === false);
const st = s.states.at(-1);
check('renderState.layers [projection, quad]: the quad in front (back to front)',
  st && st.layers && st.layers.length === 2 && st.layers[0] === base && st.layers[1] === q &&
  !('baseLayer' in st));
check('the C side told the quad is on (the eyes leave the panel out)', calls.at(-1)[1] === 1);
// a binding whose createQuadLayer throws: the fallback
class Throws extends WithQuad { createQuadLayer() { throw new Error('no'); } }
s = session(['layers']);
check('createQuadLayer throws: the panel in the scene, said',
  HolXR.quadSetup(s, gl, base, Throws) === 'scene' && HolXR.quad === null &&
  /quad layer failed \(no\)/.test(logs.at(-1)) && calls.at(-1)[1] === 0);
process.exit(failed);
