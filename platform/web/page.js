// page.js - the Holonomy page around the wasm game (platform/web/): what to
// play (URL parameters, a level file), the Enter VR button, the canvas size,
// the on-screen touch buttons, and the logs kept in browser storage with
// their download links.
//
// URL parameters: mode=tutorial|flag|keys|explore and seed=S (a level made
// from the seed, as `holonomy play --mode`), level=URL (a level file served
// beside the page), study=URL (a study file: its level files are fetched
// from beside it, and the participant's number, from participant=P07,
// gives the order of its conditions: README, Study designs),
// lesson=N (lesson N for a class, 1..6, as `holonomy play --lesson N`; the
// bar's lesson list loads it), participant=ID (the logs' participant), snap=DEG (snap turn on the
// Left/Right keys), tiling=4,Q room=CxR cell=M (every level's geometry, as
// play's --tiling/--room/--cell), haptics=0 (no controller pulses in VR, as
// holonomy xr --no-haptics), track_hz=N (the logs' track rows N times a
// second, 10..90, as --track-hz), lang=en|de|nl (the language of the page
// and the game's text, as --lang; without it the browser's language when
// it is one of them, else English), seated=1 (seated play, as play --seated:
// one room step a push of W/S/A/D, the touch stick or the on-screen arrows;
// the bar's Seated box sets it), quiz=pre|post (a class's pre-test or
// post-test: docs/teaching.md), class=CODE (the Logs' "send to teacher",
// shown when the server collects: docs/teaching.md). None: the default campaign. A level file
// chosen with "Level file..." plays on the next load (kept in
// sessionStorage for this tab).
'use strict';

