# cli_gl_sync.sh - no GPU sync in the desktop frame path: `holonomy play`
# under Xvfb, its GL entry points counted through the loader
# (tests/gl_sync_count.c, LD_PRELOAD: glGetError, glFinish, glReadPixels,
# glGet*). Over 300 frames after the first, the count is 0; the first frame
# checks errors once (the window's size); with HOLONOMY_GL_DEBUG=1 every
# frame asks (300 glGetError: the counter's control).
. tests/lib.sh
SO=${GL_SYNC_SO:-build/tests/gl_sync_count.so}

if [ ! -f "$SO" ]; then
    echo "note: no $SO (make $SO): the GL calls are not counted"
    finish cli_gl_sync
    exit $?
fi
if ldd "$H" 2>/dev/null | grep -q 'libasan'; then
    echo "note: a sanitizer build (its runtime must load first): the GL calls are not counted"
    finish cli_gl_sync
    exit $?
fi
if ! start_xvfb 37; then
    echo "note: no Xvfb here: the GL calls are not counted"
    finish cli_gl_sync
    exit $?
fi

# sync_run NAME OUT [ENV...]: play 301 frames of an explore level, counting
# from the second frame on
sync_run() {
    name=$1 out=$2; shift 2
    run "$name" 0 env "$@" LD_PRELOAD="$SO" HOL_GL_SYNC_OUT="$out" HOL_GL_SYNC_AFTER=1 \
        "$H" play --mode explore --seed 2 --frames 301 --size 96x72
}
sync_run "play 301 frames" "$T/sync"
grep -qx 'swaps 301' "$T/sync" && ok || bad "frames: $(cat "$T/sync" 2>/dev/null)"
grep -qx 'total 0' "$T/sync" && ok || bad "sync calls in 300 frames: $(tr '\n' ' ' <"$T/sync" 2>/dev/null)"
grep -q 'unwrapped' "$T/sync" && bad "a glGet* the counter cannot count was loaded: $(cat "$T/sync")" || ok

# the control: HOLONOMY_GL_DEBUG=1 checks every frame, and the counter sees it
sync_run "play 301 frames, GL debug" "$T/sync-debug" HOLONOMY_GL_DEBUG=1
grep -qx 'glGetError 300' "$T/sync-debug" && ok || bad "debug: $(tr '\n' ' ' <"$T/sync-debug" 2>/dev/null)"

# the whole run, init included: the first frame's one check is there
run "play 3 frames" 0 env LD_PRELOAD="$SO" HOL_GL_SYNC_OUT="$T/sync-all" \
    "$H" play --mode explore --seed 2 --frames 3 --size 96x72
grep -q '^glGetError [1-9]' "$T/sync-all" && ok || bad "no error check at init: $(cat "$T/sync-all")"

finish cli_gl_sync
