# Two commands do all the set-up on a machine with only Python 3.11: `make run` and `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test lint figures clean

# Installs exactly the versions the tests passed with: requirements.lock (hashes, Python 3.11 on
# Linux x86_64), then this project without its dependencies. pyproject.toml keeps ranges for people
# who install hfsm into an environment of their own; `make lock` re-resolves them (a deliberate
# change, with its own commit), `make test-latest` runs the suite against the newest versions.
$(STAMP): pyproject.toml requirements.lock
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --require-hashes --no-deps -r requirements.lock
	$(BIN)/python -m pip install --quiet --no-deps --no-build-isolation -e .
	touch $(STAMP)

run: $(STAMP)
	$(BIN)/hfsm-run machines/move_furniture.yaml

# The monitor's browser tests drive Debian's Chromium (no browser download); installed once, as root.
CHROMIUM := $(VENV)/.chromium
$(CHROMIUM): $(STAMP)
	command -v chromium >/dev/null || { apt-get update -qq && \
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium; }
	touch $(CHROMIUM)

# The language server's editor test drives Debian's Neovim; installed once, as root.
NEOVIM := $(VENV)/.neovim
$(NEOVIM): $(STAMP)
	command -v nvim >/dev/null || { apt-get update -qq && \
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends neovim; }
	touch $(NEOVIM)

test: $(STAMP) $(CHROMIUM) $(NEOVIM)
	$(BIN)/python -m pytest

lint: $(STAMP)
	$(BIN)/ruff check hfsm hfsm_behaviours hfsm_sim tools tests
	$(BIN)/mypy -p hfsm -p hfsm_behaviours -p hfsm_sim

clean:
	rm -rf $(VENV) $(LATEST) .pytest_cache .mypy_cache .ruff_cache

# Diagrams of machines/ and examples/ (SVG for people, DOT for the staleness test): see docs/GRAPH.md.
figures: $(STAMP)
	$(BIN)/hfsm-graph machines -o docs/figures --format svg,dot --prune
	$(BIN)/hfsm-graph examples -o docs/figures/examples --format svg,dot --no-legend --prune
	$(BIN)/hfsm-graph tests/diagram/data/search.yaml --depth 2 -o docs/figures/depth --format svg,dot --no-legend --no-overview --prune

# Primitives' declarations, read without importing the simulator: see hfsm_behaviours/registry.py.
.PHONY: declarations
declarations: $(STAMP)
	$(BIN)/python -m hfsm.declarations hfsm_behaviours.registry:primitives > hfsm_behaviours/primitives.json

# Engine against its peers (transitions, python-statemachine, sismic, a dict floor): see docs/PERFORMANCE.md.
.PHONY: bench
bench: $(STAMP)
	$(BIN)/python -m pip install --quiet -r tools/bench-requirements.txt
	$(BIN)/python tools/bench_engine.py

.PHONY: lock test-latest
lock: $(STAMP)
	$(BIN)/uv pip compile pyproject.toml --extra dev --generate-hashes --upgrade --python-version 3.11 \
		--python-platform x86_64-manylinux_2_28 --no-header --annotation-style line -o requirements.lock

LATEST := .venv-latest
test-latest: $(CHROMIUM) $(NEOVIM)
	rm -rf $(LATEST)
	$(PYTHON) -m venv $(LATEST)
	$(LATEST)/bin/python -m pip install --quiet --upgrade pip
	$(LATEST)/bin/python -m pip install --quiet --upgrade -e '.[dev]'
	$(LATEST)/bin/python -m pip list --format=freeze > $(LATEST)/versions.txt
	$(LATEST)/bin/python -m pytest
