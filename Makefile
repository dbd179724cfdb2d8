# tethersim — two commands on a fresh machine: `make run`, `make test`.
PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp
# pytest processes (pytest-xdist): the budget is make test under 4 minutes on 2 cores, and a
# cold first run spends most of it compiling kernels, one model at a time per process.
# worksteal: an idle process takes queued tests from a busy one, so the few tests that
# compile a 20-45 s loop do not leave one process with the tail (cold fast tier 205-208 s
# against 227-235 s with the default `load`, measured on 2 cores, 2026-12-04)
JOBS   ?= 2
XDIST  := -n $(JOBS) --dist worksteal

.PHONY: install run test test-slow test-fast test-generic check-bitwise docs-check derive check-generated lint bench clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[test,derive,dask]'
	@# bytecode now, as pip does for non-editable installs: a shell with
	@# PYTHONDONTWRITEBYTECODE set would otherwise recompile ~80 modules (0.24 s) every run
	$(PY) -m compileall -q tethersim generated >/dev/null
	@# compile the kernels of `make run` once, now: the first run then starts at once
	@tmp=$$(mktemp -d) && $(VENV)/bin/tethersim run satI --periods 1 --no-plots --out $$tmp \
	  >/dev/null && rm -rf $$tmp
	touch $(STAMP)

install: $(STAMP)

## The main job: a SatI simulation (50 orbits) with its plots in results/satI.
run: $(STAMP)
	$(VENV)/bin/tethersim run satI --periods 50 --out results/satI

## Regenerate generated/ from derive/ (sympy -> numba).
derive: $(STAMP)
	$(PY) -m derive

## Regenerate into a temporary folder and diff against the committed files.
check-generated: $(STAMP)
	@tmp=$$(mktemp -d) && $(PY) -m derive $$tmp >/dev/null && \
	  for f in $$tmp/*.py; do diff -u generated/$$(basename $$f) $$f || exit 1; done && \
	  echo "generated/ is reproduced byte for byte" && rm -rf $$tmp

## Layer contracts (import-linter) and style (ruff).
lint: $(STAMP)
	$(VENV)/bin/lint-imports
	$(VENV)/bin/ruff check .

## The suite: contracts and style, every test but the slow tier (under 4 minutes on 2 cores
## from a fresh clone).  `make test-slow` runs the slow tier; CI runs both and then
## `make derive` with `git diff` (generated/ reproduced byte for byte, what
## `make check-generated` checks without touching the tree: tens of seconds, so not in make test).
test: $(STAMP) lint
	$(PY) -m pytest -q $(XDIST) -m "not slow"

## The slow tier: derivations of the 3-D and free-orbit models, long physics runs, every
## README command as written (two processes, as make test).
test-slow: $(STAMP)
	$(PY) -m pytest -q $(XDIST) -m slow

## Tests without the slow tier and without the contract and regeneration checks.
test-fast: $(STAMP)
	$(PY) -m pytest -q $(XDIST) -m "not slow"

## The fast tier on a generic x86-64 CPU: numba compiles for no particular CPU and numpy's
## CPU-dispatched kernels are switched off, so a test that only passes on the CPU it was
## written on fails here first (CI runs it; its kernels go to their own cache folder).
test-generic: $(STAMP)
	NUMBA_CPU_NAME=generic TETHERSIM_CACHE_DIR=$${TMPDIR:-/tmp}/tethersim-generic-cache \
	NPY_DISABLE_CPU_FEATURES="$$($(PY) -c 'import numpy._core._multiarray_umath as m; \
	  print(" ".join(f for f in m.__cpu_dispatch__ if m.__cpu_features__.get(f)))')" \
	  $(PY) -m pytest -q $(XDIST) -m "not slow"

## Bit identity on this machine: the reference runs at BASE and in the working tree, to the
## last bit (tests compare stored numbers to stated tolerances instead: tests/reference.py).
check-bitwise: $(STAMP)
	$(PY) tools/bitwise.py $(or $(BASE),HEAD)

## The figures printed in the docs beside their computed values (tools/, not in the wheel;
## tests/output/test_doc_numbers.py checks them in make test, the --slow ones in test-slow).
docs-check: $(STAMP)
	$(PY) -m tools.docnumbers --slow

## Speed figures (medians of repeats, ratios in the same run).
bench: $(STAMP)
	$(PY) -m pip install -q -e '.[bench]'
	$(PY) bench/run.py

clean:
	rm -rf $(VENV) results build *.egg-info
	find . -name __pycache__ -prune -exec rm -rf {} +
