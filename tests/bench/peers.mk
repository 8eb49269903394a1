# make bench-peers: ga2d against Box2D 2.4.1 and Chipmunk 7 on the scenes of
# tests/bench/scenes.h (tests/bench/peers/).  Included by the top-level
# Makefile; not part of `make test`.  Needs the Debian packages
# libbox2d-dev and libchipmunk-dev.  BENCH_RUNS=n sets the runs per engine.
#   ./build/bench/peers [scene] [csv]   runs one scene (default: all)
# Where the CPU has AVX2, ga2d is also built a second time with -mavx2 and
# run as a fourth engine, ga2d-avx2 (PEERS_AVX2=0 leaves it out).

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

bench-peers: bench-peers-check
	@$(MAKE) --no-print-directory $(PEERS_BIN)
	./$(PEERS_BIN) all $(PEERS_CSV)
