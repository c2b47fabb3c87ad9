// hol_web_al.js - the few OpenAL calls the sound player makes
// (platform/audio/hol_audio.c), carried out on WebAudio (emcc --js-library).
//
// Emscripten's own OpenAL (-lopenal) is the whole API: about 58 KB of JS
// with the Browser object it pulls in (13 KB gzip, a third of holonomy.js),
// for the 21 functions the player calls. This is those 21, for the way the
// player uses them and no other (docs/web.md, Sound):
// - one device and one context: an AudioContext, made at alcOpenDevice
//   (the player opens only after a user gesture: hol_web_sound.c);
// - buffers of 16-bit mono PCM (AL_FORMAT_MONO16) at any rate;
// - sources relative to a listener that never moves (AL_SOURCE_RELATIVE,
//   no distance model, rolloff 0): each is a PannerNode at the source's
//   position (HRTF when the context asks for ALC_HRTF_SOFT, as the player
//   does; else equal power) into a GainNode (AL_GAIN), and a play is an
//   AudioBufferSourceNode (AL_BUFFER, AL_LOOPING) into the panner;
// - alcGetProcAddress finds nothing (the web has no loopback device), and
//   alGetError reports AL_INVALID_OPERATION (0xA004) after a call made
//   without a context, else AL_NO_ERROR.
// Module.holAudioState() (hol_web_lib.js) reads HolAL.ctx.state, and
// Module.holAudioNodes() what plays (tests/web/run.mjs).

