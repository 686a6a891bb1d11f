# rastrum - build, test and install the C core and the Python package.
#
#   make                 build/librastrum.a and build/librastrum.so
#   make test            C tests, then the Python tests (installs the package)
#   make demo            render the demo scenes to out/ and print the speed table
#   make asan            C and Python tests under AddressSanitizer + UBSan
#   make strict          the core and the Python glue under gcc and clang, -std=c99 -pedantic -Werror
#   make valgrind        C tests under valgrind memcheck, then valgrind-py
#   make valgrind-py     a quick profile of the Python tests under memcheck
#   make firmware-check  the core for Cortex-M0 and rv32: no float, heap or stdio; .text sizes
#   make cross-check     C tests on 32-bit ARM and big-endian MIPS (qemu), same pixels as x86
#   make install         PREFIX=/usr/local DESTDIR= : header, libraries, rastrum.pc
#   make uninstall       the reverse
#   make example         the pkg-config example (after make install)
#   make display-example a 320x240 RGB565 display fed spans band by band (run by test-c)
#   make fuzz-check      libFuzzer targets (clang): the corpus, then FUZZ_SECONDS=20 each (CI: 30)
#   make fuzz-regress    the fuzz targets over the corpus without libFuzzer (gcc, sanitizers)
#   make fuzz-long       each libFuzzer target for FUZZ_SECONDS (default 600), two at a time;
#                        executions and coverage to bench/fuzz-long.txt, corpus merged (-merge=1)
#   make race-check      seed fills racing a writer thread, under ASan+UBSan and under TSan

CC      ?= cc
PYTHON  ?= python3
PREFIX  ?= /usr/local
DESTDIR ?=
LIBDIR  ?= $(PREFIX)/lib
INCDIR  ?= $(PREFIX)/include

WARN    := -std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -Wdouble-promotion \
           -Wstrict-prototypes -Wmissing-prototypes -Wcast-align -Wconversion \
           -Wno-sign-conversion
CFLAGS  ?= -O2
ALL_CFLAGS = $(WARN) $(CFLAGS) -Icsrc/include -Icsrc/src

