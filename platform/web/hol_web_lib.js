// hol_web_lib.js - the page's side of the web platform (emcc --js-library):
// the WebXR session and its frames, the page's focus and config, events to
// the page. The C side is platform/web/hol_web_*.c.
//
// WebXR: an immersive-vr session with the local-floor reference space
// (bounded-floor where the device offers it), an XRWebGLLayer with depth and
// stencil on the page's WebGL 2 context, and per XRFrame: the viewer pose,
// each view's viewport, projection matrix and transform, both controllers'
// grips and xr-standard gamepads (arrays that may hold nulls) copied into
// the C frame record (hol_web_xr.h: offsets asked from hol_web_xr_offset),
// then hol_web_xr_step draws both eyes into the layer's framebuffer
// (registered with emscripten's GL as a framebuffer name; IWER's layer has
// none: the canvas's default framebuffer).
//
// The world panel (HUD text, prompts, menus): where the browser offers the
// WebXR Layers API (the session granted the optional 'layers' feature and
// XRWebGLBinding has createQuadLayer), an XRQuadLayer in front of the
// projection layer (renderState.layers [projection, quad]: back to front),
// drawn by the C side only when its content changes or the browser says
// needsRedraw. The layer is not static (isStatic false): the Layers spec
// lets a static layer be drawn only while needsRedraw is set, once after
// its creation, so its text could never change. A draw that fails (its
// getSubImage throws) is told once on the console and tried again the
// next frame. Else, or with ?panel=scene, the panel in each eye (the
// fallback). A console line 'web: panel ...' says which.

