# foon2pddl developer tasks. `make test` works on a fresh Debian machine (installs first).
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp
# The public FOON data beside the checkout when there (benchmarks, experiments), else the test corpus.
SHARED ?= $(if $(wildcard ../shared/data),../shared/data,tests/data)

.PHONY: install system-deps test bench fuzz lint pddl demo experiment clean

install: $(STAMP)

# Debian packages: WordNet 3.0 (FOON-EXP similarity) and Graphviz (SVG task trees).
system-deps:
	@if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	  need=""; for p in wordnet-base wordnet-sense-index graphviz; do \
	    dpkg -s $$p >/dev/null 2>&1 || need="$$need $$p"; done; \
	  if [ -n "$$need" ]; then apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$need; fi; \
	else echo "not root on Debian: install wordnet-base wordnet-sense-index graphviz yourself (or nltk.download('wordnet'))"; fi

# Each step says what it does; pip's output goes to $(VENV)/pip-install.log (both pips: one run ticks across
# the seam), a line per phase to the terminal. pip_phases says a step's line itself (--first), at once: its
# first tick then comes TICK s after that line, not after an interpreter's start under load.
$(STAMP): pyproject.toml
	@echo "make install: 1/4 system packages (WordNet 3.0, Graphviz) ..."
	@$(MAKE) -s system-deps
	@mkdir -p $(VENV)
	@$(PYTHON) tools/pip_phases.py --log $(VENV)/venv.log --first "make install: 2/4 a virtual environment in $(VENV) ..." --who "make install" --phase "creating a virtual environment in $(VENV)" $(PYTHON) -m venv $(VENV)
	@$(PY) tools/pip_phases.py --log $(VENV)/pip-install.log --first "make install: 3/4 foon2pddl and its dependencies (pip; a few minutes on a fresh machine) ..." sh -c "$(PY) -m pip install --progress-bar off --upgrade pip && $(PY) -m pip install --progress-bar off -e '.[test,gen,experiment]'"
	@# bytecode, as a wheel install writes it (PYTHONDONTWRITEBYTECODE would leave none)
	@$(PY) tools/pip_phases.py --log $(VENV)/compileall.log --first "make install: 4/4 compiling foon2pddl's bytecode ..." --who "make install" --phase "compiling foon2pddl's bytecode" $(PY) -m compileall -q foon2pddl
	@touch $(STAMP)
	@echo "make install: done; run .venv/bin/foon2pddl (README.md)"

test: $(STAMP)
	$(PY) -m pytest -n 2 tests

bench: $(STAMP)
	$(PY) -m bench --shared $(SHARED)

# 10,000 seeded mutants of the shared subgraphs through stats/retrieve/compile (`make test` runs 500).
FUZZ_MUTANTS ?= 10000
fuzz: $(STAMP)
	FOON2PDDL_MUTANTS=$(FUZZ_MUTANTS) $(PY) -m pytest -n 2 -q tests/test_fuzz_mutants.py tests/test_fuzz_inputs.py

lint: $(STAMP)
	$(VENV)/bin/ruff check foon2pddl tests bench

pddl: $(STAMP)
	$(PY) -m foon2pddl.cli.examples_cmd

demo: $(STAMP)
	$(VENV)/bin/foon2pddl plan --goal guacamole
	$(VENV)/bin/foon2pddl plan --goal lemonade --network gen

# Default protocol (10 trials x 100 goals, REG/EXP/GEN), every solver on every goal, on a local Dask
# cluster of 2 workers. Resumes: cells already in docs/experiment/results.jsonl are not rerun; from an
# empty docs/experiment (rm -r docs/experiment) it recomputes every cell, as docs/experiment.md should be.
# fd-relational is the physical solver (objects and what holds what; its plans pass the relational
# replay); fd-instances (objects without holders, whose plans that replay rejects) runs when named.
EXPERIMENT_SOLVERS ?= native-greedy,native-complete,native-optimal,fd-tree,fd-tree-opt,fd-relational,fd-lifted-gen
experiment: $(STAMP)
	$(VENV)/bin/foon2pddl experiment $(SHARED)/foon-subgraphs --jobs 2 --solvers $(EXPERIMENT_SOLVERS) \
	  -o docs/experiment --report docs/experiment.md

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .hypothesis
