# Two commands do all set-up on a fresh Debian bookworm machine:
#   make run    installs what is missing, builds, and runs the bundled example cell: its output,
#               and its path, timeline and samples in $(RUN_DIR)
#   make test   installs what is missing, builds, and runs every test
.PHONY: all deps build run test bench messages clean

EXAMPLE ?= examples/weldcell.mod
EXAMPLE_IO ?= examples/weldcell.io
RUN_DIR ?= _build/run

all: build

deps:
	@scripts/install-deps.sh

build: deps
	dune build

run: build
	@mkdir -p $(RUN_DIR)
	./_build/install/default/bin/rapid-sem motion --io $(EXAMPLE_IO) $(EXAMPLE) \
	  --svg $(RUN_DIR)/path.svg --timeline $(RUN_DIR)/timeline.svg --csv $(RUN_DIR)/path.csv
	@echo "The robot's path, the timeline and the samples: $(RUN_DIR)/path.svg, $(RUN_DIR)/timeline.svg, $(RUN_DIR)/path.csv"

test: build
	scripts/run-tests.sh

bench: build
	dune build @bench/bench

# After a change to lib/syntax/parser.mly: add the automaton's new error states to
# parser.messages (each with menhir's placeholder, which the build refuses until it is written).
MESSAGES_TMP = _build/messages

messages:
	mkdir -p $(MESSAGES_TMP)
	menhir --base $(MESSAGES_TMP)/parser --list-errors lib/syntax/parser.mly > $(MESSAGES_TMP)/auto.messages
	menhir --base $(MESSAGES_TMP)/parser --merge-errors $(MESSAGES_TMP)/auto.messages \
	  --merge-errors lib/syntax/parser.messages lib/syntax/parser.mly > $(MESSAGES_TMP)/merged.messages
	menhir --base $(MESSAGES_TMP)/parser --update-errors $(MESSAGES_TMP)/merged.messages \
	  lib/syntax/parser.mly > $(MESSAGES_TMP)/updated.messages
	mv $(MESSAGES_TMP)/updated.messages lib/syntax/parser.messages

clean:
	dune clean
