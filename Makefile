# Holonomy - plain GNU make, C11.
#
#   make            build build/holonomy
#   make test       install what is missing (make deps), then build and run
#                   every test (unit, CLI, fuzz-corpus replay)
#   make gen-tiling rewrite core/hol_tile_dfa.h (tests/gen_tiling.c)
#   make gen-font   rewrite core/hol_face_atlas.h (tests/gen_font.c; libstb-dev)
#   make deps       install the Debian packages the project needs (apt-get)
#   make deps-r     Debian's r-base-core: R referees the report's statistics
#                   in make test (tests/cli_report_r.sh; skipped without it)
#   make fuzz       build the libFuzzer harnesses and run each FUZZ_TIME s
#   make bench      build with optimisation and print the benchmark figures
#   make san        run the unit tests under AddressSanitizer + UBSan
#   make san-cli    run the command-line tests against an ASan + UBSan build
#   make kill-test  60 random kills of a study (tests/cli_kills.sh; KILL_TEST_KILLS)
#   make run        install what is missing, build and play in a desktop window
#                   (RUN_ARGS: play's options)
#   make xr         build/xr/holonomy with `holonomy xr` (XR=1 in its own folder)
#   make xr-test    the headset against Monado in a chroot (root; see README)
#   make quest      the Quest APK (needs NDK= and OPENXR_LOADER=; see README)
#   make web        build/web/: the game for browsers (WebGL 2, WebXR), emscripten
#   make web-serve  serve build/web on http://127.0.0.1:8080/ (WEB_PORT), gzip
#                   and brotli precompressed, with cache headers; COLLECT=DIR
#                   receives pupils' answers (WEB_BIND=0.0.0.0 for the LAN;
#                   docs/teaching.md), on web-serve-https too
#   make web-serve-https  serve it over HTTPS on the LAN address (WEB_HTTPS_PORT,
#                   a self-signed certificate; docs/web.md)
#   make web-test   deps-web, the web build, then headless chromium on an
#                   emulated Quest 3
#   make deps-web   Debian's emscripten, chromium, terser, brotli and openssl; npm's
#                   puppeteer-core and iwer, and bids-validator (tests/bids: the
#                   check of report --bids in tests/cli_report_bids.sh)
#   make quest-link-check  the APK's sources compiled and linked for this machine
#   make doc-pictures  every picture in render/doc and docs made again by its command
#                   (docs/pictures.sh; PICTURES_ARGS: e.g. --before, --only NAME)
#   make clean      remove build outputs
#
# Variables: CC (gcc or clang), BUILD (output folder), FUZZ_TIME (seconds),
# HID (hidapi backend: hidraw, the default, or libusb), XR (1: build
# `holonomy xr`, the OpenXR headset layer; needs libopenxr-dev and GLX).

CC      ?= gcc
BUILD   ?= build
OPT     ?= -O2
CSTD    := -std=c11
WARN    := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
CFLAGS  ?=
override CFLAGS += $(CSTD) $(WARN) $(OPT) -g -ffp-contract=off -D_DEFAULT_SOURCE -MMD -MP
LDLIBS  += -lm
FUZZ_CC ?= clang
FUZZ_TIME ?= 60

