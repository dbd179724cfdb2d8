# tethersim — two commands on a fresh machine: `make run`, `make test`.
PYTHON ?= python3
VENV   ?= .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp

.PHONY: install run test test-fast derive check-generated lint bench clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[test,derive,dask]'
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

## Layer contracts: runtime and generated code never import sympy or derive/.
lint: $(STAMP)
	$(VENV)/bin/lint-imports

## Whole suite: contracts, generated code reproducible, all tests.
test: $(STAMP) lint check-generated
	$(PY) -m pytest -q

## Tests without the slow tier.
test-fast: $(STAMP)
	$(PY) -m pytest -q -m "not slow"

## Speed figures (medians of repeats, ratios in the same run).
bench: $(STAMP)
	$(PY) -m pip install -q -e '.[bench]'
	$(PY) bench/run.py

clean:
	rm -rf $(VENV) results build *.egg-info
	find . -name __pycache__ -prune -exec rm -rf {} +
