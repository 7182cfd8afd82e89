# Two commands do all the set-up on a machine with only Python 3.11: `make run` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test lint figures clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

run: $(STAMP)
	$(BIN)/hfsm-run machines/move_furniture.yaml

# The monitor's browser tests drive Debian's Chromium (no browser download); installed once, as root.
CHROMIUM := $(VENV)/.chromium
$(CHROMIUM): $(STAMP)
	command -v chromium >/dev/null || { apt-get update -qq && \
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium; }
	touch $(CHROMIUM)

test: $(STAMP) $(CHROMIUM)
	$(BIN)/python -m pytest

lint: $(STAMP)
	$(BIN)/ruff check hfsm behaviours sim tools tests
	$(BIN)/mypy -p hfsm -p behaviours -p sim

clean:
	rm -rf $(VENV) .pytest_cache .mypy_cache .ruff_cache

# Diagrams of machines/ and examples/ (SVG for people, DOT for the staleness test): see docs/GRAPH.md.
figures: $(STAMP)
	$(BIN)/hfsm-graph machines -o docs/figures --format svg,dot --prune
	$(BIN)/hfsm-graph examples -o docs/figures/examples --format svg,dot --no-legend --prune
	$(BIN)/hfsm-graph tests/diagram/data/search.yaml --depth 2 -o docs/figures/depth --format svg,dot --no-legend --no-overview --prune

# Primitives' declarations, read without importing the simulator: see behaviours/registry.py.
.PHONY: declarations
declarations: $(STAMP)
	$(BIN)/python -m hfsm.declarations behaviours.registry:primitives > behaviours/primitives.json

# Engine against its peers (transitions, python-statemachine, sismic, a dict floor): see docs/PERFORMANCE.md.
.PHONY: bench
bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -r tools/bench-requirements.txt
	$(BIN)/python tools/bench_engine.py