CORE_SRC := $(wildcard core/*.c)
RENDER_SRC := $(wildcard render/*.c)
CLI_SRC  := $(wildcard platform/cli/*.c)
# Desktop platform services (files, PNG files) shared by the tool, render tests, benches.
PLAT_SRC := $(wildcard platform/file/*.c platform/image/*.c)
# Sound (issue 27): OpenAL Soft, loaded at run time (dlopen), so the tool
# runs silent where libopenal.so.1 is missing (platform/audio/hol_audio.h).
AUDIO_SRC := $(wildcard platform/audio/*.c)
# Gamepads: the pure descriptor parser and report decoder (tests, fuzz,
# benches link these) and the hidapi device layer (the tool only).
# The headset (OpenXR): the pure room/lifecycle part always, the session
# only with `make XR=1` (CI builds and runs it in the Monado chroot).
XR      ?= 0
# The platform shell (platform/shell/, docs/hacking.md "Adding a platform"):
# what every platform shares (the room in a play area, the panel as a quad,
# picking, environment.csv's row, the options' clashes), pure C over the
# core, the renderer's headers and the file layer; every platform links it.
SHELL_SRC := $(wildcard platform/shell/*.c)
XR_PURE_SRC := $(SHELL_SRC) platform/openxr/hol_xr_bind.c platform/openxr/hol_xr_text.c
XR_SRC  := $(XR_PURE_SRC) $(if $(filter 1,$(XR)),$(filter-out $(XR_PURE_SRC),$(wildcard platform/openxr/*.c)))
XR_LIBS := $(if $(filter 1,$(XR)),-lopenxr_loader -lGL -lX11)
ifeq ($(XR),1)
$(BUILD)/platform/cli/cmd_xr.o: override CFLAGS += -DHOL_XR
endif
HID_SRC  := platform/hid/hol_hid_desc.c platform/hid/hol_hid_pad.c platform/hid/hol_hid_link.c \
            platform/hid/hol_hid_script.c
HID_DEV_SRC := platform/hid/hol_hid_dev.c
# hidapi backend: hidraw (default, Linux hidraw nodes) or `make HID=libusb`
# (libusb, where hidraw is not available; detaches the kernel driver).
HID     ?= hidraw
HID_LIBS := -lhidapi-$(HID)
$(BUILD)/platform/hid/hol_hid_dev.o: override CFLAGS += -DHOL_HID_BACKEND='"$(HID)"'
# tests/test_*.c: cmocka suites on the core (also run under sanitizers);
# tests/test_render*.c: suites that also link the renderer and GL.
RENDER_TEST_SRC := $(wildcard tests/test_render*.c)
UNIT_SRC := $(filter-out $(RENDER_TEST_SRC),$(wildcard tests/test_*.c))
CLI_TESTS := $(wildcard tests/cli_*.sh)
# Suites that take long (CPU time measured by tests/timed.sh; cli_serve for
# its wall time, it waits on servers and apt's retries) run first, longest
# first, so that make -j2 does not end with one long suite running alone;
# the others follow in name order (a new suite needs no entry here). The
# order: make test's figures of 2026-11-27 (docs/testing.md, Times).
SLOW_FIRST := cli_play cli_docs cli_harden_logs cli_serve cli_session test_world cli_mock_study cli_kills \
              cli_nav cli_harden test_nav test_render_light cli_level cli_harden_opts cli_replay \
              cli_world cli_meta_summary cli_hostile cli_resume cli_render cli_game cli_sound cli_study \
              cli_harden_signals cli_report cli_gl_sync cli_track test_render_golden test_tile test_app \
              test_level
slow_first = $(foreach s,$(SLOW_FIRST),$(filter %/$(s).c %/$(s).sh,$(1))) \
             $(filter-out $(foreach s,$(SLOW_FIRST),%/$(s).c %/$(s).sh),$(1))
# Libraries the renderer needs (headless OSMesa; EGL for the desktop build).
RENDER_LIBS ?= -lOSMesa -lEGL -lX11 -lz
# tests/bench_render*.c: benches that also link the renderer and GL.
BENCH_RENDER_SRC := $(wildcard tests/bench_render*.c)
# tests/bench_web.c runs natively and in wasm under tests/web/bench.mjs (bench-web).
# tests/bench_ratio.c runs under tests/bench_ratio.sh: {4,5} 3x3 against the
# build before issue 20 (the tilings and room sizes), this commit's core/.
BENCH_SRC := $(filter-out $(BENCH_RENDER_SRC) tests/bench_web.c tests/bench_ratio.c,$(wildcard tests/bench_*.c))
BENCH_BASE_COMMIT ?= 609d0070eb51369e8de0939d12cbe940bcc0cbf5
FUZZ_SRC := $(wildcard fuzz/fuzz_*.c)
# The report module of the tool (`holonomy report`): its own folder.
CLI_SRC += $(wildcard platform/cli/report/*.c)

CORE_OBJ := $(CORE_SRC:%.c=$(BUILD)/%.o)
CLI_OBJ  := $(CLI_SRC:%.c=$(BUILD)/%.o) $(PLAT_SRC:%.c=$(BUILD)/%.o) $(AUDIO_SRC:%.c=$(BUILD)/%.o) \
  $(HID_SRC:%.c=$(BUILD)/%.o) $(HID_DEV_SRC:%.c=$(BUILD)/%.o) $(XR_SRC:%.c=$(BUILD)/%.o)
PLAT_OBJ := $(PLAT_SRC:%.c=$(BUILD)/%.o)
CORE_LIB := $(BUILD)/libholcore.a
RENDER_OBJ := $(RENDER_SRC:%.c=$(BUILD)/%.o)
RENDER_LIB := $(if $(RENDER_SRC),$(BUILD)/libholrender.a)
# The app does not link OSMesa: platform/osmesa/hol_osmesa.h loads it at
# run time (it pulls in LLVM, about 0.1 s of CPU at every start).
APP_LIBS := $(filter-out -lOSMesa,$(if $(RENDER_SRC),$(RENDER_LIBS)))
UNIT_BIN := $(UNIT_SRC:tests/%.c=$(BUILD)/tests/%)
RENDER_TEST_BIN := $(RENDER_TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCH_BIN := $(BENCH_SRC:tests/%.c=$(BUILD)/bench/%)
BENCH_RENDER_BIN := $(BENCH_RENDER_SRC:tests/%.c=$(BUILD)/bench/%)
FUZZ_BIN := $(FUZZ_SRC:fuzz/%.c=$(BUILD)/fuzz/%)

DEB_PACKAGES := make gcc clang libcmocka-dev libosmesa6-dev libegl-dev \
  libgles-dev libhidapi-dev libusb-1.0-0-dev libopenxr-dev \
  libegl-mesa0 libgl1-mesa-dri gcc-aarch64-linux-gnu libc6-dev-arm64-cross \
  qemu-user xvfb xdotool zlib1g-dev libx11-dev libopenal-dev \
  libstb-dev fonts-dejavu-core
# libc6-dev-arm64-cross is only a Recommends of gcc-aarch64-linux-gnu, and
# deps installs without recommends: it must be named here.
# apt waits up to APT_LOCK_WAIT seconds for another apt/dpkg to finish
# (platform/debian/apt_get.sh: dpkg's lock through DPkg::Lock::Timeout, the lists'
# and archives' locks, which that option does not cover, by trying again).
# APT_GET_CMD: the program run (the tests give a fake one).
APT_LOCK_WAIT ?= 120
APT_GET_CMD ?= apt-get
APT_GET = $$SUDO env DEBIAN_FRONTEND=noninteractive APT_GET_CMD=$(APT_GET_CMD) \
  sh platform/debian/apt_get.sh $(APT_LOCK_WAIT)

.PHONY: web web-serve web-serve-https web-test deps-web deps-r bench-web test-suites test-tools FORCE
.PHONY: all test purity fn-length unit render-test cli-test fuzz-replay fuzz bench san san-cli san-all kill-test clean deps xr \
        deps-cross check-clang cross-test run quest quest-help deps-quest quest-check check-hid-libusb deps-xr xr-test soak \
        deps-quest-link quest-link-check

all: $(BUILD)/holonomy

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(CORE_LIB): $(CORE_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

# The renderer's GLSL (render/shaders/*.glsl) as C strings, made in the
# build folder by render/shaders/glsl_c.sh (never committed) for
# render/hol_program.c, the only file that includes it (every build of
# render/: this one, the web's, build_apk.sh and quest_link_check.sh).
GLSL_H := $(BUILD)/gen/hol_glsl.h
$(GLSL_H): render/shaders/glsl_c.sh $(wildcard render/shaders/*.glsl)
	sh render/shaders/glsl_c.sh $@
$(BUILD)/render/hol_program.o: $(GLSL_H)
$(BUILD)/render/hol_program.o: override CFLAGS += -I$(BUILD)/gen

# The build's commit and date (platform/shell/hol_shell_build.h): a header
# in the build folder, remade at every make but rewritten only when its
# text changes, so a new commit recompiles hol_shell_build.c alone (here
# and in the web's build; build_apk.sh and quest_link_check.sh make their own).
BUILD_ID_H := $(BUILD)/gen/hol_build_id.h
$(BUILD_ID_H): FORCE
	@sh platform/shell/build_id.sh $@
$(BUILD)/platform/shell/hol_shell_build.o: $(BUILD_ID_H)
$(BUILD)/platform/shell/hol_shell_build.o: override CFLAGS += -I$(BUILD)/gen

$(RENDER_LIB): $(RENDER_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/holonomy: $(CLI_OBJ) $(RENDER_LIB) $(CORE_LIB)
	$(CC) $(CFLAGS) -o $@ $(CLI_OBJ) $(RENDER_LIB) $(CORE_LIB) $(LDFLAGS) $(APP_LIBS) $(HID_LIBS) $(XR_LIBS) $(LDLIBS)

$(RENDER_TEST_BIN): $(BUILD)/tests/%: tests/%.c $(wildcard tests/*.h) $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB) $(LDFLAGS) -lcmocka $(RENDER_LIBS) $(LDLIBS)

$(BUILD)/tests/test_hid: tests/test_hid.c tests/hid_samples.h $(HID_SRC) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(HID_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The session's POSIX sink (platform/file) beside the core session.
SINK_SRC := platform/file/hol_sink_posix.c
$(BUILD)/tests/test_session: tests/test_session.c $(wildcard tests/*.h) $(SINK_SRC) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(SINK_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# Output targets and the atomic writer (platform/file).
$(BUILD)/tests/test_file: tests/test_file.c platform/file/hol_file.c platform/file/hol_file.h $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< platform/file/hol_file.c $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The headset layer's pure part (room in the stage, fade, lifecycle, bindings).
$(BUILD)/tests/test_xr_%: tests/test_xr_%.c $(XR_PURE_SRC) $(wildcard platform/openxr/*.h platform/shell/*.h) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(XR_PURE_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The shell's pure part (environment.csv's row, the options' clashes).
$(BUILD)/tests/test_shell: tests/test_shell.c $(SHELL_SRC) $(wildcard platform/shell/*.h) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(SHELL_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# A new platform's template (platform/shell/template/, docs/hacking.md
# "Adding a platform"): built and run headless for a few frames by make
# test, so that it cannot rot.
TEMPLATE_SRC := platform/shell/template/hol_template_main.c
$(BUILD)/tests/hol_template: $(TEMPLATE_SRC) $(SHELL_SRC) $(wildcard platform/shell/*.h) $(RENDER_LIB) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(SHELL_SRC) $(RENDER_LIB) $(CORE_LIB) $(LDFLAGS) $(RENDER_LIBS) $(LDLIBS)
.PHONY: template-run
template-run: $(BUILD)/tests/hol_template
	@$(SUITE) "platform template (3 frames, OSMesa)" $< --frames 3

# The web platform's pure part (pancake devices, WebXR frames as records).
WEB_PURE_SRC := platform/web/hol_web_input.c platform/web/hol_web_xr.c $(SHELL_SRC)
$(BUILD)/tests/test_web_%: tests/test_web_%.c $(WEB_PURE_SRC) $(wildcard platform/web/*.h platform/shell/*.h) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(WEB_PURE_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The device layer against a scripted hidapi (tests/fake_hidapi): no device here.
$(BUILD)/tests/test_hid_dev: tests/test_hid_dev.c tests/hid_samples.h tests/fake_hidapi/hidapi/hidapi.h $(HID_SRC) $(HID_DEV_SRC) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Itests/fake_hidapi -o $@ $< $(HID_SRC) $(HID_DEV_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The sound player's hold on OpenAL Soft's loopback device (loaded at run
# time: skipped where libopenal.so.1 is missing, as under qemu).
$(BUILD)/tests/test_audio: tests/test_audio.c $(AUDIO_SRC) platform/audio/hol_audio.h $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(AUDIO_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The report's pictures (platform/cli/report/report_draw.c) and their PNG writer.
REPORT_DRAW_SRC := platform/cli/report/report_draw.c render/hol_face_draw.c render/hol_png.c
$(BUILD)/tests/test_report_draw: tests/test_report_draw.c $(REPORT_DRAW_SRC) platform/cli/report/report_draw.h $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(REPORT_DRAW_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka -lz $(LDLIBS)

# The text face's suite: the CPU rasteriser of the atlas and, for the
# sample sheet (HOL_FONT_SHEET=file.png), the PNG writer.
FONT_TEST_SRC := render/hol_face_draw.c render/hol_png.c platform/file/hol_file.c
$(BUILD)/tests/test_font: tests/test_font.c $(FONT_TEST_SRC) render/hol_face_draw.h $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(FONT_TEST_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka -lz $(LDLIBS)

# The codebook's tables against the writers' headers (platform/cli/codebook.c,
# platform/shell/hol_shell_codebook.c).
$(BUILD)/tests/test_codebook: tests/test_codebook.c platform/cli/codebook.c $(SHELL_SRC) $(wildcard platform/cli/*.h platform/shell/*.h) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< platform/cli/codebook.c $(SHELL_SRC) $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

# The report's CSV field and HTML text (platform/cli/report/report_escape.c).
$(BUILD)/tests/test_report_escape: tests/test_report_escape.c platform/cli/report/report_escape.c platform/cli/report/report_escape.h $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< platform/cli/report/report_escape.c $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

$(BUILD)/tests/%: tests/%.c $(wildcard tests/*.h) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(CORE_LIB) $(LDFLAGS) -lcmocka $(LDLIBS)

$(BENCH_RENDER_BIN): $(BUILD)/bench/%: tests/%.c $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -DNDEBUG -o $@ $< $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB) $(LDFLAGS) $(RENDER_LIBS) $(LDLIBS)

$(BUILD)/bench/bench_hid: tests/bench_hid.c tests/hid_samples.h $(HID_SRC) $(HID_DEV_SRC)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O2 -DNDEBUG -D_DEFAULT_SOURCE -o $@ $< $(HID_SRC) $(HID_DEV_SRC) \
	  $(HID_LIBS) $(LDLIBS)

$(BUILD)/bench/%: tests/%.c $(CORE_SRC)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O2 -DNDEBUG -D_DEFAULT_SOURCE -o $@ $< $(CORE_SRC) $(LDLIBS)

# libFuzzer harnesses (clang); the replay build runs the corpora as tests.
# A harness links the core; FUZZ_EXTRA_<name> adds sources and libraries.
FUZZ_EXTRA_fuzz_png := render/hol_png.c -lz
FUZZ_EXTRA_fuzz_cli := platform/cli/cli_util.c platform/file/hol_file.c platform/file/hol_lines.c
FUZZ_EXTRA_fuzz_lines := platform/cli/cli_util.c platform/file/hol_file.c platform/file/hol_lines.c
FUZZ_EXTRA_fuzz_report_instr := $(addprefix platform/cli/report/,report_stats.c report_answers.c report_instr.c \
  report_file.c report_escape.c) platform/cli/cli_util.c platform/file/hol_file.c \
  platform/file/hol_lines.c platform/cli/codebook.c platform/shell/hol_shell_codebook.c
FUZZ_EXTRA_fuzz_hid_desc := $(HID_SRC)
FUZZ_EXTRA_fuzz_hid_report := $(HID_SRC)
FUZZ_EXTRA_fuzz_hid_script := $(HID_SRC) $(HID_DEV_SRC) $(HID_LIBS)
# The harnesses share one instrumented build of the core (compiled once, not
# once a harness: 15 harnesses compiled the core 15 times); the corpus
# replays of make test link the core library of the plain build.
FUZZ_FLAGS := $(CSTD) -g -O1 -D_DEFAULT_SOURCE -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_CORE_LIB := $(BUILD)/fuzz-core/libholcore.a
$(BUILD)/fuzz-core/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@

$(FUZZ_CORE_LIB): $(CORE_SRC:%.c=$(BUILD)/fuzz-core/%.o)
	@rm -f $@
	$(AR) rcs $@ $^

$(BUILD)/fuzz/%: fuzz/%.c $(wildcard fuzz/*.h) $(FUZZ_CORE_LIB) $(RENDER_SRC) $(HID_SRC) $(PLAT_SRC) $(CLI_SRC)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_EXTRA_$*) $(FUZZ_CORE_LIB) $(LDLIBS)

$(BUILD)/fuzz-replay/%: fuzz/%.c fuzz/replay_main.c $(wildcard fuzz/*.h) $(CORE_LIB) $(RENDER_SRC) $(HID_SRC) $(PLAT_SRC) $(CLI_SRC)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g -D_DEFAULT_SOURCE -o $@ $< fuzz/replay_main.c \
	  $(FUZZ_EXTRA_$*) $(CORE_LIB) $(LDLIBS)

# The desktop game (EGL/X11 window): `make run RUN_ARGS="--mode flag"`.
# run and test install what is missing first (make deps: a second when all
# is present), then build in a make of their own, so that make -j2 never
# compiles before the headers and libraries are there.
run: deps
	@$(MAKE) --no-print-directory $(BUILD)/holonomy
	$(BUILD)/holonomy play $(RUN_ARGS)

# deps first (a fresh clone may lack the compilers and headers), then one
# make of the build and the suites: make -j2 starts the tool's objects first
# (test-tools leads test-suites' list), and a slot the build leaves idle (the
# archive, the link, a make of its own between the two: about 10 s from a
# fresh clone) goes to the next job that can run: the checks of core/, the
# unit suites (they need only the core's library) and their builds; the CLI
# suites start, longest first, once the tool is linked.
test: deps
	@$(MAKE) --no-print-directory test-suites
test-tools: all $(BUILD)/tests/x11_close $(BUILD)/tests/x11_shot $(BUILD)/tests/png_probe \
            $(BUILD)/tests/gl_sync_count.so $(BUILD)/tests/wait_for

# Every suite of make test as one list, CLI, unit and render alike: the long
# ones first (SLOW_FIRST's order), then the rest by name. A unit or render
# suite's program is built just before it runs (make -j2 starts jobs in this
# order), so the builds of the small ones fill the slots beside the long
# suites, and the end is short suites on both slots, not a build then
# test_world alone.
TEST_RUNS := $(patsubst tests/%.sh,cli-run-%,$(CLI_TESTS)) \
             $(patsubst tests/%.c,unit-run-%,$(UNIT_SRC)) \
             $(patsubst tests/%.c,render-run-%,$(RENDER_TEST_SRC))
slow_first_runs = $(foreach s,$(SLOW_FIRST),$(filter %-run-$(s),$(1))) \
                  $(filter-out $(foreach s,$(SLOW_FIRST),%-run-$(s)),$(1))
test-suites: test-tools purity fn-length tiling-gen-check font-gen-check $(call slow_first_runs,$(TEST_RUNS)) fuzz-replay \
             template-run
	@echo "make test: all suites passed"

# The automata of canonical addresses (core/hol_tile_dfa.h) are derived from
# the geometry by tests/gen_tiling.c: `make gen-tiling` rewrites the header,
# and make test checks that the committed header is what the program prints
# (tests/test_tile.c proves the automata against an independent model).
.PHONY: tiling-gen-check gen-tiling
$(BUILD)/tests/gen_tiling: tests/gen_tiling.c
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O2 -D_DEFAULT_SOURCE -o $@ $< -lm

gen-tiling: $(BUILD)/tests/gen_tiling
	$(BUILD)/tests/gen_tiling > core/hol_tile_dfa.h.tmp && mv core/hol_tile_dfa.h.tmp core/hol_tile_dfa.h

tiling-gen-check: $(BUILD)/tests/gen_tiling
	@if $(BUILD)/tests/gen_tiling | cmp -s - core/hol_tile_dfa.h; then \
	  echo "tiling automata: core/hol_tile_dfa.h is what tests/gen_tiling prints"; \
	else echo "core/hol_tile_dfa.h differs from what tests/gen_tiling prints (make gen-tiling)"; \
	  exit 1; fi

# The text face (core/hol_face_atlas.h: DejaVu Sans as a signed-distance
# atlas) is baked by tests/gen_font.c with stb_truetype: `make gen-font`
# rewrites the header, and make test checks that the committed header is
# what the baker prints (skipped, with a line, without libstb-dev or the font).
.PHONY: font-gen-check gen-font
FONT_TTF ?= /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
$(BUILD)/tests/gen_font: tests/gen_font.c
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O2 -ffp-contract=off -D_DEFAULT_SOURCE -Wno-unused-function -o $@ $< -lm

gen-font: $(BUILD)/tests/gen_font
	$(BUILD)/tests/gen_font $(FONT_TTF) > core/hol_face_atlas.h.tmp && mv core/hol_face_atlas.h.tmp core/hol_face_atlas.h

font-gen-check:
	@if [ ! -f /usr/include/stb/stb_truetype.h ] || [ ! -f $(FONT_TTF) ]; then \
	  echo "text face: skipped (no libstb-dev or fonts-dejavu-core to rebake core/hol_face_atlas.h)"; \
	else $(MAKE) --no-print-directory $(BUILD)/tests/gen_font >/dev/null && \
	  if $(BUILD)/tests/gen_font $(FONT_TTF) | cmp -s - core/hol_face_atlas.h; then \
	    echo "text face: core/hol_face_atlas.h is what tests/gen_font prints"; \
	  else echo "core/hol_face_atlas.h differs from what tests/gen_font prints (make gen-font)"; \
	    exit 1; fi; fi

purity: $(CORE_OBJ)
	@sh tests/check_core_purity.sh $(CORE_OBJ)

# The house's rule: no C function over 120 lines in core/, render/, platform/.
fn-length:
	@sh tests/check_fn_length.sh

# Each suite is a target of its own, so make -j2 runs two at once; a suite's
# output is kept until it ends, then printed whole (tests/suite.sh) with its
# time after it ("-- NAME: S.S s, cpu C.C s", tests/timed.sh).
TIMED := sh tests/timed.sh
SUITE := sh tests/suite.sh $(BUILD)/suite-logs
# UNIT_ENV: set for the unit tests only (make san: HOL_TEST_QUICK=1).
UNIT_ENV ?=
# Every suite (unit, render and CLI) runs with malloc's big blocks advised
# onto transparent huge pages: a first touch faults every 2 MB instead of
# every 4 KB, a large part of a short process's CPU in this VM (test_nav
# 9.4 -> 7.6 s of CPU, test_world 11.6 -> 9.2, a 2-frame play 0.34 ->
# 0.25 s). Only the tests' environment: the tool does not set it
# (docs/testing.md). Empty to run without.
TEST_MALLOC_ENV ?= GLIBC_TUNABLES=glibc.malloc.hugetlb=1
unit: $(UNIT_BIN) $(patsubst tests/%.c,unit-run-%,$(call slow_first,$(UNIT_SRC)))
unit-run-%: $(BUILD)/tests/%
	@$(TEST_MALLOC_ENV) $(UNIT_ENV) $(SUITE) $< $<

render-test: $(RENDER_TEST_BIN) $(RENDER_TEST_BIN:$(BUILD)/tests/%=render-run-%)
render-run-%: $(BUILD)/tests/%
	@$(TEST_MALLOC_ENV) $(SUITE) $< $<

# The pictures of README.md and docs/ (render/doc and docs), each made again by its
# one command in docs/pictures.sh from this build (docs/rendering.md#pictures-in-the-docs).
.PHONY: doc-pictures
doc-pictures: $(BUILD)/holonomy $(BUILD)/tests/test_render_panel $(BUILD)/tests/test_render_depth \
              $(BUILD)/tests/test_render_body $(BUILD)/tests/test_font $(BUILD)/tests/png_probe
	BUILD=$(BUILD) sh docs/pictures.sh $(PICTURES_ARGS)

cli-test: $(patsubst tests/%.sh,cli-run-%,$(call slow_first,$(CLI_TESTS)))
cli-run-%: $(BUILD)/holonomy $(BUILD)/tests/x11_close $(BUILD)/tests/x11_shot $(BUILD)/tests/png_probe \
           $(BUILD)/tests/gl_sync_count.so $(BUILD)/tests/wait_for
	@$(TEST_MALLOC_ENV) $(CLI_ENV) HOLONOMY=$(BUILD)/holonomy X11_CLOSE=$(BUILD)/tests/x11_close X11_SHOT=$(BUILD)/tests/x11_shot \
	  PNG_PROBE=$(BUILD)/tests/png_probe GL_SYNC_SO=$(BUILD)/tests/gl_sync_count.so WAIT_FOR=$(BUILD)/tests/wait_for \
	  $(SUITE) tests/$*.sh sh tests/$*.sh

# A test helper (LD_PRELOAD): the GL calls that wait for the GPU, counted
# through eglGetProcAddress (tests/cli_gl_sync.sh).
$(BUILD)/tests/gl_sync_count.so: tests/gl_sync_count.c
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O2 -D_DEFAULT_SOURCE -fPIC -shared -o $@ $< -ldl

# A test helper: a PNG decoded by render/hol_png.c, its colours counted.
$(BUILD)/tests/png_probe: tests/png_probe.c render/hol_png.c render/hol_png.h
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< render/hol_png.c -lz

# A test helper: waits in one process until a file appears, a folder's
# entries change or a process ends (the suites' polls; tests/lib.sh).
$(BUILD)/tests/wait_for: tests/wait_for.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $<

# A test helper: the close button of a window, as a window manager presses it.
$(BUILD)/tests/x11_close: tests/x11_close.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< -lX11

# A test helper: a digest of what a box of a window shows.
$(BUILD)/tests/x11_shot: tests/x11_shot.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< -lX11

# Every harness has a corpus of its own (a missing one fails here).
fuzz-replay: $(FUZZ_SRC:fuzz/%.c=$(BUILD)/fuzz-replay/%) $(FUZZ_SRC:fuzz/%.c=fuzz-corpus-%)
	@echo "fuzz corpora replayed: $(notdir $(FUZZ_SRC:.c=))"
fuzz-corpus-%: $(BUILD)/fuzz-replay/%
	@ls fuzz/corpus/$*/* >/dev/null || { echo "$*: no corpus in fuzz/corpus/$*"; exit 1; }
	@$(SUITE) "fuzz corpus $*" $< fuzz/corpus/$*/*

# Each harness FUZZ_TIME seconds from its corpus (new inputs go to
# $(BUILD)/fuzz/new-NAME, findings to $(BUILD)/fuzz/); make -j2 fuzz runs two
# at once.
fuzz: $(FUZZ_BIN) $(FUZZ_SRC:fuzz/%.c=fuzz-run-%)
fuzz-run-%: $(BUILD)/fuzz/%
	@mkdir -p $(BUILD)/fuzz/new-$*
	@$(SUITE) "$* for $(FUZZ_TIME) s" $< -max_total_time=$(FUZZ_TIME) -print_final_stats=1 \
	  -artifact_prefix=$(BUILD)/fuzz/ $(BUILD)/fuzz/new-$* fuzz/corpus/$*

bench: $(BENCH_BIN) $(BENCH_RENDER_BIN) $(BUILD)/holonomy $(BUILD)/tests/test_sound
	@set -e; for b in $(BENCH_BIN) $(BENCH_RENDER_BIN); do $$b; done
	@sh tests/bench_report.sh $(BUILD)/holonomy
	@sh tests/bench_sound.sh $(BUILD)/holonomy
	@$(BUILD)/tests/test_sound --bench
	@CC="$(CC)" sh tests/bench_ratio.sh $(BUILD) $(BENCH_BASE_COMMIT)
	@if command -v $(EMCC) >/dev/null && [ -x /usr/bin/chromium ] && [ -d tests/web/node_modules ]; \
	then $(MAKE) -s bench-web; \
	else echo "== web: skipped (make deps-web installs emscripten, chromium and the npm packages)"; fi

# The brute-force unit tests run lighter under the sanitizers
# (HOL_TEST_QUICK=1, tests/quick.h); make test runs them in full.
# make san SAN_UNIT_ENV= runs them in full under the sanitizers too.
SAN_UNIT_ENV ?= HOL_TEST_QUICK=1
# The sanitizer build links its runtimes statically and not as PIE: a run
# of the tool then costs about 55 ms of CPU at start, not 80 (the dynamic
# linker no longer applies the 78,000 relocations of ASan's globals and
# UBSan's type data, nor binds libasan's interceptors; CI's CLI suites run
# the tool thousands of times). The checks are the same.
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
SAN_LDFLAGS := -fsanitize=address,undefined -static-libasan -static-libubsan -no-pie
# (recipes run it with +: make sees no $(MAKE) through a variable, and its
# jobserver would not reach the sub-make, which then ran at -j1)
SAN_MAKE = $(MAKE) BUILD=$(BUILD)/san OPT=-O1 CFLAGS="$(SAN_FLAGS)" LDFLAGS="$(SAN_LDFLAGS)"
san:
	+$(SAN_MAKE) UNIT_ENV="$(SAN_UNIT_ENV)" unit

# The command-line tests against the tool itself built with ASan + UBSan
# (Mesa's own leaks are not ours: leak detection is off for the GL paths).
# CLI_ENV: set for the CLI suites only (the unit tests keep leak detection).
CLI_ENV ?=
SAN_CLI_ENV := ASAN_OPTIONS=detect_leaks=0:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1
san-cli:
	+$(SAN_MAKE) CLI_ENV="$(SAN_CLI_ENV)" cli-test
# tests/cli_kills.sh with KILL_TEST_KILLS random kills (CI; make test and
# make san-cli run it with its own 12).
KILL_TEST_KILLS ?= 60
kill-test:
	+$(MAKE) --no-print-directory CLI_ENV="HOL_KILLS=$(KILL_TEST_KILLS)" cli-run-cli_kills
# make san and make san-cli as one make (CI): the unit tests fill the two
# slots of make -j2 while the long CLI suites run, with no idle end between.
san-all:
	+$(SAN_MAKE) CLI_ENV="$(SAN_CLI_ENV)" UNIT_ENV="$(SAN_UNIT_ENV)" cli-test unit

# A warnings check: it builds and links everything, at -O0 (clang's
# warnings do not depend on the optimiser; about half the CPU of -O2).
check-clang:
	$(MAKE) CC=clang BUILD=$(BUILD)/clang OPT=-O0 all $(UNIT_BIN:$(BUILD)/%=$(BUILD)/clang/%)

# The core and its unit tests for the headset's arm64 CPU, run under qemu;
# the renderer is cross-compiled too (its GL tests need a GL, so they run on
# the host only).
# test_report_draw is the desktop report's pictures (zlib, no arm64 zlib here).
# (test_report_draw and test_font link zlib, which the arm64 sysroot lacks)
CROSS_UNIT_SRC := $(filter-out tests/test_report_draw.c tests/test_font.c,$(UNIT_SRC))
cross-test: deps-cross
	$(MAKE) CC=aarch64-linux-gnu-gcc AR=aarch64-linux-gnu-ar BUILD=$(BUILD)/aarch64 \
	  $(CROSS_UNIT_SRC:tests/%.c=$(BUILD)/aarch64/tests/%) $(BUILD)/aarch64/libholrender.a
	@$(MAKE) -s $(patsubst tests/%.c,cross-run-%,$(call slow_first,$(CROSS_UNIT_SRC)))
# Under qemu the brute-force tests run lighter (HOL_TEST_QUICK=1,
# tests/quick.h: the same checks at a smaller depth or count; the host's
# make test runs them in full). CROSS_UNIT_ENV= runs them in full here too.
CROSS_UNIT_ENV ?= HOL_TEST_QUICK=1
cross-run-%:
	@$(CROSS_UNIT_ENV) $(SUITE) "$(BUILD)/aarch64/tests/$* (qemu-aarch64)" \
	  qemu-aarch64 -L /usr/aarch64-linux-gnu $(BUILD)/aarch64/tests/$*

deps:
	@missing=""; a=$$(dpkg --print-architecture); for p in $(DEB_PACKAGES); do \
	  dpkg -s $$p:$$a >/dev/null 2>&1 || dpkg -s $$p >/dev/null 2>&1 || \
	  missing="$$missing $$p"; done; \
	if [ -z "$$missing" ]; then echo "make deps: all packages present"; \
	else SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  echo "make deps: installing$$missing"; \
	  $(APT_GET) update -qq && \
	  $(APT_GET) install -y -qq --no-install-recommends $$missing; fi

# R (Rscript, base R) for tests/cli_report_r.sh: not in deps (about 40 MB
# and more on a bare system); CI installs it before make test.
deps-r:
	@$(MAKE) -s deps DEB_PACKAGES="r-base-core"

# cmocka for arm64 comes from Debian's multiarch archive.
deps-cross: deps
	@if dpkg -s libcmocka-dev:arm64 >/dev/null 2>&1; then :; else \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO dpkg --add-architecture arm64 && $(APT_GET) update -qq && \
	  $(APT_GET) install -y -qq --no-install-recommends libcmocka-dev:arm64; fi

# The Quest APK (platform/android/build_apk.sh; needs NDK= and
# OPENXR_LOADER=, which this machine cannot have: without them it names
# them in one line and stops with exit status 2).
QUEST_DEB_PACKAGES := aapt zipalign android-framework-res cmake curl
quest:
	@NDK="$(NDK)" OPENXR_LOADER="$(OPENXR_LOADER)" BUILD="$(BUILD)" \
	  sh platform/android/build_apk.sh

# A million steps: what the user has seen never changes, memory stays flat
# (not in CI: about 3 minutes).
soak: $(CORE_LIB)
	@mkdir -p $(BUILD)/bench
	$(CC) $(CSTD) $(WARN) -O2 -DNDEBUG -D_DEFAULT_SOURCE -o $(BUILD)/bench/soak_world tests/soak_world.c $(CORE_LIB) $(LDLIBS)
	$(BUILD)/bench/soak_world $(SOAK_STEPS)

# The headset against a real OpenXR runtime: Monado in a Debian trixie
# chroot (tests/xr/, about 1.5 GB, cached at /var/cache/holonomy; needs root).
deps-xr:
	@$(MAKE) -s deps DEB_PACKAGES="debootstrap"

# The headset build in its own folder (XR=1 objects never mix with the
# plain build's: cmd_xr.o differs by -DHOL_XR).
xr:
	$(MAKE) XR=1 BUILD=$(BUILD)/xr $(BUILD)/xr/holonomy

# The host's half: `holonomy render` of the read-back eye and the comparison.
$(BUILD)/xr_png_diff: tests/xr/png_diff.c $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB)
	$(CC) $(CFLAGS) -o $@ $< $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB) $(LDFLAGS) -lz $(LDLIBS)

# The host's look at the lit eyes (tests/xr/lighting.sh).
$(BUILD)/xr_light_probe: tests/xr/light_probe.c $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB)
	$(CC) $(CFLAGS) -o $@ $< $(PLAT_OBJ) $(RENDER_LIB) $(CORE_LIB) $(LDFLAGS) -lz $(LDLIBS)

xr-test: deps-xr $(BUILD)/holonomy $(BUILD)/xr_png_diff $(BUILD)/xr_light_probe
	@HOLONOMY=$(BUILD)/holonomy PNG_DIFF=$(BUILD)/xr_png_diff LIGHT_PROBE=$(BUILD)/xr_light_probe \
	  OUT=$(BUILD)/xr-test sh tests/xr/run.sh

# The libusb hidapi backend builds too (CI builds it beside the default).
# Only the device layer differs between the backends (HOL_HID_BACKEND, and
# the library linked), so it alone is compiled again, and the tool is linked
# with the default build's other objects (not the whole tool built a second
# time: about 40 s of CPU). `make HID=libusb` still builds it all that way.
HID_LIBUSB_OBJ := $(BUILD)/hid-libusb/platform/hid/hol_hid_dev.o
HID_LIBUSB_LINK := $(filter-out $(HID_DEV_SRC:%.c=$(BUILD)/%.o),$(CLI_OBJ)) $(HID_LIBUSB_OBJ) $(RENDER_LIB) $(CORE_LIB)
$(HID_LIBUSB_OBJ): $(HID_DEV_SRC)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -DHOL_HID_BACKEND='"libusb"' -c $< -o $@
$(BUILD)/hid-libusb/holonomy: $(HID_LIBUSB_LINK)
	$(CC) $(CFLAGS) -o $@ $(HID_LIBUSB_LINK) $(LDFLAGS) $(APP_LIBS) -lhidapi-libusb $(XR_LIBS) $(LDLIBS)
check-hid-libusb: $(BUILD)/hid-libusb/holonomy
	@ldd $< | grep -q 'libhidapi-libusb' || { echo "check-hid-libusb: $< does not link libhidapi-libusb"; exit 1; }
	@echo "check-hid-libusb: $< built, linked against libhidapi-libusb"

quest-help:
	@sh platform/android/build_apk.sh --help

# The Debian tools of the Quest build that CI uses (apksigner, which pulls
# in Java, is installed by hand where an NDK exists: apt-get install apksigner).
deps-quest:
	@$(MAKE) -s deps DEB_PACKAGES="$(QUEST_DEB_PACKAGES)"

# What CI checks of the Quest build here: the manifest packaged by aapt,
# and `make quest` without the NDK stopping with exit status 2.
quest-check: deps-quest
	@sh tests/check_quest.sh

# ---- the web build (emscripten: Debian's 3.1.6; README: Web) ---------------
# The same core and renderer on WebGL 2, a thin loop in platform/web/, the
# WebXR glue as a --js-library, and our own page (emcc's -o x.html minifier
# crashes at -O1 and above in Debian's build). emcc finds acorn through
# NODE_PATH; the cache is frozen, so no ports (html5.h, not SDL).
EMCC     ?= emcc
EMCC_ENV := NODE_PATH=/usr/share/nodejs EM_CACHE=/usr/share/emscripten/cache
WEB      := $(BUILD)/web
WEB_SRC  := $(CORE_SRC) $(filter-out render/hol_png.c render/hol_face_draw.c,$(RENDER_SRC)) \
            $(wildcard platform/web/*.c) $(SHELL_SRC) \
            platform/audio/hol_audio.c
WEB_OBJ  := $(WEB_SRC:%.c=$(BUILD)/web-obj/%.o)
# Size (issue 25: the page's transfer at most 162 KB gzip -9, checked by
# make web-test): the code at -Os, but for the core's parts that run every
# frame or build the navigator's table before the first frame, at -O3
# (-Os made the wasm step about 40 % slower; the table's builder,
# hol_nav_table.c, is at -Os since: its first frame the same within the
# noise; hol_room.c and hol_wfc.c, which run on room steps and new tiles,
# likewise since issue 36; hol_tile.c and hol_hyper.c since issue 37's
# last cuts: 0.8 KB), without unrolled loops (issue 37: 0.9 KB; the
# step 5 % slower, the table the same); every object as LLVM bitcode
# (-flto: 3.0 KB, each function keeping its file's level); the link at -Oz
# with binaryen's -Oz once more, emmalloc, and Module read only for what
# page.js gives it; no GL_-prefixed extension names (nothing reads
# GL_EXTENSIONS) and no queue of deferred pointer-lock requests (the one
# request is made in the mousedown handler, where it runs at once): 0.4 KB
# (docs/web.md, "The transfer size").
WEB_HOT  := $(addprefix core/,hol_app_step.c hol_app_geom.c hol_app_view.c hol_math.c hol_motion.c \
  hol_nav.c hol_nav_arena.c hol_nav_field.c hol_nav_line.c \
  hol_world.c hol_world_tree.c)
WEB_OPT  := -Os -flto
WEB_OPT_HOT := -O2 -fno-unroll-loops -flto
WEB_CFLAGS = $(CSTD) $(WARN) $(if $(filter $(WEB_HOT),$<),$(WEB_OPT_HOT),$(WEB_OPT)) -ffp-contract=off \
  -D_DEFAULT_SOURCE -MMD -MP
WEB_LDFLAGS := -Oz -sBINARYEN_EXTRA_PASSES=-Oz -sMALLOC=emmalloc -sENVIRONMENT=web -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 \
  -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=67108864 -sTOTAL_STACK=1048576 \
  '-sINCOMING_MODULE_JS_API=[instantiateWasm,canvas,print,printErr]' \
  -sGL_EMULATE_GLES_VERSION_STRING_FORMAT=0 -sGL_SUPPORT_AUTOMATIC_ENABLE_EXTENSIONS=0 \
  -sTEXTDECODER=2 -sSUPPORT_ERRNO=0 -sGL_EXTENSIONS_IN_PREFIXED_FORMAT=0 \
  -sHTML5_SUPPORT_DEFERRING_USER_SENSITIVE_REQUESTS=0 \
  --js-library platform/web/hol_web_al.js --js-library platform/web/hol_web_lib.js
# The languages of the web build (core/hol_str.h; en always): Dutch costs
# 1.3 KB of the transfer (docs/web.md, "The transfer size").
WEB_LANGS ?= en de
# the objects are made again when these flags change (an -O3 object of an
# older build would otherwise stay): the file holds them, and is written
# only when they differ (no shell at parse time: every make would run it)
WEB_STAMP := $(BUILD)/web-obj/flags.txt
WEB_FLAGS_TEXT := $(CSTD) $(WARN) $(WEB_OPT) $(WEB_OPT_HOT) $(WEB_HOT) $(WEB_LANGS) libm
WEB_PAGE := $(addprefix $(WEB)/,index.html page.js store.js text.js)
WEB_PORT ?= 8080
WEB_HTTPS_PORT ?= 8443
WEB_BIND ?= 127.0.0.1
# COLLECT=DIR: serve.py --collect DIR (pupils' answer files, docs/teaching.md)
WEB_COLLECT = $(if $(COLLECT),--collect $(COLLECT))
# precompressed copies for web-serve: beside build/web, which stays the
# build's own (make bench-web measures its files)
WEB_Z    := $(BUILD)/web-z
WEB_ZIPPED := $(foreach f,holonomy.wasm holonomy.js $(notdir $(WEB_PAGE)),$(WEB_Z)/$(f).gz $(WEB_Z)/$(f).br)

# Without the toolchain, the web goals stop at once with one line that says
# what to run (not make's bare "Error 127" from a missing emcc).
ifneq ($(filter web web-serve web-serve-https bench-web,$(MAKECMDGOALS)),)
ifeq ($(shell command -v $(EMCC) 2>/dev/null),)
$(error emcc (emscripten) is not installed: run make deps-web first, then make $(filter web web-serve web-serve-https bench-web,$(MAKECMDGOALS)))
endif
endif
ifneq ($(filter web-serve web-serve-https,$(MAKECMDGOALS)),)
ifeq ($(shell command -v brotli 2>/dev/null),)
$(error brotli is not installed: run make deps-web first, then make $(filter web-serve web-serve-https,$(MAKECMDGOALS)))
endif
endif

$(WEB_STAMP): FORCE
	@mkdir -p $(dir $@)
	@echo '$(WEB_FLAGS_TEXT)' | cmp -s - $@ || echo '$(WEB_FLAGS_TEXT)' >$@

FORCE:

# the text face's texels packed only (core/hol_face.h: decoded into the
# atlas; the CPU's text drawing, render/hol_face_draw.c, is the report's)
$(BUILD)/web-obj/core/hol_face.o: WEB_CFLAGS += -DHOL_FACE_PACKED
# the string table without the page's words, which text.js carries (1.5 KB),
# in the languages of WEB_LANGS
$(BUILD)/web-obj/core/hol_str.o: WEB_CFLAGS += -DHOL_STR_NO_PAGE $(if $(filter nl,$(WEB_LANGS)),,-DHOL_STR_NO_NL)
# the renderer's and the platform's libm calls on the core's hol_math.h and
# a small exp family (render/hol_libm_web.h: musl's were 10.5 KB of
# the gzip'ed transfer)
$(BUILD)/web-obj/render/%.o $(BUILD)/web-obj/platform/%.o: WEB_CFLAGS += -DHOL_WEB_LIBM_MACROS -include render/hol_libm_web.h
$(BUILD)/web-obj/render/hol_program.o: $(GLSL_H)
$(BUILD)/web-obj/render/hol_program.o: WEB_CFLAGS += -I$(BUILD)/gen
$(BUILD)/web-obj/platform/shell/hol_shell_build.o: $(BUILD_ID_H)
$(BUILD)/web-obj/platform/shell/hol_shell_build.o: WEB_CFLAGS += -I$(BUILD)/gen
# the page shows no worksheet: the lessons' worksheet texts are left out
# (core/hol_lesson_text.c; the transfer size, docs/web.md), and their
# languages are WEB_LANGS's, as the string table's
$(BUILD)/web-obj/core/hol_lesson_text.o: WEB_CFLAGS += -DHOL_LESSON_APP_ONLY $(if $(filter nl,$(WEB_LANGS)),,-DHOL_STR_NO_NL)

$(BUILD)/web-obj/%.o: %.c $(WEB_STAMP)
	@mkdir -p $(dir $@)
	@echo "emcc $<"
	@$(EMCC_ENV) $(EMCC) $(WEB_CFLAGS) -c $< -o $@

# binaryen's -Oz (emscripten's binaryen package) once more on the linked
# wasm, after emcc's own passes: 0.4 KB, and 0.4 KB more with the functions
# sorted by their uses first (--reorder-functions: smaller indices); then
# emscripten's glue minified by Debian's terser (platform/web/minify.mjs;
# about 2.3 KB of the gzip'ed transfer, and 2.4 KB more for its top-level
# names: all renamed but WEB_JS_KEEP, Module for the page and what web-test
# evaluates in the page); a failure leaves no holonomy.js
WEB_JS_KEEP := Module,GL,GLctx,HEAPU8,UTF8ToString
$(WEB)/holonomy.js: $(WEB_OBJ) platform/web/hol_web_lib.js platform/web/hol_web_al.js \
                    platform/web/minify.mjs
	@mkdir -p $(dir $@)
	@echo "emcc -o $@"
	@$(EMCC_ENV) $(EMCC) $(WEB_LDFLAGS) $(WEB_OBJ) -o $@
	@wasm-opt --reorder-functions -Oz --converge $(WEB)/holonomy.wasm -o $(WEB)/holonomy.wasm || { rm -f $@; exit 1; }
	@NODE_PATH=/usr/share/nodejs node platform/web/minify.mjs $@ $@ --toplevel $(WEB_JS_KEEP) || { rm -f $@; exit 1; }

# the page's words in the languages of WEB_LANGS, from core's string table
# (issue 37), by a native tool of tests/ (no test library)
$(BUILD)/tests/gen_page_text: tests/gen_page_text.c $(CORE_LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(CORE_LIB) $(LDFLAGS) $(LDLIBS)
$(WEB)/text.js: $(BUILD)/tests/gen_page_text $(WEB_STAMP)
	@mkdir -p $(dir $@)
	$(BUILD)/tests/gen_page_text $(WEB_LANGS) >$@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }

# the page's scripts minified by terser as the glue is (platform/web/minify.mjs:
# local names only; about 1 KB of the gzip'ed transfer against stripping
# their comment lines and indentation alone; the sources keep them)
$(WEB)/%.js: platform/web/%.js platform/web/minify.mjs
	@mkdir -p $(dir $@)
	@NODE_PATH=/usr/share/nodejs node platform/web/minify.mjs $< $@

# the page without its indentation and its style's comment lines (0.1 KB)
$(WEB)/index.html: platform/web/index.html
	@mkdir -p $(dir $@)
	sed -e 's/^[[:space:]]*//' -e '/^\/\*/,/\*\/$$/d' $< >$@

$(WEB)/%: platform/web/%
	@mkdir -p $(dir $@)
	cp $< $@

web: $(WEB)/holonomy.js $(WEB_PAGE)
	@echo "make web: $(WEB)/ ($$(du -sk $(WEB)/holonomy.wasm | cut -f1) KB wasm); serve it with make web-serve"

$(WEB)/holonomy.wasm: $(WEB)/holonomy.js
	@:
$(WEB_Z)/%.gz: $(WEB)/%
	@mkdir -p $(dir $@)
	gzip -9 -n -c $< > $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }
