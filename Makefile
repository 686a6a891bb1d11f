# rastrum - build, test and install the C core and the Python package.
#
#   make                 build/librastrum.a and build/librastrum.so
#   make test            C tests, then the Python tests (installs the package and the optional extras)
#   make test-core       C tests, then the Python tests with only pytest and hypothesis
#   make test-wheel      the wheel (cp39-abi3) installed into two Python versions and tested there
#   make demo            render the demo pictures to out/ and print a short speed table
#   make bench           the full benchmarks (installs the peers: OpenCV, skia, ...)
#   make docs            the documentation site (mkdocs) into build/site
#   make figures         the pictures of README and docs drawn again; figures-check compares (CI)
#   make asan            C and Python tests under AddressSanitizer + UBSan
#   make strict          the core and the Python glue under gcc and clang, -std=c99 -pedantic -Werror
#   make valgrind        C tests under valgrind memcheck, then valgrind-py
#   make valgrind-c      the C tests alone under valgrind memcheck
#   make valgrind-py     a quick profile of the Python tests under memcheck
#   make firmware-check  the core for Cortex-M0 and rv32: no float, heap or stdio; .text sizes,
#                        and what the firmware examples link (examples/firmware_*.c)
#   make cross-check     C tests on 32-bit ARM and big-endian MIPS (qemu), same pixels as x86
#   make install         PREFIX=/usr/local DESTDIR= : header, libraries, rastrum.pc, CMake package
#   make uninstall       the reverse
#   make example         the pkg-config example (after make install)
#   make display-example a 320x240 RGB565 display fed spans band by band (run by test-c)
#   make single          build/single/rastrum.[ch]: the whole core in one file
#   make test-single     the C tests against the single-file build
#   make test-config     a cut build configuration: left-out features refused, kept ones unchanged
#   make display-qemu    the display example on an emulated Cortex-M (qemu-system-arm)
#   make fuzz-check      libFuzzer targets (clang): the corpus, then FUZZ_SECONDS=20 each (CI: 30)
#   make fuzz-regress    the fuzz targets over the corpus without libFuzzer (gcc, sanitizers)
#   make fuzz-long       each libFuzzer target for FUZZ_SECONDS (default 600), two at a time;
#                        executions and coverage to bench/fuzz-long.txt, corpus merged (-merge=1)
#   make race-check      seed fills racing a writer thread, under ASan+UBSan and under TSan

CC      ?= cc

# Python: an explicit PYTHON=..., else the active virtualenv's interpreter,
# else the project's own virtualenv .venv, made on first use from
# BASE_PYTHON (Debian's python3 is "externally managed": pip refuses to
# install into it, so nothing is ever installed outside a virtualenv).
BASE_PYTHON ?= python3
ifeq ($(origin PYTHON),undefined)
  ifneq ($(VIRTUAL_ENV),)
    PYTHON := $(VIRTUAL_ENV)/bin/python
  else
    PYTHON := $(CURDIR)/.venv/bin/python
    VENV   := $(CURDIR)/.venv/bin/python
  endif
endif
PREFIX  ?= /usr/local
DESTDIR ?=
LIBDIR  ?= $(PREFIX)/lib
INCDIR  ?= $(PREFIX)/include
# LICENSE and CHANGELOG.md go here (make install), as Debian and the GNU
# layout keep a package's documents.
DOCDIR  ?= $(PREFIX)/share/doc/rastrum

WARN    := -std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -Wdouble-promotion \
           -Wstrict-prototypes -Wmissing-prototypes -Wcast-align -Wconversion \
           -Wno-sign-conversion
CFLAGS  ?= -O2
ALL_CFLAGS = $(WARN) $(CFLAGS) -Icsrc/include -Icsrc/src

SRC     := $(wildcard csrc/src/*/*.c)
# The Python binding's C glue (not the core: it may use double and malloc),
# built into the extension by python/rastrum/_build.py and checked by make
# strict with the same warnings.
GLUE_SRC := $(wildcard python/glue/*.c)
# rastrum._seq, a CPython extension of its own (it reads Python lists; the
# limited API), built by setup.py and checked by make strict likewise.
EXT_SRC := $(wildcard python/ext/*.c)
HDR     := csrc/include/rastrum.h $(wildcard csrc/src/*/*.h)
OBJ     := $(SRC:csrc/src/%.c=build/obj/%.o)
PIC_OBJ := $(SRC:csrc/src/%.c=build/pic/%.o)