var HolWebAL = {
  $HolAL: {
    ctx: null,        // the AudioContext (the device)
    hrtf: false,      // its panners' model: HRTF (ALC_HRTF_SOFT asked for)
    bufs: [null],     // AudioBuffers by name (0: none)
    srcs: [null],     // sources by name: { panner, gain, buffer, loop, node }
    err: 0,
    gen: function (list, n, out, make) {
      for (var i = 0; i < n; i++) {
        HEAP32[(out >> 2) + i] = list.length;
        list.push(make());
      }
    },
    src: function (s) {
      var o = HolAL.srcs[s];
      if (!o) HolAL.err = 0xA001; /* AL_INVALID_NAME */
      return o;
    },
    // for the tests (Module.holAudioNodes): the sources playing (looping
    // and not), their panners' models and the looping ones' gains
    nodes: function () {
      var r = { loops: 0, shots: 0, models: [], gains: [] };
      HolAL.srcs.forEach(function (o) {
        if (!o || !o.node) return;
        if (o.node.loop) r.loops++, r.gains.push(o.gain.gain.value);
        else r.shots++;
        if (r.models.indexOf(o.panner.panningModel) < 0) r.models.push(o.panner.panningModel);
      });
      return r;
    },
    stop: function (o) {
      if (!o.node) return;
      try { o.node.stop(); } catch (e) { /* never started */ }
      o.node.disconnect();
      o.node = null;
    }
  },

  $HolAL__postset: 'Module["holAudioNodes"] = HolAL.nodes;',

  alcOpenDevice: function (name) {
    var C = window.AudioContext || window.webkitAudioContext;
    if (!C || HolAL.ctx) return 0;
    try {
      HolAL.ctx = new C();
    } catch (e) {
      return 0;
    }
    if (HolAL.ctx.state === 'suspended') HolAL.ctx.resume().catch(function () {});
    return 1;
  },
  alcCloseDevice: function (dev) {
    if (!HolAL.ctx) return 0;
    HolAL.ctx.close().catch(function () {});
    HolAL.ctx = null;
    return 1;
  },
  alcIsExtensionPresent: function (dev, name) {
    return UTF8ToString(name) === 'ALC_SOFT_HRTF' ? 1 : 0;
  },
  // attrs: ALC key and value pairs ending in 0; ALC_HRTF_SOFT (0x1992)
  alcCreateContext: function (dev, attrs) {
    if (!HolAL.ctx) return 0;
    for (var p = attrs >> 2; attrs && HEAP32[p]; p += 2)
      if (HEAP32[p] === 0x1992) HolAL.hrtf = HEAP32[p + 1] === 1;
    return 1;
  },
  alcMakeContextCurrent: function (c) {
    return c === 0 || HolAL.ctx ? 1 : 0;
  },
  alcDestroyContext: function (c) {},
  alcGetProcAddress: function (dev, name) {
    return 0;
  },
  alcGetIntegerv: function (dev, param, size, out) {
    if (size > 0 && out) HEAP32[out >> 2] = param === 0x1992 && HolAL.hrtf ? 1 : 0;
  },

  alGetError: function () {
    var e = HolAL.err;
    HolAL.err = 0;
    return e;
  },
  alDistanceModel: function (m) {},

  alGenBuffers: function (n, out) {
    HolAL.gen(HolAL.bufs, n, out, function () { return null; });
  },
  alDeleteBuffers: function (n, names) {
    for (var i = 0; i < n; i++) HolAL.bufs[HEAP32[(names >> 2) + i]] = null;
  },
  // AL_FORMAT_MONO16 (0x1101) only: the player's one format
  alBufferData: function (b, format, data, size, rate) {
    if (!HolAL.ctx || format !== 0x1101 || !(b in HolAL.bufs)) {
      HolAL.err = 0xA004;
      return;
    }
    var n = size >> 1, pcm = HEAP16.subarray(data >> 1, (data >> 1) + n);
    var ab = HolAL.ctx.createBuffer(1, n, rate), ch = ab.getChannelData(0);
    for (var i = 0; i < n; i++) ch[i] = pcm[i] / 32768;
    HolAL.bufs[b] = ab;
  },

  alGenSources: function (n, out) {
    if (!HolAL.ctx) {
      HolAL.err = 0xA004;
      return;
    }
    var ctx = HolAL.ctx;
    HolAL.gen(HolAL.srcs, n, out, function () {
      var o = { panner: ctx.createPanner(), gain: ctx.createGain(), buffer: 0, loop: false, node: null };
      o.panner.panningModel = HolAL.hrtf ? 'HRTF' : 'equalpower';
      o.panner.connect(o.gain);
      o.gain.connect(ctx.destination);
      return o;
    });
  },
  alDeleteSources: function (n, names) {
    for (var i = 0; i < n; i++) {
      var s = HEAP32[(names >> 2) + i], o = HolAL.srcs[s];
      if (!o) continue;
      HolAL.stop(o);
      o.gain.disconnect();
      HolAL.srcs[s] = null;
    }
  },
  // AL_SOURCE_RELATIVE (0x202): always (the listener never moves);
  // AL_LOOPING (0x1007); AL_BUFFER (0x1009)
  alSourcei: function (s, param, v) {
    var o = HolAL.src(s);
    if (!o) return;
    if (param === 0x1007) {
      o.loop = v !== 0;
      if (o.node) o.node.loop = o.loop;
    } else if (param === 0x1009) {
      o.buffer = v;
    }
  },
  // AL_GAIN (0x100A), AL_ROLLOFF_FACTOR (0x1021)
  alSourcef: function (s, param, v) {
    var o = HolAL.src(s);
    if (!o) return;
    if (param === 0x100A) o.gain.gain.value = v;
    else if (param === 0x1021) o.panner.rolloffFactor = v;
  },
  // AL_POSITION (0x1004): the direction from the listener, metres
  alSource3f: function (s, param, x, y, z) {
    var o = HolAL.src(s), p = o && o.panner;
    if (!o || param !== 0x1004) return;
    if (p.positionX) {
      p.positionX.value = x;
      p.positionY.value = y;
      p.positionZ.value = z;
    } else {
      p.setPosition(x, y, z);
    }
  },
  alSourcePlay: function (s) {
    var o = HolAL.src(s);
    if (!o) return;
    HolAL.stop(o);
    var b = HolAL.bufs[o.buffer];
    if (!b) return;
    var node = HolAL.ctx.createBufferSource();
    node.buffer = b;
    node.loop = o.loop;
    node.connect(o.panner);
    node.onended = function () { if (o.node === node) o.node = null; };
    node.start();
    o.node = node;
  },
  alSourceStop: function (s) {
    var o = HolAL.src(s);
    if (o) HolAL.stop(o);
  },
  alSourceRewind: function (s) {
    var o = HolAL.src(s);
    if (o) HolAL.stop(o);
  }
};

autoAddDeps(HolWebAL, '$HolAL');
mergeInto(LibraryManager.library, HolWebAL);