$(WEB_Z)/%.br: $(WEB)/%
	@mkdir -p $(dir $@)
	brotli -q 11 -c $< > $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }

# platform/web/serve.py: brotli or gzip when the browser takes it, ETag and
# Cache-Control: no-cache (docs/web.md, "Serving").
web-serve: web $(WEB_ZIPPED)
	python3 platform/web/serve.py $(WEB) --precompressed $(WEB_Z) --bind $(WEB_BIND) --port $(WEB_PORT) \
	  $(WEB_COLLECT)

# HTTPS for a headset on the same network: a self-signed certificate for
# the LAN address (WEB_LAN: give one by hand), made once in build/web-cert.
WEB_LAN ?=
web-serve-https: web $(WEB_ZIPPED)
	@lan=$$(sh platform/web/make_cert.sh $(BUILD)/web-cert $(WEB_LAN)) || exit 2; \
	echo "on the headset: https://$$lan:$(WEB_HTTPS_PORT)/ (accept the certificate once: docs/web.md)"; \
	openssl x509 -noout -fingerprint -sha256 -in $(BUILD)/web-cert/cert.pem; \
	python3 platform/web/serve.py $(WEB) --precompressed $(WEB_Z) --bind 0.0.0.0 \
	  --port $(WEB_HTTPS_PORT) --https $(BUILD)/web-cert/cert.pem $(BUILD)/web-cert/key.pem $(WEB_COLLECT)