# The soname carries the major version, read from the header.
VERSION_MAJOR := $(shell sed -n 's/^\#define RAST_VERSION_MAJOR \([0-9]*\)/\1/p' csrc/include/rastrum.h)
VERSION_MINOR := $(shell sed -n 's/^\#define RAST_VERSION_MINOR \([0-9]*\)/\1/p' csrc/include/rastrum.h)
VERSION_PATCH := $(shell sed -n 's/^\#define RAST_VERSION_PATCH \([0-9]*\)/\1/p' csrc/include/rastrum.h)
VERSION := $(VERSION_MAJOR).$(VERSION_MINOR).$(VERSION_PATCH)
SONAME  := librastrum.so.$(VERSION_MAJOR)

# setuptools keeps its objects in build/temp.* and reuses them whenever the
# sources are older, whatever the flags: a sanitizer build (asan-py) would
# then leak into the next plain or valgrind install.  Every pip install of
# the package starts from none.
PY_CLEAN := rm -rf build/lib.* build/temp.* build/bdist.*

# What the sanitizer and valgrind runs need beside the package they build.
PY_TEST_DEPS := setuptools wheel cffi numpy Pillow pytest hypothesis

# The project virtualenv, with what a --no-build-isolation build needs.
$(CURDIR)/.venv/bin/python:
	@$(BASE_PYTHON) -c 'import ensurepip, venv' 2>/dev/null || { echo "make: $(BASE_PYTHON) cannot make a virtualenv;" \
	  "on Debian/Ubuntu: sudo apt-get install python3-venv python3-dev (or run make with PYTHON=/path/to/python)"; exit 1; }
	$(BASE_PYTHON) -m venv $(CURDIR)/.venv
	$(CURDIR)/.venv/bin/python -m pip install --quiet --disable-pip-version-check --upgrade pip setuptools wheel cffi

C_TESTS := $(patsubst tests/c/%.c,build/tests/%,$(wildcard tests/c/test_*.c))
comma   := ,
SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g

.PHONY: test-c-size test-wheel test-core figures figures-check test-config race-check fuzz-long bench docs bench-precision cbench-coverage cbench-scale bench-precision-callgrind single test-single display-qemu fuzz-check fuzz-regress display-example valgrind valgrind-c valgrind-py firmware-check cross-check all lib test test-c test-install test-py demo asan asan-c asan-py strict install uninstall example clean

all: lib
lib: build/librastrum.a build/librastrum.so

build/obj/%.o: csrc/src/%.c $(HDR)
	@mkdir -p $(@D)
	@$(CC) $(ALL_CFLAGS) -c $< -o $@

build/pic/%.o: csrc/src/%.c $(HDR)
	@mkdir -p $(@D)
	@$(CC) $(ALL_CFLAGS) -fPIC -fvisibility=hidden -c $< -o $@

build/librastrum.a: $(OBJ)
	rm -f $@
	$(AR) rcs $@ $^

build/librastrum.so: $(PIC_OBJ)
	$(CC) -shared -Wl,-soname,$(SONAME) $^ -o build/librastrum.so.$(VERSION)
	ln -sf librastrum.so.$(VERSION) build/$(SONAME)
	ln -sf $(SONAME) $@

build/tests/%: tests/c/%.c build/librastrum.a tests/c/check.h tests/c/ref.h tests/c/scratch.h tests/c/rings.h tests/c/row_canvas.h tests/c/byte_canvas.h tests/c/range_rings.h tests/c/wound_check.h
	@mkdir -p $(@D)
	@$(CC) $(ALL_CFLAGS) -Wno-conversion -Itests/c $< build/librastrum.a -o $@

