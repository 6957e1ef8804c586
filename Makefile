# Panta Rhei: `make demo` runs the main job, `make test` runs every test.
# Both set up first; `make setup` is idempotent and works as root on a fresh
# Debian machine with Python 3.11.

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed

.PHONY: setup system demo evaluate test test-python test-prolog bench clean

setup: system $(STAMP)

# SWI-Prolog from Debian's packages (pyswip needs its shared library),
# WordNet's database (the question reader asks it what a noun names), and
# the venv module for Debian's own Python.
system:
	@command -v swipl >/dev/null 2>&1 || { apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq swi-prolog-nox >/dev/null; }
	@test -f /usr/share/wordnet/index.noun || { apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq wordnet-base >/dev/null; }
	@$(PYTHON) -c "import ensurepip, venv" 2>/dev/null || { apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null; }

# The packages' bytecode is compiled afterwards on every core at once
# (pip alone compiles on one, two thirds of the install's time).
$(STAMP): pyproject.toml requirements.lock
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip==25.3
	$(PY) -m pip install -q --no-compile -r requirements.lock
	$(PY) -m compileall -q -j 0 $$($(PY) -c "import sysconfig; print(sysconfig.get_paths()['purelib'])") >/dev/null
	$(PY) -m pip install -q --no-deps -e .
	@touch $@

demo: setup
	$(VENV)/bin/pantarhei demo

# Measure the learned theory against the oracle and write report/.
evaluate: setup
	$(VENV)/bin/pantarhei evaluate

test: setup test-python test-prolog

# One pytest worker per core (pytest-xdist), each test file whole on one
# worker so that a file's fixtures are computed once.
test-python:
	$(PY) -m pytest -q -n auto --dist loadfile

# Every plunit file (a .plt beside its module), loaded and run in one swipl:
# theory/pantarhei.pl loads every module of the theory.
test-prolog:
	swipl --on-error=status -q -g "load_test_files([]), (run_tests -> halt ; halt(1))" theory/pantarhei.pl

bench: setup
	$(PY) -m benchmarks --out report/bench.txt

clean:
	rm -rf $(VENV) build *.egg-info