WEB_DEB_PACKAGES := emscripten chromium brotli openssl python3 curl terser
deps-web:
	@$(MAKE) -s deps DEB_PACKAGES="$(WEB_DEB_PACKAGES)"
	@cd tests/web && if npm ls --depth=0 >/dev/null 2>&1; then echo "make deps-web: npm packages present"; \
	  else npm ci --no-audit --no-fund; fi
	@cd tests/bids && if npm ls --depth=0 >/dev/null 2>&1; then echo "make deps-web: bids-validator present"; \
	  else npm ci --no-audit --no-fund; fi

# Programs for node (wasm embedded: no fetch of a .wasm file under node).
WEB_NODE_FLAGS := -O3 -sENVIRONMENT=node -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1
$(BUILD)/web-node/math_check.js: tests/web/math_check.c tests/math_golden.h core/hol_math.c core/hol_math.h
	@mkdir -p $(dir $@)
	@echo "emcc -o $@"
	@$(EMCC_ENV) $(EMCC) $(WEB_CFLAGS) $(WEB_NODE_FLAGS) tests/web/math_check.c core/hol_math.c -o $@

$(BUILD)/web-node/bench_web.js: tests/bench_web.c tests/bench_util.h $(CORE_SRC) $(wildcard core/*.h)
	@mkdir -p $(dir $@)
	@echo "emcc -o $@"
	@$(EMCC_ENV) $(EMCC) $(CSTD) -O3 -ffp-contract=off -DNDEBUG -D_DEFAULT_SOURCE $(WEB_NODE_FLAGS) \
	  tests/bench_web.c $(CORE_SRC) -o $@

# make bench's web figures (README: Performance)
bench-web: web $(BUILD)/bench/bench_web $(BUILD)/web-node/bench_web.js
	@BENCH_NATIVE=$(BUILD)/bench/bench_web BENCH_WASM=$(BUILD)/web-node/bench_web.js WEB=$(WEB) \
	  node tests/web/bench.mjs

# deps-web first (a fresh clone has no emcc), then the build in a make of
# its own.
web-test: deps-web
	@$(MAKE) --no-print-directory web $(BUILD)/holonomy $(BUILD)/web-node/math_check.js
	@HOLONOMY=$(BUILD)/holonomy WEB=$(WEB) MATH_CHECK=$(BUILD)/web-node/math_check.js \
	  node tests/web/run.mjs

# The APK's native library without the NDK (tests/quest_link_check.sh):
# every source build_apk.sh links (but the NDK's glue and the entry that
# needs its header) compiled for this machine with __ANDROID__, against
# Debian's copies of the NDK's headers, and linked with --no-undefined
# against exactly the libraries build_apk.sh names; then it must fail on
# copies of build_apk.sh without the sound player or without -lopenal
# (tests/quest_link_test.sh).
QUEST_LINK_DEB_PACKAGES := android-liblog-dev android-libnativehelper-dev libopenxr-dev \
  libegl-dev zlib1g-dev libopenal-dev
deps-quest-link:
	@$(MAKE) -s deps DEB_PACKAGES="$(QUEST_LINK_DEB_PACKAGES)"

quest-link-check: deps-quest-link
	@CC=$(CC) sh tests/quest_link_test.sh

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
