# ga2d_physics — build, test and demo.  Everything generated goes to build/.
#   make          build the examples
#   make demo     build and run the pyramid demo (the README's main job)
#   make sdl      the interactive SDL2 demo (needs libsdl2-dev)
#   make test-browser  the demo's SVG checked in headless Chromium
#   make test     the test suite in every configuration (the README's test command)
#   make bench    benchmarks (tests/bench/): speed is measured here, never in tests
#   make trade    knob sweeps, tables and plots (tests/bench/trade.mk)
#   make bench-peers  ga2d against Box2D 2.4.1 and Chipmunk 7 (tests/bench/peers.mk)
#   make fuzz     libFuzzer harnesses, FUZZ_SECONDS each (tests/fuzz/fuzz.mk)
#   make mutate   planted bugs (tests/mutate/mutants.txt) the suite must catch
#   make clean
# Test configurations are built in parallel; the README quick start is built
# from README.md itself.

CC      ?= cc
BUILD   := build
# -ffp-contract=off: no fused multiply-add, so results do not depend on the
# compiler's choice to contract (determinism across compilers and flags).
OPT     := -O2 -g -ffp-contract=off
# The test configurations without -g (debug info was 40 % of their build
# time, and the builds most of `make test`'s); the sanitizer builds keep
# it (SAN), for the lines in their reports.
TEST_OPT := -O2 -ffp-contract=off
WARN    := -Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion -Werror
INC     := -I.
LIBS    := -lm
HEADER  := ga2d_physics.h
NPROC   := $(shell nproc 2>/dev/null || echo 2)

