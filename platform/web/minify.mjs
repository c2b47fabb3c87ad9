// minify.mjs - the web build's last step: node platform/web/minify.mjs IN OUT
// writes IN's JavaScript minified by Debian's terser (package `terser`, a
// library under /usr/share/nodejs: run with NODE_PATH=/usr/share/nodejs)
// to OUT, through OUT.tmp renamed (no half-written file). Compress and
// local names; properties stay (page.js calls Module's by name, and
// page.js the functions of store.js), and so do top-level names, but
// with `--toplevel NAME,...` (emscripten's glue: no other file reads its
// top-level names but those kept, Module and the ones web-test evaluates
// in the page). emscripten's glue (holonomy.js) loses about 2.3 KB of the
// page's gzip'ed transfer, 2.4 KB more with --toplevel (and 0.2 KB more
// with three passes of compress there), page.js and store.js 0.9 KB
// (docs/web.md, "The transfer size").
// Exit 1 with one line on stderr when it cannot.
import { createRequire } from 'module';
import fs from 'fs';

const [inPath, outPath, flag, names] = process.argv.slice(2);
try {
    if (!inPath || !outPath)
        throw new Error('usage: node platform/web/minify.mjs IN OUT');
    const require = createRequire(import.meta.url);
    const { minify } = require('terser');
    const src = fs.readFileSync(inPath, 'utf8');
    let opts = { compress: true, mangle: true };
    if (flag === '--toplevel') {
        const keep = (names || '').split(',').filter(Boolean);
        opts = { compress: { toplevel: true, top_retain: keep, passes: 3 }, mangle: { toplevel: true, reserved: keep } };
    } else if (flag)
        throw new Error(`unknown option ${flag}`);
    const r = await minify(src, opts);
    if (!r.code)
        throw new Error(`terser gave no code for ${inPath}`);
    fs.writeFileSync(outPath + '.tmp', r.code);
    fs.renameSync(outPath + '.tmp', outPath);
} catch (e) {
    try { fs.unlinkSync(outPath + '.tmp'); } catch (_) { /* none */ }
    console.error(`minify: ${inPath}: ${String(e.message).split('\n')[0]} (make deps-web installs terser)`);
    process.exit(1);
}