SRC     := $(wildcard csrc/src/*.c)
# The Python binding's C glue (not the core: it may use double and malloc),
# built into the extension by python/rastrum/_build.py and checked by make
# strict with the same warnings.
GLUE_SRC := $(wildcard python/glue/*.c)
HDR     := csrc/include/rastrum.h $(wildcard csrc/src/*.h)
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

C_TESTS := $(patsubst tests/c/%.c,build/tests/%,$(wildcard tests/c/test_*.c))
SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g

.PHONY: race-check fuzz-long fuzz-check fuzz-regress display-example valgrind valgrind-py firmware-check cross-check all lib test test-c test-install test-py demo asan asan-c asan-py strict install uninstall example clean

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

build/tests/%: tests/c/%.c build/librastrum.a tests/c/check.h tests/c/ref.h tests/c/scratch.h
	@mkdir -p $(@D)
	@$(CC) $(ALL_CFLAGS) -Wno-conversion -Itests/c $< build/librastrum.a -o $@

# ---- tests -----------------------------------------------------------------
test: test-c test-install test-py

test-c: $(C_TESTS)
	@for t in $(C_TESTS); do echo "== $$t"; ./$$t || exit 1; done
test-c: display-example

# The firmware example: scene, spans, band by band, one static arena.
display-example: build/librastrum.a
	@$(CC) $(WARN) -O2 -Icsrc/include examples/display_rgb565.c build/librastrum.a -o build/display_rgb565
	@./build/display_rgb565 build/display_rgb565.ppm

# Install into a stage, build the example through pkg-config, run it; and
# check that DESTDIR is honoured.
test-install:
	@rm -rf build/stage build/destdir
	@$(MAKE) --no-print-directory install PREFIX=$(CURDIR)/build/stage >/dev/null
	@PKG_CONFIG_PATH=$(CURDIR)/build/stage/lib/pkgconfig $(CC) -std=c99 -pedantic -Wall -Werror \
	  examples/draw_ppm.c $$(PKG_CONFIG_PATH=$(CURDIR)/build/stage/lib/pkgconfig pkg-config --cflags --libs rastrum) \
	  -Wl,-rpath,$(CURDIR)/build/stage/lib -o build/draw_ppm
	@./build/draw_ppm build/draw_ppm.ppm
	@$(MAKE) --no-print-directory install DESTDIR=$(CURDIR)/build/destdir PREFIX=/usr >/dev/null
	@test -f build/destdir/usr/include/rastrum.h && test -f build/destdir/usr/lib/pkgconfig/rastrum.pc \
	  && test -f build/destdir/usr/lib/librastrum.a && echo "test-install: 2 passed, 0 failed"
	@$(MAKE) --no-print-directory uninstall DESTDIR=$(CURDIR)/build/destdir PREFIX=/usr >/dev/null
	@test ! -e build/destdir/usr/include/rastrum.h || (echo "uninstall left files"; exit 1)

test-py:
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet '.[test]'
	$(PYTHON) -m pytest -q tests

# ---- demo (the main job) -----------------------------------------------------
demo:
	$(PY_CLEAN)
	$(PYTHON) -m pip install --quiet '.[bench]'
	$(PYTHON) bench/demo.py --out out

# ---- sanitizers --------------------------------------------------------------
asan: asan-c asan-py

asan-c:
	@mkdir -p build/asan
	@for t in $(wildcard tests/c/test_*.c); do \
	  n=build/asan/$$(basename $$t .c); \
	  $(CC) $(WARN) -Wno-conversion -O1 $(SAN) -Icsrc/include -Icsrc/src -Itests/c $$t $(SRC) -o $$n || exit 1; \
	  echo "== $$n (asan+ubsan)"; ./$$n || exit 1; \
	done

# The Python tests against an extension built with the sanitizers, loaded
# into an ordinary interpreter with the ASan runtime preloaded.
asan-py:
	rm -rf build/asan-py
	$(PY_CLEAN)
	RASTRUM_CFLAGS="$(SAN) -O1" RASTRUM_LDFLAGS="$(SAN)" \
	  $(PYTHON) -m pip install --quiet --no-deps --no-build-isolation --target build/asan-py/lib .
	LD_PRELOAD="$$($(CC) -print-file-name=libasan.so) $$($(CC) -print-file-name=libubsan.so)" \
	  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  RASTRUM_HYPOTHESIS_PROFILE=quick PYTHONPATH=build/asan-py/lib \
	  $(PYTHON) -m pytest -q -p no:cacheprovider tests

# ---- strict builds -------------------------------------------------------------
strict:
	@for cc in gcc clang; do \
	  if command -v $$cc >/dev/null; then \
	    for f in $(SRC) $(GLUE_SRC); do $$cc $(WARN) -O2 -Icsrc/include -Icsrc/src -Ipython/glue -c $$f -o /dev/null || exit 1; done; \
	    echo "strict: $$cc ok"; \
	  else echo "strict: $$cc not installed"; exit 1; fi; \
	done

# ---- valgrind ------------------------------------------------------------------
valgrind: $(C_TESTS)
	@for t in $(C_TESTS); do echo "== $$t (memcheck)"; \
	  RAST_TEST_QUICK=1 valgrind -q --error-exitcode=1 --leak-check=full ./$$t || exit 1; done
	@$(MAKE) --no-print-directory valgrind-py

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
                 or depth_reshaped or depth_set_by_hand or half_minus or public_api
valgrind-py:
	rm -rf build/valgrind-py
	$(PY_CLEAN)
	RASTRUM_CFLAGS="-g -O1" $(PYTHON) -m pip install --quiet --no-deps --no-build-isolation \
	  --target build/valgrind-py/lib .
	PYTHONMALLOC=malloc RASTRUM_HYPOTHESIS_PROFILE=valgrind PYTHONPATH=build/valgrind-py/lib \
	  valgrind -q --error-exitcode=1 --suppressions=tools/valgrind-python.supp \
	  "$$($(PYTHON) -c 'import sys; print(sys.executable)')" -m pytest -q -p no:cacheprovider \
	  -k "$(VALGRIND_PY_K)" $(VALGRIND_PY_TESTS)

# ---- bare metal --------------------------------------------------------------
firmware-check:
	@tools/firmware-check.sh build/fw

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

fuzz-regress:
	@mkdir -p build/fuzz-regress
	@for t in $(FUZZ_TARGETS); do \
	  $(CC) -std=c99 -Wall -Wextra -Werror -O1 $(SAN) $(FUZZ_INC) tests/fuzz/$$t.c tests/fuzz/driver.c $(SRC) \
	    -o build/fuzz-regress/$$t || exit 1; \
	  ./build/fuzz-regress/$$t tests/fuzz/corpus/$$t || exit 1; \
	done

fuzz-check:
	@mkdir -p build/fuzz
	@for t in $(FUZZ_TARGETS); do \
	  $(FUZZ_CC) -std=c99 -Wall -Wextra -Werror -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
	    $(FUZZ_INC) tests/fuzz/$$t.c $(SRC) -o build/fuzz/$$t || exit 1; \
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
	@FUZZ_CC="$(FUZZ_CC)" FUZZ_SECONDS="$(if $(filter command line,$(origin FUZZ_SECONDS)),$(FUZZ_SECONDS),600)" \
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
build/rastrum.pc: rastrum.pc.in csrc/include/rastrum.h
	@mkdir -p $(@D)
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(LIBDIR)|' -e 's|@INCDIR@|$(INCDIR)|' \
	    -e 's|@VERSION@|$(VERSION)|' $< > $@

install: lib build/rastrum.pc
	install -d $(DESTDIR)$(INCDIR) $(DESTDIR)$(LIBDIR)/pkgconfig
	install -m 644 csrc/include/rastrum.h $(DESTDIR)$(INCDIR)/
	install -m 644 build/librastrum.a $(DESTDIR)$(LIBDIR)/
	install -m 755 build/librastrum.so.$(VERSION) $(DESTDIR)$(LIBDIR)/
	ln -sf librastrum.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/librastrum.so
	install -m 644 build/rastrum.pc $(DESTDIR)$(LIBDIR)/pkgconfig/

uninstall:
	rm -f $(DESTDIR)$(INCDIR)/rastrum.h $(DESTDIR)$(LIBDIR)/librastrum.a \
	      $(DESTDIR)$(LIBDIR)/librastrum.so $(DESTDIR)$(LIBDIR)/$(SONAME) \
	      $(DESTDIR)$(LIBDIR)/librastrum.so.$(VERSION) $(DESTDIR)$(LIBDIR)/pkgconfig/rastrum.pc

# Build the example through pkg-config, against an installed rastrum.
example:
	$(CC) -std=c99 -O2 examples/draw_ppm.c $$(pkg-config --cflags --libs rastrum) -o build/draw_ppm

clean:
	rm -rf build out python/rastrum/_native.c python/rastrum/_native*.so
