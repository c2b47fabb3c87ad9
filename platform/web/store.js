// store.js - the browser's folder of named byte streams behind the web
// sink (platform/web/hol_web_sink.c, core/hol_sink.h): the session's logs
// and recordings, kept in IndexedDB so a reload or a closed tab loses
// nothing that was flushed, and read back at the next load (recovery of an
// attempt a closed tab left unfinished happens in the session).
//
// In memory every stream is a list of byte chunks (what the page offers for
// download). IndexedDB holds two object stores: `names` (name -> {id}) and
// `chunks` ([id, seq] -> bytes). Each change is one readwrite transaction
// made at once; IndexedDB runs transactions on the same stores in the order
// they were made, so the database always holds some prefix of the changes.
// flush() hands the bytes written since the last flush to IndexedDB; a tab
// closed in the milliseconds before that transaction commits can lose them
// (IndexedDB has no synchronous commit). rename() is one transaction:
// atomic. Without IndexedDB (some private modes) the store lives in memory
// only and `persistent` is false.
'use strict';

(function () {
  var files = new Map(); // name -> {id, parts: [Uint8Array], size, pending: []}
  var handles = [];      // open handles -> file
  var db = null, nextId = 1, failure = '';

  function tx(fn) {
    if (!db) return;
    try {
      var t = db.transaction(['names', 'chunks'], 'readwrite');
      t.onerror = function () { failure = String(t.error); };
      fn(t.objectStore('names'), t.objectStore('chunks'));
    } catch (e) {
      failure = String(e);
    }
  }

  function dropChunks(chunks, id) {
    chunks.delete(IDBKeyRange.bound([id, 0], [id, Infinity]));
  }

  function concat(parts, size) {
    var out = new Uint8Array(size), at = 0;
    parts.forEach(function (p) { out.set(p, at); at += p.length; });
    return out;
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
        tx(function (names, chunks) {
          names.put({ id: f.id }, name);
          if (old) dropChunks(chunks, old.id);
        });
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
      var data = concat(f.pending, n), seq = f.seq++, id = f.id;
      f.pending = [];
      tx(function (names, chunks) { chunks.put(data, [id, seq]); });
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
      tx(function (names, chunks) {
        names.delete(from);
        names.put({ id: f.id }, to);
        if (old && old !== f) dropChunks(chunks, old.id);
      });
      return true;
    },
    remove: function (name) {
      var f = files.get(name);
      if (!f) return true;
      files.delete(name);
      tx(function (names, chunks) {
        names.delete(name);
        dropChunks(chunks, f.id);
      });
      return true;
    },
    // up to n bytes from offset off, or null when there is no such stream
    read: function (name, off, n) {
      var f = files.get(name);
      if (!f) return null;
      var all = concat(f.parts, f.size);
      return all.subarray(Math.min(off, all.length), Math.min(off + n, all.length));
    },
    put: function (name, bytes) {
      var h = store.open(name, 0);
      store.write(h, bytes);
      store.close(h);
    },
    clear: function () {
      files.clear();
      handles.length = 0;
      tx(function (names, chunks) { names.clear(); chunks.clear(); });
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
      };
    })
  };
  window.holonomyStore = store;
})();
