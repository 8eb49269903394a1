# make fuzz: libFuzzer harnesses (tests/fuzz/fuzz_*.c, logic in fuzz_*.h),
# built with clang's fuzzer, address and undefined-behaviour sanitizers and
# run for FUZZ_SECONDS each (default 60).  Each harness keeps a corpus in
# build/fuzz/corpus/<harness>, starts from tests/fuzz/seeds/<input kind> and
# tests/fuzz/regress/<input kind>, and writes any crashing input to
# build/fuzz/<harness>-crash-*.  The last lines are one summary per harness:
# executions, coverage (cov: edges, ft: features) and corpus size.
# A finding is fixed, and its input kept in tests/fuzz/regress/<kind>/,
# which `make test` replays (tests/test_fuzz_regress.c).
#   make fuzz                      every harness, 60 s each
#   make fuzz FUZZ_SECONDS=600     longer
#   make fuzz FUZZ_JOBS=1          one harness at a time
#   make fuzz FUZZ_ONLY=world      one harness (or a list)
#   make fuzz FUZZ_EXTRA=-DFUZZ_VERBOSE   extra flags (after make fuzz-clean)
#   make fuzz-build                build only
#   make fuzz FUZZ_FIXED=1         a reproducible campaign, as CI runs it:
#                                  each harness runs FUZZ_RUNS_<kind> inputs
#                                  from seed FUZZ_SEED (default 1), starting
#                                  from the kept seeds and findings only (a
#                                  fresh corpus), so a clean clone gives the
#                                  same inputs here and on CI.  Exploring
#                                  (the default: random seed, by time, the
#                                  corpus kept) is what finds new inputs.

FUZZ_SECONDS ?= 60
FUZZ_CC      ?= clang
FUZZ_EXTRA   ?=
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_FIXED   ?=
FUZZ_SEED    ?= 1
# a fixed campaign repeats only without address randomization (the
# comparison tracer records pointers) and without rereading the corpus
# folder on a timer
FUZZ_NORAND  := $(shell setarch $$(uname -m) -R true >/dev/null 2>&1 && echo setarch $$(uname -m) -R)
# inputs per harness in a fixed campaign: about a minute each here
FUZZ_RUNS_polygon     ?= 3000000
FUZZ_RUNS_world       ?= 40000
FUZZ_RUNS_reentry     ?= 15000
FUZZ_RUNS_snapshot    ?= 30000
FUZZ_RUNS_shapes      ?= 3000000
FUZZ_RUNS_shape_world ?= 6000
FUZZ_FLAGS   := -std=c99 -O1 -g -ffp-contract=off -fsanitize=fuzzer,address,undefined \
                -fno-sanitize-recover=all -fno-omit-frame-pointer
# harness = input kind [+ _double for the double build]; the snapshot
# harness exists once the header has the snapshot API
FUZZ_KINDS   := polygon world reentry $(if $(shell grep -l ga2d_world_snapshot_load $(HEADER) 2>/dev/null),snapshot) \
                $(if $(shell grep -l ga2d_collide_shapes_scaled $(HEADER) 2>/dev/null),shapes shape_world)
FUZZ_ALL     := $(foreach k,$(FUZZ_KINDS),$(k) $(k)_double)
FUZZ_ONLY    ?= $(FUZZ_ALL)
FUZZ_BINS    := $(addprefix $(FUZZ_DIR)/fuzz_,$(FUZZ_ONLY))

.PHONY: fuzz fuzz-build fuzz-clean

# $(1): input kind, $(2): harness name, $(3): extra flags
define FUZZ_RULE
$(FUZZ_DIR)/fuzz_$(2): tests/fuzz/fuzz_$(1).c $(wildcard tests/fuzz/*.h) $(HEADER)
	@mkdir -p $(FUZZ_DIR)
	$(FUZZ_CC) $(FUZZ_FLAGS) $(3) $(FUZZ_EXTRA) $(WARN) $(INC) -Itests/fuzz $$< -o $$@ $(LIBS)
endef
$(foreach k,$(FUZZ_KINDS),$(eval $(call FUZZ_RULE,$(k),$(k),)))
$(foreach k,$(FUZZ_KINDS),$(eval $(call FUZZ_RULE,$(k),$(k)_double,-DGA2D_DOUBLE)))

fuzz-build: $(FUZZ_BINS)

# Runs the harnesses, FUZZ_JOBS at a time (default: the processor count),
# then prints every summary; fails if any harness found a crash or a
# violated invariant (tests/fuzz/run.sh).
FUZZ_JOBS ?= $(NPROC)
fuzz:
	@$(MAKE) --no-print-directory -j$(NPROC) fuzz-build
	@FUZZ_DIR=$(FUZZ_DIR) FUZZ_FIXED=$(FUZZ_FIXED) FUZZ_SEED=$(FUZZ_SEED) FUZZ_SECONDS=$(FUZZ_SECONDS) \
	  FUZZ_JOBS=$(FUZZ_JOBS) FUZZ_NORAND="$(FUZZ_NORAND)" \
	  $(foreach k,$(FUZZ_KINDS),FUZZ_RUNS_$(k)=$(FUZZ_RUNS_$(k))) \
	  sh tests/fuzz/run.sh $(FUZZ_ONLY)

fuzz-clean:
	rm -rf $(FUZZ_DIR)
