# Two commands do all set-up on a fresh Debian bookworm machine:
#   make run    installs what is missing, builds, and parses and prints the bundled example
#   make test   installs what is missing, builds, and runs every test
.PHONY: all deps build run test bench messages clean

EXAMPLE ?= examples/weldcell.mod

all: build

deps:
	@scripts/install-deps.sh

build: deps
	dune build

run: build
	./_build/install/default/bin/rapid-sem parse --print $(EXAMPLE)

test: build
	scripts/run-tests.sh

bench: build
	dune build @bench/bench

# After a change to lib/syntax/parser.mly: add the automaton's new error states to
# parser.messages (each with menhir's placeholder, which the build refuses until it is written).
messages:
	menhir --list-errors lib/syntax/parser.mly > /tmp/rapid-sem.auto.messages
	menhir --merge-errors /tmp/rapid-sem.auto.messages --merge-errors lib/syntax/parser.messages \
	  lib/syntax/parser.mly > /tmp/rapid-sem.merged.messages
	menhir --update-errors /tmp/rapid-sem.merged.messages lib/syntax/parser.mly > lib/syntax/parser.messages
	rm -f lib/syntax/parser.automaton lib/syntax/parser.conflicts lib/syntax/parser.ml lib/syntax/parser.mli

clean:
	dune clean