var HolWebLib = {
  $HolXR: {
    session: null,
    space: null,
    spaceType: '',
    fb: null,
    fbName: 0,
    off: null,
    frames: 0,
    base: null,       // the projection layer (XRWebGLLayer)
    quad: null,       // the panel's quad layer: { binding, layer, fb, fbName }
    quadW: 824,       // its texture: the widest panel box (hol_xr_quad_image)
    quadH: 372,

    // Where the world panel goes: 'quad' or 'scene' and why (no browser
    // needed: tests/web/quad_check.mjs runs it on stubs).
    panelMode: function (s, Binding, pref) {
      if (pref === 'scene') return { mode: 'scene', why: 'asked for (?panel=scene)' };
      if (typeof Binding !== 'function' || !Binding.prototype ||
          typeof Binding.prototype.createQuadLayer !== 'function')
        return { mode: 'scene', why: 'the browser has no XRWebGLBinding.createQuadLayer' };
      var f = s.enabledFeatures;
      if (!f || Array.prototype.indexOf.call(f, 'layers') < 0)
        return { mode: 'scene', why: 'the session was not granted the layers feature' };
      return { mode: 'quad', why: 'XRQuadLayer' };
    },

    // The quad layer after the projection layer, or the fallback (the
    // projection layer alone, set already): the chosen mode's name.
    quadSetup: function (s, gl, base, Binding, pref) {
      var m = HolXR.panelMode(s, Binding, pref);
      if (m.mode === 'quad') {
        try {
          var binding = new Binding(s, gl);
          var layer = binding.createQuadLayer({
            space: HolXR.space, viewPixelWidth: HolXR.quadW, viewPixelHeight: HolXR.quadH,
            layout: 'mono', isStatic: false, width: 0.3, height: 0.2
          });
          if ('blendTextureSourceAlpha' in layer) layer.blendTextureSourceAlpha = true;
          s.updateRenderState({ layers: [base, layer] }); // back to front
          HolXR.quad = { binding: binding, layer: layer, fb: gl.createFramebuffer(), fbName: 0,
            retry: 0, failed: 0, shown: 0 };
        } catch (e) {
          m = { mode: 'scene', why: 'the quad layer failed (' + e.message + ')' };
          HolXR.quad = null;
        }
      }
      console.log('web: panel ' + (m.mode === 'quad' ? 'as a WebXR quad layer (XRQuadLayer ' +
        HolXR.quadW + 'x' + HolXR.quadH + ', over the projection layer)'
        : 'in the scene: ' + m.why));
      if (Module['_hol_web_xr_panel_quad']) Module['_hol_web_xr_panel_quad'](HolXR.quad ? 1 : 0);
      return m.mode;
    },

    // After the step: the quad placed, and drawn when its content changed
    // (or the browser lost its texture, or the last draw failed); no panel
    // this frame (none, or the view faded out): its texture cleared once
    // (transparent), and drawn anew when the panel is back.
    quadFrame: function (xrf) {
      var q = HolXR.quad;
      var r = Module['_hol_web_xr_panel_place'](q.layer.needsRedraw || q.retry ? 1 : 0);
      if (!r && !q.shown) return;
      if (r) {
        var o = Module['_hol_web_xr_panel_buffer']() >> 2, f = HEAPF32;
        q.layer.transform = new XRRigidTransform(
          { x: f[o], y: f[o + 1], z: f[o + 2] }, { x: f[o + 3], y: f[o + 4], z: f[o + 5], w: f[o + 6] });
        q.layer.width = f[o + 7];
        q.layer.height = f[o + 8];
      }
      if (r === 1) return;
      q.retry = 1; // until the draw is done
      var gl = GLctx, sub;
      try {
        sub = q.binding.getSubImage(q.layer, xrf);
      } catch (e) {
        if (!q.failed++) console.log('web: the panel layer refused a draw (' + e.message + '): tried again');
        return;
      }
      if (!q.fbName) {
        q.fbName = GL.getNewId(GL.framebuffers);
        q.fb.name = q.fbName;
        GL.framebuffers[q.fbName] = q.fb;
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, q.fb);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D,
        sub.colorTexture, 0);
      if (!r) {
        gl.clearColor(0, 0, 0, 0);
        gl.clear(gl.COLOR_BUFFER_BIT);
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
        q.shown = 0; // q.retry stays: the panel drawn again when back
        return;
      }
      q.retry = Module['_hol_web_xr_panel_draw'](q.fbName, sub.viewport.width, sub.viewport.height);
      q.shown = 1;
    },

    scale: 1.0,       // XRWebGLLayer framebufferScaleFactor: the recommended size
    foveation: 0.5,   // fixedFoveation 0 (none) .. 1 (most): medium
    maxRate: 90,      // the highest target frame rate asked for (Hz)

    // updateTargetFrameRate: the highest supported rate up to maxRate
    frameRate: function (s) {
      var rates = s.supportedFrameRates;
      if (!rates || !rates.length || !s.updateTargetFrameRate) {
        console.log('web: xr frame rate: the browser chooses (no supportedFrameRates)');
        return;
      }
      var best = 0;
      for (var i = 0; i < rates.length; i++)
        if (rates[i] <= HolXR.maxRate && rates[i] > best) best = rates[i];
      if (!best) return;
      s.updateTargetFrameRate(best).then(function () {
        console.log('web: xr frame rate ' + best + ' Hz');
      }, function (e) {
        console.log('web: xr frame rate not set: ' + e.message);
      });
    },

    supported: async function () {
      if (!navigator.xr || !navigator.xr.isSessionSupported) return false;
      try {
        return await navigator.xr.isSessionSupported('immersive-vr');
      } catch (e) {
        return false;
      }
    },

    offsets: function () {
      if (HolXR.off) return HolXR.off;
      var names = ['frame', 'nviews', 'visibility', 'head_valid', 'head_pos', 'head_quat',
        'bounds', 'view', 'view_size', 'vp', 'proj', 'pos', 'quat', 'pad', 'pad_size',
        'present', 'touch_layout', 'grip_valid', 'grip_pos', 'grip_quat', 'button', 'axes', 'hand',
        'joints_valid', 'joint'];
      var o = {};
      for (var i = 0; i < names.length; i++) o[names[i]] = Module['_hol_web_xr_offset'](i);
      HolXR.off = o;
      return o;
    },

    enter: async function () {
      if (HolXR.session) return;
      HolXR.enterT = performance.now(); // the store's rule: tracked within 4 s
      HolXR.tracked = false;
      var s = await navigator.xr.requestSession('immersive-vr', {
        requiredFeatures: ['local-floor'],
        optionalFeatures: ['bounded-floor', 'hand-tracking', 'layers']
      });
      try {
        var gl = GLctx;
        if (gl.makeXRCompatible) await gl.makeXRCompatible();
        // quality (docs/web.md: Quality): MSAA where the browser gives it,
        // the device's recommended resolution (scale 1), medium fixed
        // foveation where offered, and the highest frame rate up to 90 Hz
        var layer = new XRWebGLLayer(s, gl, {
          antialias: true, depth: true, stencil: true, alpha: false,
          framebufferScaleFactor: HolXR.scale
        });
        if ('fixedFoveation' in layer) {
          try { layer.fixedFoveation = HolXR.foveation; } catch (e) { /* not offered */ }
        }
        s.updateRenderState({ baseLayer: layer });
        HolXR.base = layer;
        HolXR.frameRate(s);
        try {
          HolXR.space = await s.requestReferenceSpace('bounded-floor');
          HolXR.spaceType = 'bounded-floor';
        } catch (e) {
          HolXR.space = await s.requestReferenceSpace('local-floor');
          HolXR.spaceType = 'local-floor';
        }
        HolXR.quadSetup(s, gl, layer, typeof XRWebGLBinding === 'undefined' ? null
          : XRWebGLBinding, (Module['holConfig'] || {}).panel);
      } catch (e) {
        s.end();
        throw e;
      }
      HolXR.session = s;
      HolXR.frames = 0;
      HolXR.held = { left: [0, 0], right: [0, 0] };
      // select (a trigger, or a hand's pinch) and squeeze, held from their
      // start to their end: the hand's trigger and squeeze buttons (so a
      // hand with no gamepad confirms, backs, opens the menu: hol_web_xr.h)
      var hold = function (k, v) {
        return function (ev) {
          var h = ev.inputSource && HolXR.held[ev.inputSource.handedness];
          if (h) h[k] = v;
        };
      };
      s.addEventListener('selectstart', hold(0, 1));
      s.addEventListener('selectend', hold(0, 0));
      s.addEventListener('squeezestart', hold(1, 1));
      s.addEventListener('squeezeend', hold(1, 0));
      s.addEventListener('end', HolXR.ended);
      // the pause's reason: a hidden session draws no frames, so the page
      // hears it here (the headset taken off, its screen asleep); visible
      // again, the next step tells the page its state anew
      s.addEventListener('visibilitychange', function () {
        var v = s.visibilityState;
        console.log('web: xr visibility ' + v);
        Module['_hol_web_pause_retell'](v == 'hidden');
        if (Module['holEvent'] && v !== 'visible')
          Module['holEvent']('pause', v === 'hidden' ? 'the headset is off' :
            'a system menu is over the game');
      });
      console.log('web: xr reference space ' + HolXR.spaceType);
      Module['_hol_web_xr_active'](1);
      if (Module['holEvent']) Module['holEvent']('xr', 'started');
      // the browser's recentre: the app re-places the room, walks nothing
      if (HolXR.space.addEventListener)
        HolXR.space.addEventListener('reset', function () {
          console.log('web: reference space reset (a recentre)');
          Module['_hol_web_xr_recentred']();
        });
      if (HolXR.spaceType === 'bounded-floor') {
        HolXR.fit();
        if (HolXR.space.addEventListener)
          HolXR.space.addEventListener('reset', function () { HolXR.fit(); });
      }
      s.requestAnimationFrame(HolXR.frame);
    },

    leave: function () {
      if (HolXR.session) HolXR.session.end();
    },

    ended: function () {
      HolXR.session = null;
      HolXR.space = null;
      HolXR.fb = null;
      HolXR.base = null;
      if (HolXR.quad && HolXR.quad.fbName) {
        GLctx.deleteFramebuffer(HolXR.quad.fb);
        GL.framebuffers[HolXR.quad.fbName] = null;
      }
      HolXR.quad = null;
      Module['_hol_web_xr_panel_quad'](0);
      Module['_hol_web_xr_active'](0);
      if (Module['holEvent']) Module['holEvent']('xr', 'ended');
    },

    // The layer's framebuffer as a GL name emscripten's glBindFramebuffer
    // knows (0: the default framebuffer).
    fbId: function (fb) {
      if (!fb) return 0;
      if (fb !== HolXR.fb) {
        var id = GL.getNewId(GL.framebuffers);
        fb.name = id;
        GL.framebuffers[id] = fb;
        HolXR.fb = fb;
        HolXR.fbName = id;
      }
      return HolXR.fbName;
    },

    put: function (f, at, arr, n) {
      for (var i = 0; i < n; i++) f[at + i] = arr && arr[i] !== undefined ? arr[i] : 0;
    },

    pads: function (xrf, f, o, base) {
      for (var h = 0; h < 2; h++) HolXR.put(f, base + o.pad + h * o.pad_size, null, o.pad_size);
      var srcs = xrf.session.inputSources;
      for (var i = 0; i < srcs.length; i++) {
        var src = srcs[i];
        var h = src.handedness === 'left' ? 0 : src.handedness === 'right' ? 1 : -1;
        if (h < 0) continue;
        var p = base + o.pad + h * o.pad_size;
        var gp = src.gamepad;
        if (src.gripSpace) {
          var gpose = xrf.getPose(src.gripSpace, HolXR.space);
          if (gpose) {
            var t = gpose.transform;
            f[p + o.grip_valid] = 1;
            HolXR.put(f, p + o.grip_pos, [t.position.x, t.position.y, t.position.z], 3);
            HolXR.put(f, p + o.grip_quat,
              [t.orientation.x, t.orientation.y, t.orientation.z, t.orientation.w], 4);
          }
        }
        // a tracked hand is there (and is a hand: its pinches are
        // gestures, hol_web_xr.h) with or without a gamepad
        if (src.hand) {
          f[p + o.present] = 1;
          f[p + o.hand] = 1;
          HolXR.joints(xrf, src.hand, f, p + o.joints_valid, p + o.joint);
        }
        var ev = HolXR.held && HolXR.held[src.handedness];
        if (ev && (ev[0] || ev[1])) {
          f[p + o.present] = 1;
          if (ev[0]) f[p + o.button] = 1;
          if (ev[1]) f[p + o.button + 1] = 1;
        }
        if (!gp) continue;
        f[p + o.present] = 1;
        var b = gp.buttons || [];
        f[p + o.touch_layout] = b.length >= 6 && b[4] && b[5] ? 1 : 0;
        for (var k = 0; k < 8; k++)
          f[p + o.button + k] = (b[k] && b[k].pressed) || f[p + o.button + k] ? 1 : 0;
        var ax = gp.axes || [];
        for (var k = 0; k < 4; k++) f[p + o.axes + k] = typeof ax[k] === 'number' ? ax[k] : 0;
      }
    },

    // A tracked hand's 25 joints (XRHand's order): x, y, z in the reference
    // space and the radius each, and 1 at `valid` when every joint has a
    // pose (drawn, and the hands-only recentre: hol_web_xr.h), read with
    // fillPoses and fillJointRadii (the Hand Input module's; no object a
    // joint); none where the browser lacks them.
    joints: function (xrf, hand, f, valid, at) {
      var sp = hand.holSpaces || (hand.holSpaces = Array.from(hand.values()));
      var m = HolXR.jm || (HolXR.jm = new Float32Array(400)), r = HolXR.jr || (HolXR.jr = new Float32Array(25));
      try {
        if (sp.length !== 25 || !xrf.fillPoses(sp, HolXR.space, m) || !xrf.fillJointRadii(sp, r)) return;
      } catch (e) {
        return;
      }
      for (var i = 0; i < 25; i++) {
        f[at + 4 * i] = m[16 * i + 12];
        f[at + 4 * i + 1] = m[16 * i + 13];
        f[at + 4 * i + 2] = m[16 * i + 14];
        f[at + 4 * i + 3] = r[i];
      }
      f[valid] = 1;
    },

    // Bounded-floor: the polygon handed to the C side's fit (hol_web_xr_fit:
    // the room and cell that fit it, told and offered), at most 64 points.
    fit: function () {
      var g = HolXR.space && HolXR.space.boundsGeometry;
      if (!g || g.length < 3) {
        console.log('web: no bounded-floor polygon: the room is not fitted to the play area');
        return;
      }
      var n = Math.min(g.length, 64), p = Module['_hol_web_xr_fit_buffer']() >> 2;
      for (var i = 0; i < n; i++) {
        HEAPF32[p + 2 * i] = g[i].x;
        HEAPF32[p + 2 * i + 1] = g[i].z;
      }
      Module['_hol_web_xr_fit'](n);
    },

    // Bounded-floor: the width and depth of the bounds polygon's box.
    bounds: function () {
      var g = HolXR.space && HolXR.space.boundsGeometry;
      if (!g || g.length < 3) return [0, 0];
      var x0 = 1e9, x1 = -1e9, z0 = 1e9, z1 = -1e9;
      for (var i = 0; i < g.length; i++) {
        x0 = Math.min(x0, g[i].x); x1 = Math.max(x1, g[i].x);
        z0 = Math.min(z0, g[i].z); z1 = Math.max(z1, g[i].z);
      }
      return [x1 - x0, z1 - z0];
    },

    frame: function (t, xrf) {
      var s = HolXR.session;
      if (!s) return;
      s.requestAnimationFrame(HolXR.frame);
      var o = HolXR.offsets();
      var base = Module['_hol_web_xr_frame_buffer']() >> 2;
      var f = HEAPF32;
      HolXR.put(f, base, null, o.frame);
      var vis = s.visibilityState;
      f[base + o.visibility] = vis === 'visible' ? 2 : vis === 'visible-blurred' ? 1 : 0;
      HolXR.put(f, base + o.bounds, HolXR.bounds(), 2);
      var pose = xrf.getViewerPose(HolXR.space);
      var layer = HolXR.base || s.renderState.baseLayer; // with layers, baseLayer is null
      if (pose && !pose.emulatedPosition && !HolXR.tracked) {
        HolXR.tracked = true;
        console.log('web: xr first head-tracked frame ' +
          Math.round(performance.now() - HolXR.enterT) + ' ms after Enter VR');
      }
      if (pose) {
        var tr = pose.transform;
        f[base + o.head_valid] = pose.emulatedPosition ? 2 : 1;
        HolXR.put(f, base + o.head_pos, [tr.position.x, tr.position.y, tr.position.z], 3);
        HolXR.put(f, base + o.head_quat,
          [tr.orientation.x, tr.orientation.y, tr.orientation.z, tr.orientation.w], 4);
        var n = Math.min(pose.views.length, 2);
        f[base + o.nviews] = n;
        for (var i = 0; i < n; i++) {
          var v = pose.views[i], vp = layer.getViewport(v), at = base + o.view + i * o.view_size;
          HolXR.put(f, at + o.vp, [vp.x, vp.y, vp.width, vp.height], 4);
          HolXR.put(f, at + o.proj, v.projectionMatrix, 16);
          var vt = v.transform;
          HolXR.put(f, at + o.pos, [vt.position.x, vt.position.y, vt.position.z], 3);
          HolXR.put(f, at + o.quat,
            [vt.orientation.x, vt.orientation.y, vt.orientation.z, vt.orientation.w], 4);
        }
      }
      HolXR.pads(xrf, f, o, base);
      HolXR.frames++;
      if (!pose) return; // no views to draw this frame (tracking lost)
      var rc = Module['_hol_web_xr_step'](t, HolXR.fbId(layer.framebuffer));
      if (rc !== 0) s.end();
      else if (HolXR.quad) HolXR.quadFrame(xrf);
    }
  },
  $HolXR__postset: 'Module["holXR"] = HolXR;',

  // a controller pulse (hand 0 left, 1 right; amplitude 0..1; ms) on the
  // first haptic actuator of that hand's gamepad; 1 if one was asked
  hol_web_js_pulse__deps: ['$HolXR'],
  hol_web_js_pulse: function (hand, amp, ms) {
    var s = HolXR.session, want = hand ? 'right' : 'left';
    if (!s) return 0;
    var srcs = s.inputSources;
    for (var i = 0; i < srcs.length; i++) {
      var gp = srcs[i].handedness === want && srcs[i].gamepad;
      var a = gp && gp.hapticActuators && gp.hapticActuators[0];
      if (!a || !a.pulse) continue;
      try {
        a.pulse(amp, ms).catch(function () {});
        HolXR.pulses = (HolXR.pulses || 0) + 1;
        return 1;
      } catch (e) {
        return 0;
      }
    }
    return 0;
  },

  hol_web_js_focused__deps: ['$HolXR'],
  hol_web_js_focused: function () {
    return document.hasFocus() && !document.hidden ? 1 : 0;
  },

  // The first user gesture (a click, a key, a touch; Enter VR is a click):
  // a browser lets an AudioContext run only after one (hol_web_sound.c).
  // Module.holAudioState() tells the tests the AudioContext's state
  // (hol_web_al.js keeps it in HolAL.ctx; '' if none).
  $HolGesture: { seen: false },
  $HolGesture__deps: ['$HolAL'],
  $HolGesture__postset:
    '["pointerdown", "mousedown", "keydown", "touchend"].forEach(function (t) {' +
    '  window.addEventListener(t, function () { HolGesture.seen = true; }, true); });' +
    'Module["holAudioState"] = function () {' +
    '  return HolAL.ctx ? HolAL.ctx.state : ""; };',
  hol_web_js_gesture__deps: ['$HolGesture'],
  hol_web_js_gesture: function () {
    return HolGesture.seen ? 1 : 0;
  },

  // environment.csv's strings (hol_web_env.c): 0 os (the user agent's
  // parenthesised part), 1 the browser and version, 2 the controller (in VR
  // the right, else left, input source's profiles[0]; else the first
  // standard gamepad's id), 3 the query string, 4 the GL renderer (the
  // unmasked one where WEBGL_debug_renderer_info exists), 5
  // XRSession.frameRate (also returned: 0 where undefined)
  hol_web_js_env: function (what, buf, cap) {
    var ua = navigator.userAgent, s = HolXR.session, q = s ? s.inputSources : navigator.getGamepads(), b, v, i;
    if (what == 0) v = (/\(([^)]*)/.exec(ua) || [])[1];
    if (what == 1) v = ((/(OculusBrowser|SamsungBrowser|Edg|OPR)\/[\d.]*\d/.exec(ua) ||
      /(Firefox|HeadlessChrome|Chrome|Version)\/[\d.]*\d/.exec(ua) || [])[0] || '').replace('Version', 'Safari');
    if (what == 4) {
      b = GLctx.getExtension('WEBGL_debug_renderer_info');
      v = GLctx.getParameter(b ? b.UNMASKED_RENDERER_WEBGL : GLctx.RENDERER);
    }
    for (i = 0; what == 2 && i < q.length; i++)
      if (s ? !v || q[i].handedness == 'right' : !v && q[i] && q[i].mapping == 'standard')
        v = s ? q[i].profiles[0] : q[i].id;
    if (what == 3) v = location.search.slice(1);
    if (what == 5) v = s && s.frameRate;
    stringToUTF8(v ? String(v) : '', buf, cap);
    return +v || 0;
  },

  hol_web_js_event: function (kind, text) {
    var k = UTF8ToString(kind), t = UTF8ToString(text);
    if (Module['holEvent']) Module['holEvent'](k, t);
  },

  // a User Timing mark (performance.mark): the start's phases and the
  // first frame, for the bench (tests/web/first_frame.mjs)
  hol_web_js_mark: function (name) {
    if (window.performance && performance.mark) performance.mark(UTF8ToString(name));
  },

  hol_web_js_config: function (key, buf, cap) {
    var c = Module['holConfig'] || {};
    var v = c[UTF8ToString(key)];
    stringToUTF8(v === undefined || v === null ? '' : String(v), buf, cap);
  },

  // ---- the store behind the session's sink (hol_web_sink.c, store.js) ----
  hol_web_js_store_open: function (name, append) {
    try {
      return window.holonomyStore.open(UTF8ToString(name), append);
    } catch (e) {
      return -1;
    }
  },
  hol_web_js_store_write: function (h, data, n) {
    return window.holonomyStore.write(h, HEAPU8.subarray(data, data + n)) ? 0 : -1;
  },
  hol_web_js_store_flush: function (h) {
    return window.holonomyStore.flush(h) ? 0 : -1;
  },
  hol_web_js_store_close: function (h) {
    return window.holonomyStore.close(h) ? 0 : -1;
  },
  hol_web_js_store_rename: function (from, to) {
    var ok = window.holonomyStore.rename(UTF8ToString(from), UTF8ToString(to));
    if (ok && Module['holEvent']) Module['holEvent']('saved', UTF8ToString(to));
    return ok ? 0 : -1;
  },
  hol_web_js_store_remove: function (name) {
    return window.holonomyStore.remove(UTF8ToString(name)) ? 0 : -1;
  },
  hol_web_js_store_read: function (name, off, buf, n) {
    var b = window.holonomyStore.read(UTF8ToString(name), off, n);
    if (!b) return -1;
    HEAPU8.set(b, buf);
    return b.length;
  },
  hol_web_js_store_list: function (buf, cap) {
    var s = window.holonomyStore.names().map(function (n) { return n + '\n'; }).join('');
    if (buf) stringToUTF8(s, buf, cap);
    return lengthBytesUTF8(s);
  },
  hol_web_js_store_why: function (buf, cap) {
    stringToUTF8(window.holonomyStore.why(), buf, cap);
  },
  // the session's start (ISO 8601 UTC) and id (YYYYMMDDTHHMMSSZ-XXXXXXXX)
  hol_web_js_meta: function (start, session, cap) {
    var iso = new Date().toISOString().replace(/\.\d+Z$/, 'Z');
    var r = new Uint32Array(1);
    crypto.getRandomValues(r);
    var id = iso.replace(/[-:]/g, '') + '-' + ('0000000' + r[0].toString(16)).slice(-8);
    stringToUTF8(iso, start, cap);
    stringToUTF8(id, session, cap);
  }
};

autoAddDeps(HolWebLib, '$HolXR');
mergeInto(LibraryManager.library, HolWebLib);
