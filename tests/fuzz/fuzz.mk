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

# Runs each harness in turn, then prints every summary; fails if any
# harness found a crash or a violated invariant.
fuzz: fuzz-build
	@status=0; summary=""; \
	for h in $(FUZZ_ONLY); do \
	    kind=$${h%_double}; corpus=$(FUZZ_DIR)/corpus/$$h; log=$(FUZZ_DIR)/$$h.log; \
	    if [ -n "$(FUZZ_FIXED)" ]; then \
	        corpus=$(FUZZ_DIR)/fixed-corpus/$$h; rm -rf $$corpus; \
	        case $$kind in \
	        polygon) runs=$(FUZZ_RUNS_polygon);; world) runs=$(FUZZ_RUNS_world);; \
	        reentry) runs=$(FUZZ_RUNS_reentry);; snapshot) runs=$(FUZZ_RUNS_snapshot);; \
	        shapes) runs=$(FUZZ_RUNS_shapes);; *) runs=$(FUZZ_RUNS_shape_world);; esac; \
	        limit="-runs=$$runs -seed=$(FUZZ_SEED) -reload=0"; what="$$runs inputs from seed $(FUZZ_SEED)"; \
	        run="$(FUZZ_NORAND)"; \
	    else \
	        limit="-max_total_time=$(FUZZ_SECONDS)"; what="$(FUZZ_SECONDS) s"; run=""; \
	    fi; \
	    mkdir -p $$corpus tests/fuzz/seeds/$$kind tests/fuzz/regress/$$kind; \
	    echo "== fuzz $$h: $$what"; \
	    $$run ./$(FUZZ_DIR)/fuzz_$$h $$limit -timeout=20 -max_len=4096 -print_final_stats=1 \
	        -artifact_prefix=$(FUZZ_DIR)/$$h- $$corpus tests/fuzz/seeds/$$kind tests/fuzz/regress/$$kind \
	        > $$log 2>&1; rc=$$?; \
	    done_line=$$(grep -E '^#[0-9]+[[:space:]]+DONE' $$log | tail -n 1); \
	    execs=$$(grep -E '^stat::number_of_executed_units:' $$log | awk '{print $$2}'); \
	    cov=$$(printf '%s\n' "$$done_line" | sed -n 's/.*cov: \([0-9]*\).*/\1/p'); \
	    ft=$$(printf '%s\n' "$$done_line" | sed -n 's/.* ft: \([0-9]*\).*/\1/p'); \
	    corp=$$(printf '%s\n' "$$done_line" | sed -n 's/.* corp: \([^ ]*\).*/\1/p'); \
	    rate=$$(printf '%s\n' "$$done_line" | sed -n 's/.* exec\/s: \([0-9]*\).*/\1/p'); \
	    if [ $$rc -ne 0 ] || [ -z "$$done_line" ]; then \
	        tail -n 40 $$log; status=1; \
	        line=$$(printf 'fuzz %-16s FAILED (exit %s): see %s and %s-crash-*' $$h $$rc $$log $(FUZZ_DIR)/$$h); \
	    else \
	        line=$$(printf 'fuzz %-16s %10s executions  cov: %-5s ft: %-6s corpus: %-12s %s exec/s' \
	            $$h "$$execs" "$$cov" "$$ft" "$$corp" "$$rate"); \
	    fi; \
	    echo "$$line"; summary="$$summary$$line\n"; \
	done; \
	echo "== fuzz summary ($(if $(FUZZ_FIXED),fixed campaign from seed $(FUZZ_SEED),$(FUZZ_SECONDS) s per harness))"; printf "$$summary"; exit $$status

fuzz-clean:
	rm -rf $(FUZZ_DIR)
