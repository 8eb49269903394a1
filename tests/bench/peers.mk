# make bench-peers: ga2d against Box2D 2.4.1 and Chipmunk 7 on the scenes of
# tests/bench/scenes.h (tests/bench/peers/).  Included by the top-level
# Makefile; not part of `make test`.  Needs the Debian packages
# libbox2d-dev and libchipmunk-dev.  BENCH_RUNS=n sets the runs per engine.
#   ./build/bench/peers [scenes] [csv]  runs the scenes named (default: all);
#   make bench-peers PEERS_SCENE=a,b      the same through make (names separated by commas)
# Where the CPU has AVX2, ga2d is also built a second time with -mavx2 and
# run as a fourth engine, ga2d-avx2 (PEERS_AVX2=0 leaves it out).
#
# Box2D v3 side by side: B2V3_SRC=<a Box2D v3 source tree> (a clone of its
# public repository: src/*.c, include/box2d/*.h) builds Box2D v3 from those
# sources with the C compiler into $(BUILD)/bench/b2v3/ (never into this
# tree; no cmake) and runs it as one more engine, "Box2D-v3", in the same
# invocation, engines alternating, one worker, 4 substeps at 60 Hz, its
# defaults otherwise; the tables then also give ga2d/v3 and v3/2.4.1.
#   make bench-peers B2V3_SRC=/path/to/box2d      (binary: $(BUILD)/bench/peers-v3)
# The flags are those of its CMake build for a generic x86-64 Release-like
# build: C17 with extensions, -O2 -DNDEBUG, -ffp-contract=off (its
# determinism setting), hidden visibility, its default SIMD (SSE2 on
# x86-64: BOX2D_AVX2 is off by default; B2V3_CFLAGS_EXTRA=-mavx2
# -DBOX2D_AVX2 would build its AVX2 path).  Without B2V3_SRC nothing of this
# is built and the tables are as before.

PEERS_DIR  := tests/bench/peers
PEERS_BIN  := $(BUILD)/bench/peers
PEERS_OBJ  := $(BUILD)/bench/peers-obj
PEERS_CSV  := $(BUILD)/bench/peers.csv
PEERS_CC   ?= gcc
PEERS_CXX  ?= g++
PEERS_WARN := -Wall -Wextra -Wpedantic -Wshadow -Werror
PEERS_LIBS := -lbox2d -lchipmunk
PEERS_AVX2 ?= $(shell grep -qw avx2 /proc/cpuinfo 2>/dev/null && echo 1 || echo 0)
PEERS_GA2D := $(PEERS_OBJ)/ga2d_peer.o
ifeq ($(PEERS_AVX2),1)
PEERS_GA2D += $(PEERS_OBJ)/ga2d_peer_avx2.o
endif

.PHONY: bench-peers bench-peers-check

