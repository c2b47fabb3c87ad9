// store.js - the browser's folder of named byte streams behind the web
// sink (platform/web/hol_web_sink.c, core/hol_sink.h): the session's logs
// and recordings, kept in IndexedDB so that a reload or a closed tab loses
// nothing, read back at the next load (the session itself finishes an
// attempt a closed tab left unfinished).
//
// In memory every stream is a list of byte chunks (what the page offers for
// download). IndexedDB holds two object stores: `names` (name -> {id}) and
// `chunks` ([id, seq] -> bytes). Every change (open, flush, rename, remove)
// is one transaction of blind writes (put or delete of fixed keys), made at
// once; IndexedDB runs transactions on the same stores in the order they
// were made, so the database always holds a prefix of the changes, and a
// rename is atomic.
//
// IndexedDB commits asynchronously, so the changes not yet committed when
// the page goes away (pagehide, or hidden) are also written, synchronously,
// to localStorage as a journal; the next load applies the journal to the
// database before reading it. Blind writes replayed in order give the same
// end state whichever prefix had committed, so a reload or a closed tab
// loses nothing the session handed over. Without IndexedDB (some private
// modes) the store lives in memory only and `persistent` is false; a
// journal too large for localStorage's quota is lost (why() says so).
'use strict';

(function () {
  var files = new Map(); // name -> {id, parts: [Uint8Array], size, pending: [], seq}
  var handles = [];      // open handles -> file
  var db = null, nextId = 1, failure = '';
  var uncommitted = [];  // transactions (op lists) made and not yet complete
  var journaled = false; // the page is hidden or going: keep the journal current
  var JOURNAL = 'holonomy-journal';

  // Ops: ['name', name, id] ['unname', name] ['chunk', id, seq, bytes]
  // ['drop', id] ['clear']
  function apply(names, chunks, op) {
    if (op[0] === 'name') names.put({ id: op[2] }, op[1]);
    else if (op[0] === 'unname') names.delete(op[1]);
    else if (op[0] === 'chunk') chunks.put(op[3], [op[1], op[2]]);
    else if (op[0] === 'drop') chunks.delete(IDBKeyRange.bound([op[1], 0], [op[1], Infinity]));
    else if (op[0] === 'clear') { names.clear(); chunks.clear(); }
  }

  function commit(ops) {
    if (!db) return;
    uncommitted.push(ops);
    try {
      var t = db.transaction(['names', 'chunks'], 'readwrite');
      t.oncomplete = function () {
        var i = uncommitted.indexOf(ops);
        if (i >= 0) uncommitted.splice(i, 1);
        if (journaled) writeJournal();
      };
      t.onerror = function () { failure = String(t.error); };
      var n = t.objectStore('names'), c = t.objectStore('chunks');
      ops.forEach(function (op) { apply(n, c, op); });
    } catch (e) {
      failure = String(e);
    }
    if (journaled) writeJournal();
  }

  // The uncommitted changes, in order, to localStorage (or none there).
  function writeJournal() {
    try {
      var ops = [];
      uncommitted.forEach(function (t) { ops = ops.concat(t); });
      if (!ops.length) { localStorage.removeItem(JOURNAL); return; }
      localStorage.setItem(JOURNAL, JSON.stringify(ops.map(function (op) {
        return op[0] === 'chunk' ? ['chunk', op[1], op[2], b64(op[3])] : op;
      })));
    } catch (e) {
      failure = 'the journal did not fit in localStorage: ' + e;
    }
  }

  function concat(parts, size) {
    var out = new Uint8Array(size), at = 0;
    parts.forEach(function (p) { out.set(p, at); at += p.length; });
    return out;
  }

  function b64(u8) {
    var s = '';
    for (var i = 0; i < u8.length; i += 32768) s += String.fromCharCode.apply(null, u8.subarray(i, i + 32768));
    return btoa(s);
  }

  function unb64(s) {
    var t = atob(s), u8 = new Uint8Array(t.length);
    for (var i = 0; i < t.length; i++) u8[i] = t.charCodeAt(i);
    return u8;
  }

  var store = {
    persistent: false,
    why: function () { return failure || 'browser storage failed'; },
    names: function () { return Array.from(files.keys()); },
    size: function (name) { var f = files.get(name); return f ? f.size : -1; },
    bytes: function (name) {
      var f = files.get(name);
      return f ? concat(f.parts, f.size) : null;
    },
    open: function (name, append) {
      var f = files.get(name);
      if (!f || !append) {
        var old = f;
        f = { id: nextId++, parts: [], size: 0, pending: [], seq: 0 };
        files.set(name, f);
        commit(old ? [['name', name, f.id], ['drop', old.id]] : [['name', name, f.id]]);
      }
      handles.push(f);
      return handles.length - 1;
    },
    write: function (h, bytes) {
      var f = handles[h];
      if (!f) return false;
      var b = new Uint8Array(bytes); // a copy: the caller's buffer is reused
      f.parts.push(b);
      f.pending.push(b);
      f.size += b.length;
      return true;
    },
    flush: function (h) {
      var f = handles[h];
      if (!f) return false;
      if (!f.pending.length) return true;
      var n = 0;
      f.pending.forEach(function (p) { n += p.length; });
      commit([['chunk', f.id, f.seq++, concat(f.pending, n)]]);
      f.pending = [];
      return !failure;
    },
    close: function (h) {
      if (handles[h]) store.flush(h);
      handles[h] = null;
      while (handles.length && !handles[handles.length - 1]) handles.pop();
      return true;
    },
    rename: function (from, to) {
      var f = files.get(from);
      if (!f) return false;
      var old = files.get(to);
      files.delete(from);
      files.set(to, f);
      var ops = [['unname', from], ['name', to, f.id]];
      if (old && old !== f) ops.push(['drop', old.id]);
      commit(ops);
      return true;
    },
    remove: function (name) {
      var f = files.get(name);
      if (!f) return true;
      files.delete(name);
      commit([['unname', name], ['drop', f.id]]);
      return true;
    },
    // up to n bytes from offset off, or null when there is no such stream
    read: function (name, off, n) {
      var f = files.get(name);
      if (!f) return null;
      var all = concat(f.parts, f.size);
      return all.subarray(Math.min(off, all.length), Math.min(off + n, all.length));
    },
    clear: function () {
      files.clear();
      handles.length = 0;
      commit([['clear']]);
    },
    // on (the page is hidden or going away): the changes IndexedDB has not
    // confirmed go to localStorage at once (synchronously), and the journal
    // follows every change and commit; off (visible again): dropped, as the
    // page lives to see its transactions commit.
    journal: function (on) {
      journaled = !!on && !!db;
      if (journaled) writeJournal();
      else try { localStorage.removeItem(JOURNAL); } catch (e) { /* none */ }
    },
    // loads what earlier pages kept; resolves when the store is usable
    ready: new Promise(function (resolve) {
      var req;
      try {
        req = indexedDB.open('holonomy', 1);
      } catch (e) {
        failure = String(e);
        resolve(false);
        return;
      }
      req.onupgradeneeded = function () {
        req.result.createObjectStore('names');
        req.result.createObjectStore('chunks');
      };
      req.onerror = function () { failure = String(req.error); resolve(false); };
      req.onsuccess = function () {
        db = req.result;
        replayJournal(function () { load(resolve); });
      };
    })
  };

  // A journal left by the last page: applied before anything is read.
  function replayJournal(done) {
    var j = null;
    try { j = JSON.parse(localStorage.getItem(JOURNAL) || 'null'); } catch (e) { j = null; }
    if (!j || !j.length) { done(); return; }
    var t = db.transaction(['names', 'chunks'], 'readwrite');
    var n = t.objectStore('names'), c = t.objectStore('chunks');
    j.forEach(function (op) { apply(n, c, op[0] === 'chunk' ? ['chunk', op[1], op[2], unb64(op[3])] : op); });
    t.oncomplete = function () {
      localStorage.removeItem(JOURNAL);
      console.log('holonomy: ' + j.length + ' change(s) the last page left uncommitted applied from its journal');
      done();
    };
    t.onerror = function () { failure = String(t.error); done(); };
  }

  function load(resolve) {
    var t = db.transaction(['names', 'chunks'], 'readonly');
    var named = [], chunks = [];
    t.objectStore('names').openCursor().onsuccess = function (e) {
      var c = e.target.result;
      if (!c) return;
      named.push([c.key, c.value.id]);
      c.continue();
    };
    t.objectStore('chunks').openCursor().onsuccess = function (e) {
      var c = e.target.result;
      if (!c) return;
      chunks.push([c.key, new Uint8Array(c.value)]); // in key order: [id, seq]
      c.continue();
    };
    t.oncomplete = function () {
      var byId = new Map();
      named.forEach(function (nv) {
        var f = { id: nv[1], parts: [], size: 0, pending: [], seq: 0 };
        files.set(nv[0], f);
        byId.set(f.id, f);
        nextId = Math.max(nextId, f.id + 1);
      });
      chunks.forEach(function (kc) {
        var f = byId.get(kc[0][0]);
        if (f) {
          f.parts.push(kc[1]);
          f.size += kc[1].length;
          f.seq = kc[0][1] + 1;
        }
        nextId = Math.max(nextId, kc[0][0] + 1);
      });
      store.persistent = true;
      resolve(true);
    };
    t.onerror = function () { failure = String(t.error); resolve(false); };
  }

  window.holonomyStore = store;
})();
