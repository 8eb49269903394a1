# make trade: what each knob costs and buys (tests/bench/trade.c), built as
# float and as double.  The knob sweep runs TRADE_RUNS rounds (default 5),
# the float and the double build in turn, so that a slow spell of the
# machine falls on both alike; then the float build times the optional
# passes on and off, and one report writes build/trade/<scene>.svg and
# build/trade/tables.md and prints the tables.  Nothing runs in parallel:
# it is all timed.  The pyramid20 and oscillator plots are copied to
# tests/bench/plots/, which the README shows, so every `make trade`
# regenerates them.
TRADE_DIR  := $(BUILD)/trade
TRADE_RUNS ?= 5
TRADE_DEP  := tests/bench/trade.c tests/bench/scene_run.h tests/bench/scenes.h tests/bench/svg_plot.h $(HEADER)

.PHONY: trade

$(TRADE_DIR)/trade-float: $(TRADE_DEP)
	@mkdir -p $(dir $@)
	gcc -std=c99 $(OPT) $(WARN) $(INC) $< -o $@ $(LIBS)

$(TRADE_DIR)/trade-double: $(TRADE_DEP)
	@mkdir -p $(dir $@)
	gcc -std=c99 -DGA2D_DOUBLE $(OPT) $(WARN) $(INC) $< -o $@ $(LIBS)

trade: $(TRADE_DIR)/trade-float $(TRADE_DIR)/trade-double
	rm -f $(TRADE_DIR)/knobs-float.csv $(TRADE_DIR)/knobs-double.csv
	r=1; while [ $$r -le $(TRADE_RUNS) ]; do \
	  ./$(TRADE_DIR)/trade-float knobs $(TRADE_DIR)/knobs-float.csv $$r && \
	  ./$(TRADE_DIR)/trade-double knobs $(TRADE_DIR)/knobs-double.csv $$r || exit 1; \
	  r=$$((r + 1)); \
	done
	TRADE_RUNS=$(TRADE_RUNS) ./$(TRADE_DIR)/trade-float passes $(TRADE_DIR)/passes.csv
	./$(TRADE_DIR)/trade-float report $(TRADE_DIR) $(TRADE_DIR)/knobs-float.csv $(TRADE_DIR)/knobs-double.csv \
	  $(TRADE_DIR)/passes.csv
	@mkdir -p tests/bench/plots
	cp $(TRADE_DIR)/pyramid20.svg $(TRADE_DIR)/oscillator.svg tests/bench/plots/

# bench_scenes.c includes these too; the pattern rule for benches lists
# only the .c and the library header.
$(BUILD)/bench/bench_scenes: tests/bench/scene_run.h tests/bench/scenes.h