B2V3_SRC ?=
B2V3_DIR := $(BUILD)/bench/b2v3
ifneq ($(strip $(B2V3_SRC)),)
B2V3_C       := $(wildcard $(B2V3_SRC)/src/*.c)
B2V3_OBJS    := $(patsubst $(B2V3_SRC)/src/%.c,$(B2V3_DIR)/obj/%.o,$(B2V3_C))
B2V3_LIB     := $(B2V3_DIR)/libbox2d-v3.a
B2V3_CFLAGS  := -std=gnu17 -O2 -DNDEBUG -ffp-contract=off -fvisibility=hidden $(B2V3_CFLAGS_EXTRA)
PEERS_RUN    := $(BUILD)/bench/peers-v3
PEERS_V3_OBJ := $(PEERS_OBJ)/bench_peers_v3.o $(PEERS_OBJ)/b2v3_peer.o $(B2V3_LIB)
else
PEERS_RUN    := $(PEERS_BIN)
endif

# Compile and link a tiny program against both peers, so a missing header
# or library is reported before anything else is built.
bench-peers-check:
	@mkdir -p $(PEERS_OBJ)
	@printf '#include <box2d/box2d.h>\n#include <chipmunk/chipmunk.h>\nint main() { b2World w(b2Vec2(0, -10)); cpSpaceFree(cpSpaceNew()); return 0; }\n' \
	  | $(PEERS_CXX) -x c++ - -o $(PEERS_OBJ)/check $(PEERS_LIBS) >/dev/null 2>&1 || { \
	  echo "make bench-peers: Box2D 2.4.1 and Chipmunk 7 development files were not found"; \
	  echo "  (box2d/box2d.h with -lbox2d, chipmunk/chipmunk.h with -lchipmunk)."; \
	  echo "Install them with:"; \
	  echo "  sudo apt-get install libbox2d-dev libchipmunk-dev"; \
	  exit 1; }
	@rm -f $(PEERS_OBJ)/check

# ga2d is built as C99 in its own unit, in the library's default (float) build.
$(PEERS_OBJ)/ga2d_peer.o: $(PEERS_DIR)/ga2d_peer.c $(PEERS_DIR)/ga2d_peer.h $(HEADER)
	@mkdir -p $(dir $@)
	$(PEERS_CC) -std=c99 $(OPT) $(PEERS_WARN) -Wdouble-promotion $(INC) -c $< -o $@

$(PEERS_OBJ)/ga2d_peer_avx2.o: $(PEERS_DIR)/ga2d_peer.c $(PEERS_DIR)/ga2d_peer.h $(HEADER)
	@mkdir -p $(dir $@)
	$(PEERS_CC) -std=c99 $(OPT) -mavx2 -DGA2D_PEER_AVX2 -DGA2D_STATIC $(PEERS_WARN) -Wdouble-promotion $(INC) -c $< -o $@

$(PEERS_OBJ)/bench_peers.o: $(PEERS_DIR)/bench_peers.cpp $(PEERS_DIR)/ga2d_peer.h tests/bench/scenes.h
	@mkdir -p $(dir $@)
	$(PEERS_CXX) -std=c++11 $(OPT) $(PEERS_WARN) $(INC) -DPEERS_OPT='"$(OPT)"' -DPEERS_AVX2=$(PEERS_AVX2) \
	  -DPEERS_BOX2D_VERSION='"$(shell pkg-config --modversion box2d 2>/dev/null)"' -c $< -o $@

$(PEERS_BIN): $(PEERS_OBJ)/bench_peers.o $(PEERS_GA2D)
	$(PEERS_CXX) $^ -o $@ $(PEERS_LIBS) $(LIBS)

# --- Box2D v3 (only with B2V3_SRC): its library, its peer unit (C17,
# its headers only there), and the driver built again knowing of it.
ifneq ($(strip $(B2V3_SRC)),)
$(B2V3_DIR)/obj/%.o: $(B2V3_SRC)/src/%.c
	@mkdir -p $(dir $@)
	$(PEERS_CC) $(B2V3_CFLAGS) -I$(B2V3_SRC)/include -I$(B2V3_SRC)/src -c $< -o $@

$(B2V3_LIB): $(B2V3_OBJS)
	@rm -f $@
	ar rcs $@ $^

$(PEERS_OBJ)/b2v3_peer.o: $(PEERS_DIR)/b2v3_peer.c $(PEERS_DIR)/ga2d_peer.h $(B2V3_SRC)/include/box2d/box2d.h
	@mkdir -p $(dir $@)
	$(PEERS_CC) -std=c17 $(OPT) -DNDEBUG $(PEERS_WARN) -I$(B2V3_SRC)/include -c $< -o $@

$(PEERS_OBJ)/bench_peers_v3.o: $(PEERS_DIR)/bench_peers.cpp $(PEERS_DIR)/ga2d_peer.h tests/bench/scenes.h
	@mkdir -p $(dir $@)
	$(PEERS_CXX) -std=c++11 $(OPT) $(PEERS_WARN) $(INC) -DPEERS_OPT='"$(OPT)"' -DPEERS_AVX2=$(PEERS_AVX2) -DPEERS_B2V3=1 \
	  -DPEERS_B2V3_CFLAGS='"$(B2V3_CFLAGS)"' -DPEERS_B2V3_SRC='"$(B2V3_SRC)"' \
	  -DPEERS_BOX2D_VERSION='"$(shell pkg-config --modversion box2d 2>/dev/null)"' -c $< -o $@

$(BUILD)/bench/peers-v3: $(PEERS_V3_OBJ) $(PEERS_GA2D)
	$(PEERS_CXX) $(PEERS_V3_OBJ) $(PEERS_GA2D) -o $@ $(PEERS_LIBS) -lpthread $(LIBS)
endif

bench-peers: bench-peers-check
	@if [ -n "$(strip $(B2V3_SRC))" ] && [ ! -f "$(B2V3_SRC)/include/box2d/box2d.h" -o ! -f "$(B2V3_SRC)/src/physics_world.c" ]; then \
	  echo "make bench-peers: B2V3_SRC=$(B2V3_SRC) is not a Box2D v3 source tree"; \
	  echo "  (it needs include/box2d/box2d.h and src/*.c, as in a clone of Box2D's repository)"; exit 1; fi
	@$(MAKE) --no-print-directory $(PEERS_RUN)
	./$(PEERS_RUN) $(or $(PEERS_SCENE),all) $(PEERS_CSV)