TEST_SRC := $(sort $(wildcard tests/test_*.c))
TEST_DEP := $(TEST_SRC) tests/test.h $(wildcard tests/*.h tests/fuzz/*.h) examples/task_pool.h $(HEADER)
# sdl_demo.c needs SDL2: built by `make sdl`, not by `make`
EXAMPLES := $(filter-out $(BUILD)/examples/sdl_demo,$(patsubst examples/%.c,$(BUILD)/examples/%,$(wildcard examples/*.c)))

.PHONY: mutants-apply all examples demo sdl test test-build test-browser bench clean check mutate

all: examples
examples: $(EXAMPLES)

$(BUILD)/examples/%: examples/%.c $(HEADER) $(wildcard examples/*.h)
	@mkdir -p $(dir $@)
	$(CC) -std=c99 $(OPT) $(WARN) $(INC) $< -o $@ $(LIBS) -pthread

demo: $(BUILD)/examples/pyramid
	./$(BUILD)/examples/pyramid

# The interactive SDL2 demo (eleven scenes, keys 1-9, 0 and J; drag, throw, toggles; see the file).
sdl: examples/sdl_demo.c $(HEADER)
	@command -v sdl2-config >/dev/null 2>&1 || { echo "make sdl needs SDL2 development files: apt-get install libsdl2-dev"; exit 1; }
	@mkdir -p $(BUILD)/examples
	$(CC) -std=c99 $(OPT) $(WARN) $(INC) examples/sdl_demo.c -o $(BUILD)/examples/sdl_demo $$(sdl2-config --cflags --libs) $(LIBS)

# The pyramid's SVG in headless Chromium (needs chromium and imagemagick).
test-browser: demo
	@sh tests/browser_check.sh

# --- test configurations: name, compiler and language flags ----------------
# C99 float and double, C++11, with gcc and clang; a build with a large
# GA2D_MAX_POLYGON_VERTICES; and address + undefined-behaviour sanitizers.
SAN := -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
TEST_CONFIGS := gcc-c99-float gcc-c99-double gcc-cxx11-float gcc-cxx11-double \
                clang-c99-float clang-c99-double clang-cxx11-float clang-cxx11-double \
                gcc-c99-double-maxv64 asan-ubsan-clang-c99-float asan-ubsan-gcc-c99-double
CFG_gcc-c99-float            := gcc -std=c99
CFG_gcc-c99-double           := gcc -std=c99 -DGA2D_DOUBLE
CFG_gcc-cxx11-float          := g++ -std=c++11 -x c++
CFG_gcc-cxx11-double         := g++ -std=c++11 -x c++ -DGA2D_DOUBLE
CFG_clang-c99-float          := clang -std=c99
CFG_clang-c99-double         := clang -std=c99 -DGA2D_DOUBLE
CFG_clang-cxx11-float        := clang++ -std=c++11 -x c++
CFG_clang-cxx11-double       := clang++ -std=c++11 -x c++ -DGA2D_DOUBLE
CFG_gcc-c99-double-maxv64    := gcc -std=c99 -DGA2D_DOUBLE -DGA2D_MAX_POLYGON_VERTICES=64
CFG_asan-ubsan-clang-c99-float := clang -std=c99 $(SAN)
CFG_asan-ubsan-gcc-c99-double  := gcc -std=c99 -DGA2D_DOUBLE $(SAN)

TEST_BINS := $(addprefix $(BUILD)/tests/,$(TEST_CONFIGS))

$(BUILD)/tests/%: $(TEST_DEP)
	@mkdir -p $(dir $@)
	$(CFG_$*) $(TEST_OPT) $(WARN) $(INC) $(TEST_SRC) -x none -o $@ $(LIBS) -pthread

# The README's quick start, cut out of README.md, must build warning-free as
# C99 and C++11 and run.
$(BUILD)/readme/quickstart.c: README.md
	@mkdir -p $(dir $@)
	awk '/^## Quick start/{q=1} q&&/^```c$$/{f=1;next} f&&/^```$$/{exit} f' README.md > $@
	@test -s $@ || { echo "README.md has no quick start block"; exit 1; }
$(BUILD)/readme/quickstart: $(BUILD)/readme/quickstart.c $(HEADER)
	$(CC) -std=c99 $(OPT) $(WARN) $(INC) $< -o $@ $(LIBS)
	$(CXX) -std=c++11 -x c++ $(OPT) $(WARN) $(INC) $< -x none -o $@-cxx $(LIBS)

# The README's API snippets, each cut out of README.md (the first C block
# under its "### <Heading>:" heading) into build/readme/<name>_snippet.inc
# and run inside tests/readme_<name>.c: each must build as C99 and C++11
# and make what it says.  shapes: a ball, a chain on a ground, a sensor;
# joints: a hinge, a rope, a weld, the mouse drag; queries: a ray, a pick,
# a blast.
README_HEADING_shapes := Shapes
README_HEADING_joints := Joints
README_HEADING_queries := Queries
$(BUILD)/readme/%_snippet.inc: README.md
	@mkdir -p $(dir $@)
	awk '/^### $(README_HEADING_$*):/{q=1} q&&/^```c$$/{f=1;next} f&&/^```$$/{exit} f' README.md > $@
	@test -s $@ || { echo "README.md has no $* block"; exit 1; }
$(BUILD)/readme/%: tests/readme_%.c $(BUILD)/readme/%_snippet.inc $(HEADER)
	$(CC) -std=c99 $(OPT) $(WARN) $(INC) -I$(BUILD)/readme $< -o $@ $(LIBS)
	$(CXX) -std=c++11 -x c++ $(OPT) $(WARN) $(INC) -I$(BUILD)/readme $< -x none -o $@-cxx $(LIBS)

# Determinism (issue 8): the mixed scene of tests/determinism_scene.h must
# hash the same in every build of one precision: gcc and clang, C and C++,
# -O0, -O2 and -O3 (all with -ffp-contract=off; never -ffast-math), and the
# solver's lanes as 16-byte compiler vectors, 32-byte ones (AVX2) or, with
# GA2D_NO_SIMD, plain structs.
DET_VARIANTS := gcc-O0 gcc-O2 gcc-O3 clang-O0 clang-O3 gxx-O2 clangxx-O2 gccnosimd-O2 clangnosimd-O3
DET_CC_gcc     := gcc -std=c99
DET_CC_gccnosimd   := gcc -std=c99 -DGA2D_NO_SIMD
DET_CC_clangnosimd := clang -std=c99 -DGA2D_NO_SIMD
# 8 lanes where the processor has AVX2: the lane count changes no bit either
ifeq ($(shell grep -qw avx2 /proc/cpuinfo 2>/dev/null && echo yes),yes)
DET_VARIANTS += gccavx2-O2 clangavx2-O3
endif
DET_CC_gccavx2     := gcc -std=c99 -mavx2
DET_CC_clangavx2   := clang -std=c99 -mavx2
DET_CC_clang   := clang -std=c99
DET_CC_gxx     := g++ -std=c++11 -x c++
DET_CC_clangxx := clang++ -std=c++11 -x c++
DET_BINS := $(foreach p,float double,$(addprefix $(BUILD)/det/$(p)-,$(DET_VARIANTS)))
DET_FLAGS_float  :=
DET_FLAGS_double := -DGA2D_DOUBLE
# The pinned hashes: a change that alters the scene's bits says why in its
# commit and updates them here.
DET_PINS := float:cb0284c3b9263554 double:23bf545268d43496

$(BUILD)/det/%: tests/determinism.c tests/determinism_scene.h $(HEADER)
	@mkdir -p $(dir $@)
	$(DET_CC_$(word 2,$(subst -, ,$*))) $(DET_FLAGS_$(word 1,$(subst -, ,$*))) -$(word 3,$(subst -, ,$*)) -ffp-contract=off $(WARN) $(INC) $< -x none -o $@ $(LIBS)

test-build: $(TEST_BINS) $(BUILD)/readme/quickstart $(BUILD)/readme/shapes $(BUILD)/readme/joints $(BUILD)/readme/queries $(DET_BINS)

# Runs every configuration (built in parallel), prints each one's summary,
# and ends with the total line "N passed, N failed".
test:
	@$(MAKE) --no-print-directory -j$(NPROC) test-build
	@echo "README quick start:" && ./$(BUILD)/readme/quickstart && ./$(BUILD)/readme/quickstart-cxx >/dev/null
	@./$(BUILD)/readme/shapes && ./$(BUILD)/readme/shapes-cxx && echo "README shapes snippet: built and ran (C99, C++11)"
	@./$(BUILD)/readme/joints && ./$(BUILD)/readme/joints-cxx && echo "README joints snippet: built and ran (C99, C++11)"
	@./$(BUILD)/readme/queries && ./$(BUILD)/readme/queries-cxx && echo "README queries snippet: built and ran (C99, C++11)"
	@echo "determinism: one hash per precision over $(words $(DET_BINS)) builds" && \
	  for p in float double; do \
	    for b in $(BUILD)/det/$$p-*; do ./$$b || { echo "  $$b: failed (above)"; exit 1; }; done | sort | uniq -c; \
	    n=$$(for b in $(BUILD)/det/$$p-*; do ./$$b; done | sort -u | wc -l); \
	    test "$$n" = 1 || { echo "  determinism FAILED: $$p builds disagree"; exit 1; }; \
	    got=$$(./$(BUILD)/det/$$p-gcc-O2 | cut -d' ' -f2); \
	    echo " $(DET_PINS) " | grep -q " $$p:$$got " || \
	      { echo "  determinism FAILED: $$p hash $$got is not the pinned one ($(DET_PINS))"; exit 1; }; \
	  done; echo "  pinned: $(DET_PINS)"
	@sh tests/run_all.sh $(TEST_BINS)

# One configuration (C99 float, gcc) and the float determinism pin, for the
# edit-test loop.  make check T=solver runs only the tests named so.
check: $(BUILD)/tests/gcc-c99-float $(BUILD)/det/float-gcc-O2 mutants-apply
	@got=$$(./$(BUILD)/det/float-gcc-O2 | cut -d' ' -f2); echo " $(DET_PINS) " | grep -q " float:$$got " || \
	  { echo "determinism FAILED: float hash $$got is not the pinned one ($(DET_PINS))"; exit 1; }
	./$(BUILD)/tests/gcc-c99-float $(T)

# Every planted bug of tests/mutate/mutants.txt still applies to the header
# (its from text found exactly once): an edit that moves a line a mutant
# names fails make check at once, not make mutate's long run.
mutants-apply:
	@mkdir -p $(BUILD)/mutate && for n in $$(awk -v mode=list -f tests/mutate/mutate.awk tests/mutate/mutants.txt | cut -f1); do \
	  awk -v mode=apply -v name="$$n" -v out=$(BUILD)/mutate/apply-check.h -f tests/mutate/mutate.awk tests/mutate/mutants.txt $(HEADER) || exit 1; \
	done

# --- benchmarks: tests/bench/bench_*.c, each given a CSV path under build/bench
BENCH_SRC  := $(wildcard tests/bench/bench_*.c)
BENCH_BINS := $(patsubst tests/bench/%.c,$(BUILD)/bench/%,$(BENCH_SRC))

$(BUILD)/bench/%: tests/bench/%.c $(HEADER) examples/task_pool.h
	@mkdir -p $(dir $@)
	$(CC) -std=c99 $(OPT) $(WARN) $(INC) $< -o $@ $(LIBS) -pthread

# make test builds the bench drivers too: they read private names of the
# header, and a rename must fail the tests, not the next make bench
test-build: $(BENCH_BINS)

bench: $(BENCH_BINS)
	@for b in $(BENCH_BINS); do echo "== $$b"; ./$$b $(BUILD)/bench/$$(basename $$b).csv || exit 1; done

# --- mutation check: each planted bug of tests/mutate/mutants.txt, one at a
#     time in a copy of the header, must make the suite fail (C99 float with
#     gcc, or double where a mutant says so).  make mutate M="name ..." runs
#     only those named.
mutate:
	@CC=gcc sh tests/mutate/run.sh $(M)

# --- make trade (tests/bench/trade.mk), make bench-peers (tests/bench/peers.mk),
#     make fuzz (tests/fuzz/fuzz.mk)
-include tests/bench/trade.mk tests/bench/peers.mk tests/fuzz/fuzz.mk

clean:
	rm -rf $(BUILD)