(function () {
  var params = new URLSearchParams(location.search);
  var config = {};
  ['mode', 'seed', 'participant', 'snap', 'tiling', 'room', 'cell', 'gldebug', 'haptics', 'sound', 'track_hz', 'panel', 'seated'].forEach(function (k) {
    if (params.has(k)) config[k] = params.get(k);
  });
  var $ = function (id) { return document.getElementById(id); };
  // ---- the language: the page's words from text.js (core/hol_str.c's
  // table, made by tests/gen_page_text.c in the build's languages), the
  // game's from the same table in the wasm (config.lang) ----
  var TEXT = window.holonomyText || {};
  var langOf = function (tag) { // "de", "de-DE", "de_AT" -> "de"; else ""
    tag = String(tag || '');
    var c = tag.slice(0, 2).toLowerCase();
    return TEXT[c] && (tag.length === 2 || /^..[-_]/.test(tag)) ? c : '';
  };
  var lang = langOf(params.get('lang')) ||
    (navigator.languages || [navigator.language]).map(langOf).filter(Boolean)[0] || 'en';
  config.lang = lang;
  document.documentElement.lang = lang;
  var T = function (key, arg) {
    var s = (TEXT[lang] || {})[key] || (TEXT.en || {})[key] || key;
    return arg === undefined ? s : s.replace('%s', function () { return arg; });
  };
  document.querySelectorAll('[data-t]').forEach(function (e) { e.textContent = T(e.dataset.t); });
  document.querySelectorAll('[data-title]').forEach(function (e) { e.title = T(e.dataset.title); });
  var status = function (s) { $('status').textContent = s; };
  // the page's state: playing (in VR or not), paused (and why), over
  // (vrFailed: the status says why Enter VR failed, until the game's next
  // level or restart, when it says Playing again)
  var playing = T('playing'), inVR = false, over = false, vrFailed = false;
  var resumeStatus = function () { vrFailed = false; status(inVR ? T('inVR') : playing); };

  // ---- the VR button: Enter VR, Exit VR, or why VR is not offered ----
  function vrButton(text, enabled, why) {
    var b = $('vr');
    b.textContent = text;
    b.disabled = !enabled;
    b.title = why || '';
    b.hidden = false;
  }
  function vrAvailability() {
    if (over) { $('vr').hidden = true; return; }
    if (inVR) { vrButton(T('vrExit'), true); return; }
    if (!window.isSecureContext) {
      vrButton(T('vrHttps'), false, T('vrHttpsWhy'));
      return;
    }
    if (!navigator.xr) {
      vrButton(T('vrNone'), false, T('vrNoneWhy'));
      return;
    }
    Module.holXR.supported().then(function (ok) {
      if (over || inVR) return;
      if (ok) vrButton(T('vrEnter'), true);
      else vrButton(T('vrNoHeadset'), false, T('vrNoHeadsetWhy'));
    });
  }

  // ---- canvas size: CSS pixels times the device's ratio (at most 2) ----
  var canvas = $('canvas');
  function resize() {
    var r = Math.min(window.devicePixelRatio || 1, 2);
    var w = Math.max(16, Math.round(canvas.clientWidth * r));
    var h = Math.max(16, Math.round(canvas.clientHeight * r));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  }
  window.addEventListener('resize', resize);
  if (window.ResizeObserver) new ResizeObserver(resize).observe(canvas); // the bar wraps
  resize();

  // ---- touch buttons ----
  window.addEventListener('touchstart', function () {
    document.body.classList.add('touch');
  }, { once: true, passive: true });
  document.querySelectorAll('#touch button').forEach(function (b) {
    var bit = +b.dataset.btn;
    var set = function (down) {
      return function (e) {
        e.preventDefault();
        if (Module._hol_web_touch_button) Module._hol_web_touch_button(bit, down);
      };
    };
    b.addEventListener('pointerdown', set(1));
    b.addEventListener('pointerup', set(0));
    b.addEventListener('pointercancel', set(0));
    b.addEventListener('pointerleave', set(0));
  });

  // ---- a level file for the next load ----
  $('file').addEventListener('change', function () {
    var f = this.files && this.files[0];
    if (!f) return;
    f.text().then(function (t) {
      sessionStorage.setItem('holonomy-level', JSON.stringify({ name: f.name, text: t }));
      var u = new URL(location.href);
      ['mode', 'seed', 'level'].forEach(function (k) { u.searchParams.delete(k); });
      u.searchParams.set('levelfile', '1');
      location.href = u.href;
    });
  });

  // ---- logs: listed from the store, offered for download ----
  function refreshLogs() {
    var store = window.holonomyStore;
    if (!store) return;
    var names = store.names().sort();
    var list = $('loglist');
    list.textContent = '';
    if (!names.length) { list.textContent = T('noLogs'); return; }
    var ul = document.createElement('ul');
    names.forEach(function (n) {
      var li = document.createElement('li');
      var a = document.createElement('a');
      a.textContent = n + ' (' + store.size(n) + ' ' + T('bytes') + ')';
      a.href = '#';
      a.addEventListener('click', function (e) {
        e.preventDefault();
        var url = URL.createObjectURL(new Blob([store.bytes(n)], { type: 'text/plain' }));
        var d = document.createElement('a');
        d.href = url;
        d.download = n;
        document.body.appendChild(d);
        d.click();
        d.remove();
        setTimeout(function () { URL.revokeObjectURL(url); }, 1000);
      });
      li.appendChild(a);
      ul.appendChild(li);
    });
    list.appendChild(ul);
    $('logsbtn').textContent = T('logs') + ' (' + names.length + ')';
  }
  window.holonomyRefreshLogs = refreshLogs;
  // ---- class=CODE: the answers sent to the teacher's machine when its
  // server collects them (make web-serve COLLECT=DIR: docs/teaching.md) ----
  var klass = params.get('class');
  if (klass && window.fetch) fetch('collect', { cache: 'no-store' }).then(function (r) {
    if (r.ok) $('send').hidden = false;
  }, function () {});
  $('send').addEventListener('click', function () {
    var store = window.holonomyStore, said = $('sent');
    var names = store ? store.names().filter(function (n) { return /(^|\/)answers\.csv$/.test(n); }) : [];
    if (!names.length) { said.textContent = T('noLogs'); return; }
    Promise.all(names.map(function (n) {
      return fetch('collect?class=' + encodeURIComponent(klass), { method: 'POST', body: store.bytes(n) })
        .then(function (r) { return r.text().then(function (t) { if (!r.ok) throw new Error(t.trim()); }); });
    })).then(function () { said.textContent = T('sent', names.length); },
      function (e) { said.textContent = T('sendFailed', e.message); });
  });
  // the overlay opens below the bar, which wraps on a narrow window: it
  // never covers a button
  function placeLogs() {
    var top = Math.ceil($('bar').getBoundingClientRect().bottom + 4);
    $('logs').style.top = top + 'px';
    $('logs').style.maxHeight = Math.max(80, window.innerHeight - top - 8) + 'px';
  }
  if (window.ResizeObserver) new ResizeObserver(placeLogs).observe($('bar'));
  window.addEventListener('resize', placeLogs);
  $('logsbtn').addEventListener('click', function () {
    refreshLogs();
    placeLogs();
    $('logs').hidden = !$('logs').hidden;
  });
  $('clear').addEventListener('click', function () {
    if (window.holonomyStore && confirm(T('clearAsk'))) {
      window.holonomyStore.clear();
      refreshLogs();
    }
  });

  // ---- the wasm: its download and compile start now, beside the store's
  // opening, and holonomy.js instantiates the compiled module (a server
  // without application/wasm: compiled from the bytes instead) ----
  var fail = function (what, e) {
    status(T('failed', what + ': ' + e));
    console.error('holonomy: ' + what + ': ' + e);
  };
  var wasm = (WebAssembly.compileStreaming ? WebAssembly.compileStreaming(fetch('holonomy.wasm'))
    : Promise.reject(0)).catch(function () {
    return fetch('holonomy.wasm').then(function (r) {
      if (!r.ok) throw new Error('holonomy.wasm: ' + r.status);
      return r.arrayBuffer();
    }).then(function (b) { return WebAssembly.compile(b); });
  });
  wasm.then(function () { performance.mark('holonomy-wasm'); }, function (e) {
    fail(T('noGame'), e);
  });

  // ---- the module ----
  window.Module = {
    instantiateWasm: function (imports, done) {
      wasm.then(function (m) { return WebAssembly.instantiate(m, imports); })
        .then(function (i) { done(i); }, function (e) { fail(T('noStart'), e); });
      return {};
    },
    canvas: canvas,
    holConfig: config,
    print: function (s) { console.log(s); },
    printErr: function (s) { console.warn(s); },
    holEvent: function (kind, text) {
      if (kind === 'ready') {
        playing = config.levelName ? T('playingLevel', config.levelName) : T('playing');
        status(playing);
        canvas.focus();
        vrAvailability();
        if (navigator.xr && navigator.xr.addEventListener)
          navigator.xr.addEventListener('devicechange', vrAvailability);
      } else if (kind === 'pause') {
        if (!over) status(T('paused', text));
      } else if (kind === 'resume') {
        if (!over) resumeStatus();
      } else if (kind === 'fit') {
        status(text);
      } else if (kind === 'fit-offer') {
        // the room that fits the play area, offered: the page again with it
        var u = new URL(location.href), q = new URLSearchParams(text);
        q.forEach(function (v, k) { u.searchParams.set(k, v); });
        var a = $('fitlink');
        if (a) { a.href = u.href; a.hidden = false; }
      } else if (kind === 'xr') {
        inVR = text === 'started';
        if (!over) resumeStatus();
        vrAvailability();
      } else if (kind === 'over') {
        over = true;
        status(T('over'));
        vrAvailability();
        $('again').hidden = false;
        refreshLogs();
        placeLogs();
        $('logs').hidden = false;
      } else if (kind === 'failed') {
        over = true;
        vrAvailability();
        status(T('failed', text));
        console.error('holonomy: ' + text);
      } else if (kind === 'saved') {
        refreshLogs();
        if (vrFailed && !over) resumeStatus(); // a level ended: a restart or the next
      } else if (kind === 'warning') {
        status(T('warning', text));
        console.warn('holonomy: ' + text);
      }
    }
  };
  // leaving the page ends the attempt in play ('aborted') and keeps the
  // files: what IndexedDB has not committed yet goes to the store's journal
  window.addEventListener('pagehide', function () {
    if (Module._hol_web_abort) Module._hol_web_abort();
    window.holonomyStore.journal(true);
  });
  // a page restored from the back-forward cache had its session ended at
  // pagehide: start afresh
  window.addEventListener('pageshow', function (e) {
    if (e.persisted) location.reload();
  });
  document.addEventListener('visibilitychange', function () {
    window.holonomyStore.journal(document.hidden);
  });
  $('vr').addEventListener('click', function () {
    if (inVR) { Module.holXR.leave(); return; }
    Module.holXR.enter().catch(function (e) {
      status(T('vrFailed', e.message));
      vrFailed = true;
    });
  });
  // after the session: the same page afresh (its level, its parameters)
  $('again').addEventListener('click', function () { location.reload(); });

  // the game starts once the store holds what earlier pages kept
  function start() {
    window.holonomyStore.ready.then(function (persistent) {
      if (!persistent)
        console.warn('holonomy: no IndexedDB here: logs are kept in memory only (' +
          window.holonomyStore.why() + ')');
      refreshLogs();
      performance.mark('holonomy-store');
      var s = document.createElement('script');
      s.src = 'holonomy.js';
      document.body.appendChild(s);
    });
  }
  // a level's name: its file's name up to the first '.' (as the desktop's)
  function levelName(file) {
    var n = file.split('.')[0] || file;
    return n.slice(0, 60);
  }
  // a study file and the level files its practice and level lines name
  // (the wasm's parser checks the file; this only finds what to fetch)
  function loadStudy(url) {
    var base = new URL(url, location.href);
    return fetch(base).then(function (r) {
      if (!r.ok) throw new Error(url + ': ' + r.status);
      return r.text();
    }).then(function (t) {
      config.study = t;
      config.levelName = 'study ' + levelName(url.split('/').pop());
      var paths = [];
      t.split('\n').forEach(function (line) {
        var m = /^\s*(practice|level)\s+(\S+)/.exec(line.split('#')[0]);
        if (m && paths.indexOf(m[2]) < 0) paths.push(m[2]);
      });
      return Promise.all(paths.map(function (p) {
        return fetch(new URL(p, base)).then(function (r) {
          if (!r.ok) throw new Error(p + ': ' + r.status);
          return r.text();
        }).then(function (lt) { config['level:' + p] = lt; });
      }));
    });
  }
  // seated play: the box reloads with seated=1 (or without); the arrows show
  $('seated').checked = config.seated === '1';
  if (config.seated === '1') document.body.classList.add('seated');
  $('seated').onchange = function () {
    var u = new URL(location.href);
    if (this.checked) u.searchParams.set('seated', '1'); else u.searchParams.delete('seated');
    location.href = u.href;
  };
  // the lesson list: the chosen lesson on the next load (its geometry kept)
  $('lessons').onchange = function () {
    var u = new URL(location.href);
    ['mode', 'seed', 'level', 'levelfile', 'study'].forEach(function (k) { u.searchParams.delete(k); });
    u.searchParams.set('lesson', this.value);
    location.href = u.href;
  };
  var saved = params.has('levelfile') && sessionStorage.getItem('holonomy-level');
  if (params.has('study')) {
    loadStudy(params.get('study')).then(start).catch(function (e) {
      status(T('noStudy', e.message));
      console.error('holonomy: cannot load the study ' + e.message);
    });
  } else if (saved) {
    var lv = JSON.parse(saved);
    config.level = lv.text;
    config.levelName = levelName(lv.name);
    start();
  } else if (/^[1-6]$/.test(params.get('lesson') || '')) {
    config.level = 'lesson ' + params.get('lesson') + '\n';
    config.levelName = 'lesson-' + params.get('lesson');
    start();
  } else if (/^(pre|post)$/.test(params.get('quiz') || '')) {
    config.level = 'quiz ' + params.get('quiz') + '\n';
    config.levelName = params.get('quiz') + 'test';
    start();
  } else if (params.has('level')) {
    var url = params.get('level');
    fetch(url).then(function (r) {
      if (!r.ok) throw new Error(url + ': ' + r.status);
      return r.text();
    }).then(function (t) {
      config.level = t;
      config.levelName = levelName(url.split('/').pop());
      start();
    }).catch(function (e) {
      status(T('noLevel', e.message));
      console.error('holonomy: cannot load the level ' + e.message);
    });
  } else {
    start();
  }
})();