# the glue's ring-size checks: the glue compiled in (#include)
build/tests/test_glue_rings: $(GLUE_SRC) $(wildcard python/glue/*.h)

# ---- tests -----------------------------------------------------------------
test: test-c test-install test-py

test-c: $(C_TESTS)
	@for t in $(C_TESTS); do echo "== $$t"; ./$$t || exit 1; done
test-c: display-example test-c-size

# The firmware example: scene, spans, band by band, one static arena.
display-example: build/librastrum.a
	@$(CC) $(WARN) -O2 -Icsrc/include examples/display_rgb565.c build/librastrum.a -o build/display_rgb565
	@./build/display_rgb565 build/display_rgb565.ppm

# The C packaging as a user meets it: the README's C example and install
# steps as written (pkg-config and CMake), one .pc per PREFIX, DESTDIR,
# uninstall (tools/test-install.sh).
test-install: lib
	@tools/test-install.sh

# PY_TEST_EXTRAS: the extras the tests run with.  All of them by default:
# the optional inputs (shapely, affine, tqdm), the peers the compatibility
# tests compare with (rasterio, geopandas, pycocotools) and Dask
# (dask.distributed, dask-geopandas, xarray, rioxarray) for rastrum.dask;
# with fewer (PY_TEST_EXTRAS=test) those tests skip.
# test-py says what it installs, and why, before installing it
# (tools/extras.py reads the extras from pyproject.toml).
PY_TEST_EXTRAS ?= test,gis,compat-test,dask
test-py: | $(VENV)
	@$(PYTHON) tools/extras.py $(PY_TEST_EXTRAS)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check '.[$(PY_TEST_EXTRAS)]'
	$(PYTHON) -m pytest -q --durations=15 tests

# The wheel as a user installs it: built once (cp39-abi3), installed into
# fresh virtualenvs of the oldest and newest Python found (pyenv's, python3.N
# on PATH; WHEEL_PYTHONS="py1 py2" to choose), a few test files run against
# it there (tools/test-wheel.sh).  Fewer than two Pythons fails, with why.
test-wheel: | $(VENV)
	@tools/test-wheel.sh $(PYTHON) $(CURDIR)/build/test-wheel

# The core alone: the C tests, then the Python tests with only pytest and
# hypothesis installed (the tests of the optional inputs and the peers skip);
# make test is the full run, the README's test command.
test-core: PY_TEST_EXTRAS := test
test-core: test-c test-py

# ---- demo and benchmarks --------------------------------------------------------
# The demo needs only the package (numpy, Pillow): the pictures, then a short
# table against whichever peers happen to be installed.  The full benchmarks
# install the peers ('.[bench]', several hundred MB) and take minutes.
demo: | $(VENV)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check .
	$(PYTHON) bench/demo.py --out out

bench: | $(VENV)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check '.[bench,test]'
	$(PYTHON) bench/bench.py
	$(PYTHON) bench/bench_triangles.py
	$(PYTHON) bench/bench_shade.py
	$(PYTHON) bench/bench_seedfill.py
	$(PYTHON) bench/bench_threads.py --quick
	$(PYTHON) bench/bench_scale.py --sizes 512 --json bench/scale.json
	$(PYTHON) bench/scale_report.py bench/scale.json --plot docs/scale_frontier.png

# ---- figures -------------------------------------------------------------------
# make figures: the pictures of README.md and docs/ drawn again into docs/
# (bench/demo.py, tools/coco_picture.py; tools/figures.py lists which comes
# from where).  make figures-check (CI): draws them into a scratch folder and
# compares pixels, and compares the firmware size tables with make
# firmware-check's output (run again when the core is newer than it).
# Timing tables are not drift-checked: they vary from run to run.
figures: | $(VENV)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check .
	$(PYTHON) tools/figures.py make

figures-check: | $(VENV)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check .
	@if [ ! -f build/fw-report.txt ] || [ -n "$$(find csrc examples tools/firmware tools/firmware-check.sh \
	     -newer build/fw-report.txt -type f | head -1)" ]; then $(MAKE) --no-print-directory firmware-check; fi
	$(PYTHON) tools/figures.py check --firmware-log build/fw-report.txt

# ---- documentation ---------------------------------------------------------------
# mkdocs builds README.md's pages in docs/ into build/site; the API reference
# comes from the docstrings (mkdocstrings).  --strict: a warning fails it.
docs: | $(VENV)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check '.[docs]'
	$(PYTHON) -m mkdocs build --strict --site-dir build/site

# ---- types -------------------------------------------------------------------
# mypy --strict, as a user's script meets the installed package (its
# annotations and py.typed): on tests/test_typed_api.py, which uses every
# public name, and on every Python example of README.md and docs/*.md.
.PHONY: typecheck
typecheck: | $(VENV)
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check '.[typecheck]'
	$(PYTHON) -m mypy --strict --no-incremental tests/test_typed_api.py
	$(PYTHON) tools/typecheck_examples.py

# ---- sanitizers --------------------------------------------------------------
asan: asan-c asan-py

# core_lib DIR, COMPILER AND FLAGS: the core compiled once into DIR/librastrum.a
# for the test programs of one instrumented run to link (compiling it again
# for each of them was most of those runs' time).
core_lib = rm -rf $(1) && mkdir -p $(1)/obj && \
  for f in $(SRC); do $(2) -Icsrc/include -Icsrc/src -c $$f -o $(1)/obj/$$(basename $$f .c).o || exit 1; done && \
  ar rcs $(1)/librastrum.a $(1)/obj/*.o

asan-c:
	@$(call core_lib,build/asan/core,$(CC) $(WARN) -Wno-conversion -O1 $(SAN))
	@for t in $(wildcard tests/c/test_*.c); do \
	  n=build/asan/$$(basename $$t .c); \
	  $(CC) $(WARN) -Wno-conversion -O1 $(SAN) -Icsrc/include -Icsrc/src -Itests/c $$t build/asan/core/librastrum.a -o $$n || exit 1; \
	  echo "== $$n (asan+ubsan)"; ./$$n || exit 1; \
	done

# The C tests that reach the size-optimised builds' own code (what the
# firmware builds compile, #if __OPTIMIZE_SIZE__: "accumulate"'s matching
# of shared edges by their four fields and a 32-bit hash, among others)
# against the core at -Os.
test-c-size:
	@$(call core_lib,build/size/core,$(CC) $(WARN) -Os)
	@for t in test_coverage test_batch; do \
	  $(CC) $(WARN) -Wno-conversion -Os -Icsrc/include -Icsrc/src -Itests/c tests/c/$$t.c build/size/core/librastrum.a -o build/size/$$t || exit 1; \
	  echo "== build/size/$$t (-Os)"; ./build/size/$$t || exit 1; \
	done

# The Python tests against an extension built with the sanitizers, loaded
# into an ordinary interpreter with the ASan runtime preloaded.
asan-py: | $(VENV)
	rm -rf build/asan-py
	$(PYTHON) -m pip install --quiet --disable-pip-version-check $(PY_TEST_DEPS)
	$(PY_CLEAN)
	RASTRUM_CFLAGS="$(SAN) -O1" RASTRUM_LDFLAGS="$(SAN)" \
	  $(PYTHON) -m pip install --quiet --no-deps --no-build-isolation --target build/asan-py/lib .
	LD_PRELOAD="$$($(CC) -print-file-name=libasan.so) $$($(CC) -print-file-name=libubsan.so)" \
	  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  RASTRUM_HYPOTHESIS_PROFILE=quick PYTHONPATH=build/asan-py/lib \
	  $(PYTHON) -m pytest -q -p no:cacheprovider tests

# ---- strict builds -------------------------------------------------------------
strict:
	@pyinc=$$($(BASE_PYTHON) -c "import sysconfig; print(sysconfig.get_paths()['include'])") || exit 1; \
	for cc in gcc clang; do \
	  if command -v $$cc >/dev/null; then \
	    for f in $(SRC) $(GLUE_SRC); do $$cc $(WARN) -O2 -Icsrc/include -Icsrc/src -Ipython/glue -c $$f -o /dev/null || exit 1; done; \
	    for f in $(SRC); do $$cc $(WARN) -Os -Icsrc/include -Icsrc/src -c $$f -o /dev/null || exit 1; done; \
	    for f in $(EXT_SRC); do $$cc $(WARN) -O2 -DPy_LIMITED_API=0x03090000 -I"$$pyinc" -c $$f -o /dev/null || exit 1; done; \
	    echo "strict: $$cc ok"; \
	  else echo "strict: $$cc not installed"; exit 1; fi; \
	done

# ---- valgrind ------------------------------------------------------------------
valgrind: valgrind-c
	@$(MAKE) --no-print-directory valgrind-py

# The C tests alone under memcheck (CI runs them in its C-only lane).
valgrind-c: $(C_TESTS)
	@for t in $(C_TESTS); do echo "== $$t (memcheck)"; \
	  RAST_TEST_QUICK=1 valgrind -q --error-exitcode=1 --leak-check=full ./$$t || exit 1; done

# A quick profile of the Python tests under memcheck, against an extension
# built with -g: the real interpreter binary (not a pyenv shim, which
# valgrind would not follow into), PYTHONMALLOC=malloc so that memcheck
# sees every allocation, and the suppressions of CPython's own noise
# (tools/valgrind-python.supp; never a frame of rastrum).  A few minutes.
# Issue 18 adds the depth-buffer rows (the heap overflow), the checked
# depth property, exact snapping and the public-API fuzz test.
VALGRIND_PY_TESTS ?= tests/test_bad_input.py tests/test_threads.py tests/test_snapping.py \
                     tests/test_hardening2.py tests/test_fuzz_api.py
VALGRIND_PY_K ?= NaN or empty or Fortran or snap or (other_bad_input and depth) or depth_int64 \
                 or depth_reshaped or depth_set_by_hand or half_minus or public_api or every_public_name
valgrind-py: | $(VENV)
	rm -rf build/valgrind-py
	$(PYTHON) -m pip install --quiet --disable-pip-version-check $(PY_TEST_DEPS)
	$(PY_CLEAN)
	RASTRUM_CFLAGS="-g -O1" $(PYTHON) -m pip install --quiet --no-deps --no-build-isolation \
	  --target build/valgrind-py/lib .
	PYTHONMALLOC=malloc RASTRUM_HYPOTHESIS_PROFILE=valgrind PYTHONPATH=build/valgrind-py/lib \
	  valgrind -q --error-exitcode=1 --suppressions=tools/valgrind-python.supp \
	  "$$($(PYTHON) -c 'import sys; print(sys.executable)')" -m pytest -q -p no:cacheprovider \
	  -k "$(VALGRIND_PY_K)" $(VALGRIND_PY_TESTS)

# ---- one file ------------------------------------------------------------------
# build/single/rastrum.c and rastrum.h: the whole core as one translation
# unit, generated from csrc/ (tools/single.py), for dropping into a firmware
# build.  test-single builds it with the core's warnings under gcc and
# clang and runs every C test against it instead of the library, with
# -DRAST_NO_AVX2: so the C tests run the SSE2 levels of coverage rows here
# and the AVX2 ones (where the processor has it) in make test-c.
SINGLE_TESTS := $(patsubst tests/c/%.c,build/single/tests/%,$(wildcard tests/c/test_*.c))

single: build/single/rastrum.c
build/single/rastrum.c: $(SRC) $(HDR) tools/single.py
	@python3 tools/single.py build/single

build/single/rastrum.o: build/single/rastrum.c
	@for cc in gcc clang; do $$cc $(WARN) -O2 -DRAST_NO_AVX2 -c $< -o $@ || exit 1; done

build/single/tests/%: tests/c/%.c build/single/rastrum.o tests/c/check.h tests/c/ref.h tests/c/scratch.h tests/c/rings.h tests/c/row_canvas.h tests/c/byte_canvas.h tests/c/range_rings.h tests/c/wound_check.h
	@mkdir -p $(@D)
	@$(CC) $(WARN) -Wno-conversion -O2 -Ibuild/single -Icsrc/src -Itests/c $< build/single/rastrum.o -o $@

test-single: $(SINGLE_TESTS)
	@for t in $(SINGLE_TESTS); do echo "== $$t (single-file build)"; ./$$t || exit 1; done

# A build configuration (csrc/src/base/config.h): tests/c/test_config.c
# against the one-file library compiled with tests/c/config_cut.h, then
# with examples/firmware_min_conf.h, checks that the features each leaves
# out are refused cleanly; the pixels of the kept ones must hash as in the
# full build's run.  Then each firmware
# example under its own configuration header draws the picture it draws
# with the full library.
test-config: build/single/rastrum.c build/single/tests/test_config display-example
	@mkdir -p build/config
	@./build/single/tests/test_config > build/config/full.txt
	@grep '^scene ' build/config/full.txt | sort > build/config/full.scenes
	@for conf in config_cut firmware_min_conf; do \
	  for cc in gcc clang; do $$cc $(WARN) -O2 -DRAST_CONFIG_HEADER="\"$$conf.h\"" -Itests/c -Iexamples \
	    -c build/single/rastrum.c -o build/config/rastrum.o || exit 1; done; \
	  $(CC) $(WARN) -Wno-conversion -O2 -DRAST_CONFIG_HEADER="\"$$conf.h\"" -Ibuild/single \
	    -Icsrc/src -Itests/c -Iexamples tests/c/test_config.c build/single/rastrum.c -o build/config/test_$$conf || exit 1; \
	  ./build/config/test_$$conf > build/config/$$conf.txt || { grep -v '^scene ' build/config/$$conf.txt; exit 1; }; \
	  grep -v '^scene ' build/config/$$conf.txt; \
	  grep '^scene ' build/config/$$conf.txt | sort > build/config/$$conf.scenes; \
	  if [ -n "$$(comm -23 build/config/$$conf.scenes build/config/full.scenes)" ]; then \
	    comm -23 build/config/$$conf.scenes build/config/full.scenes; echo "test-config: $$conf: FAILED"; exit 1; fi; \
	  echo "test-config: $$conf.h: $$(wc -l < build/config/$$conf.scenes) kept scenes hash as in the full build"; \
	done
	@for app in firmware_min firmware_tri firmware_lines firmware_gauge; do \
	  $(CC) $(WARN) -O2 -DFIRMWARE_PRINT -Iexamples -Ibuild/single examples/$$app.c \
	    build/single/rastrum.c -o build/config/$$app-full || exit 1; \
	  $(CC) $(WARN) -O2 -DFIRMWARE_PRINT -DRAST_CONFIG_HEADER="\"$${app}_conf.h\"" -Iexamples \
	    -Ibuild/single examples/$$app.c build/single/rastrum.c -o build/config/$$app || exit 1; \
	  f=$$(./build/config/$$app-full) || { echo "$$app: $$f"; exit 1; }; \
	  c=$$(./build/config/$$app) || { echo "$$app (configured): $$c"; exit 1; }; \
	  if [ "$$f" = "$$c" ]; then echo "test-config: $$app under $${app}_conf.h: $$c, as in the full build"; \
	  else echo "test-config: $$app: '$$c' under $${app}_conf.h, '$$f' in the full build"; exit 1; fi; \
	done
	@$(CC) $(WARN) -O2 -DRAST_CONFIG_HEADER='"display_rgb565_conf.h"' -Iexamples -Ibuild/single \
	  examples/display_rgb565.c build/single/rastrum.c -o build/config/display_rgb565
	@./build/config/display_rgb565 build/config/display_rgb565.ppm > build/config/display.log
	@./build/display_rgb565 build/config/display_full.ppm > build/config/display_full.log
	@c=$$(sed -n 's/^frame hash: //p' build/config/display.log); \
	f=$$(sed -n 's/^frame hash: //p' build/config/display_full.log); \
	if [ -n "$$c" ] && [ "$$c" = "$$f" ]; then \
	  echo "test-config: display_rgb565 under display_rgb565_conf.h: frame hash $$c, as in the full build"; \
	else echo "test-config: display_rgb565: frame hash '$$c' under its configuration, '$$f' in the full build"; exit 1; fi

# The display example on an emulated Cortex-M (qemu-system-arm, mps2-an385,
# semihosting), from the single-file build; its frame hash must equal this
# machine's.
display-qemu: single display-example
	@tools/qemu-m/run.sh build/qemu-m

# ---- the 64-bit vertex path's cost (issue 13) ---------------------------------
# The same polygons through the int32 path (S = 8) and the int64 path (S = 8,
# 24, 32), medians side by side in one run; then, with callgrind, the
# instruction counts of one round (repeatable where timings are not).
ROUNDS ?= 31
build/bench_precision: bench/bench_precision.c build/librastrum.a
	@$(CC) $(WARN) -O2 -Icsrc/include $< build/librastrum.a -o $@

# The coverage scenes ("area" and "accumulate") in C alone: medians and an
# image hash per scene, so that two builds can be compared bit for bit;
# `valgrind --tool=callgrind build/cbench_coverage 1 star area` counts one call.
build/cbench_coverage: bench/cbench_coverage.c bench/cbench_time.h build/librastrum.a
	@$(CC) $(WARN) -O2 -Icsrc/include $< build/librastrum.a -lm -o $@

cbench-coverage: build/cbench_coverage
	@./build/cbench_coverage

# Growth with the work (issue 33): seeded scene families at doubling sizes,
# instructions of one call under callgrind, and each method's exponent
# log2(cost(2N) / cost(N)); `build/cbench_scale FAMILY N METHOD` runs one.
build/cbench_scale: bench/cbench_scale.c bench/cbench_time.h build/librastrum.a
	@$(CC) $(WARN) -O2 -Icsrc/include $< build/librastrum.a -lm -o $@

cbench-scale: build/cbench_scale
	@tools/callgrind-scale.sh build/cbench_scale

# The path flattener alone (issue 34): `python bench/dump_path.py FILE`,
# then `valgrind --tool=callgrind --toggle-collect=flatten_pass
# build/cbench_flatten FILE flatten` (or count_pass ... size).
build/cbench_flatten: bench/cbench_flatten.c build/librastrum.a
	@$(CC) $(WARN) -O2 -Icsrc/include $< build/librastrum.a -o $@

bench-precision: build/bench_precision
	@./build/bench_precision $(ROUNDS)

bench-precision-callgrind: build/bench_precision
	@tools/callgrind-precision.sh build/bench_precision

# ---- bare metal --------------------------------------------------------------
# Its output is kept in build/fw-report.txt (make figures-check compares the
# size tables of README.md and docs/c.md with it).
firmware-check: single
	@mkdir -p build; { tools/firmware-check.sh build/fw 2>&1; echo $$? > build/fw-status; } | tee build/fw-report.txt; \
	  s=$$(cat build/fw-status); [ "$$s" -eq 0 ] || rm -f build/fw-report.txt; exit $$s

cross-check:
	@tools/cross-check.sh build/cross

# ---- fuzzing ---------------------------------------------------------------------
# tests/fuzz/fuzz_*.c are libFuzzer targets with their oracle inside.
# fuzz-regress runs each over its committed corpus (tests/fuzz/corpus/NAME)
# through driver.c, with $(CC) and the sanitizers; fuzz-check builds them
# with clang's libFuzzer, runs the corpus and then fuzzes each target for
# FUZZ_SECONDS seconds (new inputs go to build/fuzz/new_NAME, crashes to
# build/fuzz/NAME-crash-*; a crash fails the target).
FUZZ_TARGETS := $(patsubst tests/fuzz/%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_SECONDS ?= 20
FUZZ_CC ?= clang
FUZZ_INC := -Icsrc/include -Icsrc/src -Itests/c
# fuzz_seq embeds the interpreter (python/ext/seq.c takes Python objects):
# its headers and library, from BASE_PYTHON (Debian: python3-dev)
FUZZ_PY = $(shell $(BASE_PYTHON) -c 'import sysconfig as s; v = s.get_config_var; \
  print("-I%s -L%s -lpython%s -Wl,-rpath,%s" % (s.get_paths()["include"], v("LIBDIR"), v("LDVERSION"), v("LIBDIR")))')
fuzz_extra = case $$t in fuzz_seq) x="$(FUZZ_PY)";; *) x=;; esac

fuzz-regress:
	@$(call core_lib,build/fuzz-regress/core,$(CC) -std=c99 -Wall -Wextra -Werror -O1 $(SAN))
	@for t in $(FUZZ_TARGETS); do \
	  $(fuzz_extra); \
	  $(CC) -std=c99 -Wall -Wextra -Werror -O1 $(SAN) $(FUZZ_INC) tests/fuzz/$$t.c tests/fuzz/driver.c \
	    build/fuzz-regress/core/librastrum.a $$x -lm -o build/fuzz-regress/$$t || exit 1; \
	  ./build/fuzz-regress/$$t tests/fuzz/corpus/$$t || exit 1; \
	done

fuzz-check:
	@mkdir -p build/fuzz
	@$(call core_lib,build/fuzz/core,$(FUZZ_CC) -std=c99 -Wall -Wextra -Werror -g -O1 \
	  -fsanitize=fuzzer-no-link$(comma)address$(comma)undefined -fno-sanitize-recover=all)
	@for t in $(FUZZ_TARGETS); do \
	  $(fuzz_extra); \
	  $(FUZZ_CC) -std=c99 -Wall -Wextra -Werror -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
	    $(FUZZ_INC) tests/fuzz/$$t.c build/fuzz/core/librastrum.a $$x -lm -o build/fuzz/$$t || exit 1; \
	  rm -rf build/fuzz/new_$$t; mkdir -p build/fuzz/new_$$t; \
	  if ./build/fuzz/$$t -max_total_time=$(FUZZ_SECONDS) -timeout=20 -print_final_stats=1 \
	       -artifact_prefix=build/fuzz/$$t- build/fuzz/new_$$t tests/fuzz/corpus/$$t \
	       > build/fuzz/$$t.log 2>&1; then \
	    echo "$$t: $$(ls tests/fuzz/corpus/$$t | wc -l) corpus inputs," \
	      "$$(sed -n 's/^stat::number_of_executed_units: *//p' build/fuzz/$$t.log) executions" \
	      "in $(FUZZ_SECONDS) s, 0 crashes"; \
	  else tail -40 build/fuzz/$$t.log; echo "$$t: crashed (build/fuzz/$$t.log)"; exit 1; fi; \
	done

# fuzz-long: each target for FUZZ_SECONDS (default 10 minutes), FUZZ_JOBS
# at a time, niced; the logs go to FUZZ_LOG_DIR and one line per target
# (executions, coverage, corpus size, crashes) to FUZZ_LONG_OUT.  New
# inputs are merged into the committed corpus with -merge=1 (which keeps
# only inputs that add coverage, so the corpus stays small).
FUZZ_JOBS ?= 2
FUZZ_LOG_DIR ?= build/fuzz-long
FUZZ_LONG_OUT ?= bench/fuzz-long.txt
fuzz-long:
	@FUZZ_CC="$(FUZZ_CC)" FUZZ_PY="$(FUZZ_PY)" FUZZ_SECONDS="$(if $(filter command line,$(origin FUZZ_SECONDS)),$(FUZZ_SECONDS),600)" \
	  FUZZ_JOBS="$(FUZZ_JOBS)" FUZZ_LOG_DIR="$(FUZZ_LOG_DIR)" FUZZ_LONG_OUT="$(FUZZ_LONG_OUT)" \
	  tools/fuzz-long.sh $(FUZZ_TARGETS)

# The racing-writer test (tests/race/): a thread writes the target while
# rast_flood_fill / rast_boundary_fill run, RACE_SECONDS in all, under
# ASan + UBSan ($(CC)) and under TSan (clang), the writer's race on the
# pixels being the one suppression (tests/race/tsan.supp).
RACE_SECONDS ?= 2
RACE_FLAGS := -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -O1 -g -pthread \
              -Icsrc/include -Icsrc/src
race-check:
	@mkdir -p build/race
	@$(CC) $(RACE_FLAGS) $(SAN) tests/race/test_race.c $(SRC) -o build/race/test_race_asan
	@echo "== build/race/test_race_asan (asan+ubsan)"; ./build/race/test_race_asan $(RACE_SECONDS)
	@$(FUZZ_CC) $(RACE_FLAGS) -fsanitize=thread tests/race/test_race.c $(SRC) -o build/race/test_race_tsan
	@echo "== build/race/test_race_tsan (tsan)"; \
	  TSAN_OPTIONS="suppressions=tests/race/tsan.supp halt_on_error=1 exitcode=66" \
	  ./build/race/test_race_tsan $(RACE_SECONDS)

# ---- install ----------------------------------------------------------------------
# The .pc file and the CMake package are written for the PREFIX, LIBDIR and
# INCDIR of each install (never a file left from an earlier one, which
# would point at the first PREFIX used).
CMAKEDIR ?= $(LIBDIR)/cmake/rastrum
SUBST = sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' -e 's|@INCDIR@|$(INCDIR)|g' \
            -e 's|@VERSION@|$(VERSION)|g' -e 's|@VERSION_MAJOR@|$(VERSION_MAJOR)|g' \
            -e 's|@SONAME@|$(SONAME)|g'

install: lib
	install -d $(DESTDIR)$(INCDIR) $(DESTDIR)$(LIBDIR)/pkgconfig $(DESTDIR)$(CMAKEDIR) $(DESTDIR)$(DOCDIR)
	install -m 644 LICENSE CHANGELOG.md $(DESTDIR)$(DOCDIR)/
	install -m 644 csrc/include/rastrum.h $(DESTDIR)$(INCDIR)/
	install -m 644 build/librastrum.a $(DESTDIR)$(LIBDIR)/
	install -m 755 build/librastrum.so.$(VERSION) $(DESTDIR)$(LIBDIR)/
	ln -sf librastrum.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/librastrum.so
	$(SUBST) rastrum.pc.in > $(DESTDIR)$(LIBDIR)/pkgconfig/rastrum.pc
	$(SUBST) tools/cmake/rastrum-config.cmake.in > $(DESTDIR)$(CMAKEDIR)/rastrum-config.cmake
	$(SUBST) tools/cmake/rastrum-config-version.cmake.in > $(DESTDIR)$(CMAKEDIR)/rastrum-config-version.cmake
	chmod 644 $(DESTDIR)$(LIBDIR)/pkgconfig/rastrum.pc $(DESTDIR)$(CMAKEDIR)/*.cmake

uninstall:
	rm -f $(DESTDIR)$(INCDIR)/rastrum.h $(DESTDIR)$(LIBDIR)/librastrum.a \
	      $(DESTDIR)$(LIBDIR)/librastrum.so $(DESTDIR)$(LIBDIR)/$(SONAME) \
	      $(DESTDIR)$(LIBDIR)/librastrum.so.$(VERSION) $(DESTDIR)$(LIBDIR)/pkgconfig/rastrum.pc \
	      $(DESTDIR)$(CMAKEDIR)/rastrum-config.cmake $(DESTDIR)$(CMAKEDIR)/rastrum-config-version.cmake
	rm -f $(DESTDIR)$(DOCDIR)/LICENSE $(DESTDIR)$(DOCDIR)/CHANGELOG.md
	-rmdir $(DESTDIR)$(CMAKEDIR) $(DESTDIR)$(DOCDIR) 2>/dev/null

# Build the example through pkg-config, against an installed rastrum
# (PKG_CONFIG_PATH=PREFIX/lib/pkgconfig for a PREFIX pkg-config does not
# search).  The binary records the library's directory (an rpath from
# pkg-config's libdir), so it runs from any PREFIX without LD_LIBRARY_PATH.
example:
	@mkdir -p build
	$(CC) -std=c99 -O2 examples/draw_ppm.c $$(pkg-config --cflags --libs rastrum) \
	  -Wl,-rpath,"$$(pkg-config --variable=libdir rastrum)" -o build/draw_ppm
	./build/draw_ppm build/draw_ppm.ppm

clean:
	rm -rf build out python/rastrum/_native.c python/rastrum/_native*.so
