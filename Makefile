# toolcomp developer entry points. Everything is bootstrapped from a fresh Debian 12 machine
# (run as root, or with the Debian packages already installed).
#   make demo    run the example program and plot it
#   make test    build, then run every C++ and Python test
#   make build   bootstrap and build only
#   make oracle  differential tests against LinuxCNC's interpreter (installs linuxcnc-uspace)
#   make bench   benchmarks (print figures)
#   make fuzz    libFuzzer targets (fuzz/) for FUZZ_SECONDS each, ASan+UBSan (installs clang)
#   make test-sanitize  C++ and Python tests against an ASan+UBSan build (build/sanitize)
#   make docs    the documentation site (Sphinx) in build/docs/html
#   make stub    regenerate python/toolcomp/_core.pyi from the built module
SHELL      := /bin/bash
PYTHON     ?= python3
VENV       := .venv
PY         := $(VENV)/bin/python
BUILD_DIR  := build/py
APT_PKGS   := g++ libeigen3-dev catch2 ninja-build
ORACLE_PKGS:= linuxcnc-uspace
FUZZ_PKGS  := clang libclang-rt-dev

.PHONY: all build test demo oracle bench clean bootstrap fuzz test-sanitize docs stub

all: build

# ---- bootstrap -------------------------------------------------------------------------
build/.apt-stamp:
	@mkdir -p build
	@missing=$$(for p in $(APT_PKGS); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages: $$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@touch $@

$(VENV)/.stamp: build/.apt-stamp pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q "scikit-build-core>=0.10" "pybind11>=2.13" cmake ninja
	$(PY) -m pip install -q "numpy>=1.21" pytest hypothesis "shapely>=2" nbclient nbformat ipykernel matplotlib pandas tqdm "dask[distributed]" mypy \
	  "pybind11-stubgen==3.0.0"
	@touch $@

bootstrap: $(VENV)/.stamp

# Editable install with a fixed build dir: CMake/Ninja rebuild only what changed.
build: bootstrap
	PATH=$(abspath $(VENV))/bin:$$PATH $(PY) -m pip install -q --no-build-isolation --no-deps -e . \
	  -Cbuild-dir=$(BUILD_DIR) -Ccmake.define.TOOLCOMP_TESTS=ON -Ccmake.define.TOOLCOMP_BENCH=ON -Ccmake.build-type=Release
	$(PY) -c "import toolcomp"

test: build
	cd $(BUILD_DIR) && PATH=$(abspath $(VENV))/bin:$$PATH ctest --output-on-failure

# The demo needs the module and a plot, no more: it builds neither the C++ tests nor the
# benchmarks and installs only numpy and matplotlib (make test adds the rest later, to the
# same build directory). Each step says what it does; the build's [n/N] lines count.
$(VENV)/.demo-stamp: build/.apt-stamp
	@echo "== demo 1/3: a Python environment with numpy, matplotlib and the build tools"
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q "scikit-build-core>=0.10" "pybind11>=2.13" cmake ninja "numpy>=1.21" matplotlib
	@touch $@

demo: $(VENV)/.demo-stamp
	@echo "== demo 2/3: building the C++ module (a few minutes on 2 cores; log in build/demo-build.log)"
	@set -o pipefail; PATH=$(abspath $(VENV))/bin:$$PATH $(PY) -m pip install -v --no-build-isolation --no-deps -e . \
	  -Cbuild-dir=$(BUILD_DIR) -Ccmake.build-type=Release 2>&1 | tee build/demo-build.log \
	  | { grep --line-buffered -E '^ *\[[0-9]+/[0-9]+\]' || true; } | sed -u 's/ Building CXX object CMakeFiles\/[^ ]*dir\// /'
	@echo "== demo 3/3: running examples/bracket.ngc (G41 around a bracket) and drawing it"
	@mkdir -p demo-out
	$(PY) -m toolcomp run examples/bracket.ngc --tools examples/tools.tbl --plot demo-out/bracket.png
	@echo "plot written to demo-out/bracket.png: the programmed outline and the compensated path 5 mm outside it"

build/.oracle-stamp:
	@dpkg -s $(ORACLE_PKGS) >/dev/null 2>&1 || { apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(ORACLE_PKGS); }
	@touch $@

oracle: build build/.oracle-stamp
	$(PY) -m pytest -q tests/oracle

bench: build
	$(PY) tests/bench/run_bench.py

# ---- fuzzing ---------------------------------------------------------------------------
# One libFuzzer target per front end, per tool-table reader and for the whole pipeline
# (fuzz/*.cpp), built with clang in build/fuzz against their own coverage-, ASan- and
# UBSan-instrumented core (CMake option TOOLCOMP_FUZZ). Each runs FUZZ_SECONDS; the corpus
# starts from tests/programs, the tables of tests/ and examples/ and fuzz/seeds, and grows
# in build/fuzz/corpus across runs. Any crash, sanitizer report, uncaught non-toolcomp
# exception, timeout (25 s for one input: a loaded 2-core VM once stalled a 1 ms input past
# 10 s, which replayed in 0.03 s) or out-of-memory fails; the input is saved as
# build/fuzz/crashes/<target>-* and replays with `build/fuzz/<target> FILE`.
FUZZ_SECONDS ?= 60
JOBS         ?= $(shell nproc)
FUZZ_DIR     := build/fuzz
FUZZ_TARGETS := fuzz_iso_parse fuzz_heidenhain_parse fuzz_sinumerik_parse fuzz_pipeline \
                fuzz_table_linuxcnc fuzz_table_csv fuzz_table_json fuzz_table_heidenhain \
                fuzz_table_sinumerik fuzz_tc_dp
FUZZ_FLAGS   := -timeout=25 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1

build/.fuzz-apt-stamp: build/.apt-stamp
	@missing=$$(for p in $(FUZZ_PKGS); do dpkg -s $$p >/dev/null 2>&1 || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing Debian packages: $$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@touch $@

fuzz: bootstrap build/.fuzz-apt-stamp
	PATH=$(abspath $(VENV))/bin:$$PATH cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOOLCOMP_FUZZ=ON -DTOOLCOMP_PYTHON=OFF -DTOOLCOMP_TESTS=OFF >/dev/null
	PATH=$(abspath $(VENV))/bin:$$PATH cmake --build $(FUZZ_DIR) --target fuzzers -j$(JOBS)
	$(PYTHON) fuzz/seed_corpus.py $(FUZZ_DIR)/seeds
	@mkdir -p $(FUZZ_DIR)/crashes; failed=; \
	for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_DIR)/corpus/$$t; \
	  echo "fuzz: $$t for $(FUZZ_SECONDS) s (log $(FUZZ_DIR)/$$t.log)"; \
	  if ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1 \
	     UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	     $(FUZZ_DIR)/$$t $(FUZZ_FLAGS) -max_total_time=$(FUZZ_SECONDS) \
	       -artifact_prefix=$(FUZZ_DIR)/crashes/$$t- $(FUZZ_DIR)/corpus/$$t $(FUZZ_DIR)/seeds/$$t \
	       >$(FUZZ_DIR)/$$t.log 2>&1; then \
	    grep -E "^stat::number_of_executed_units|^Done" $(FUZZ_DIR)/$$t.log | tr '\n' ' '; echo; \
	  else \
	    failed="$$failed $$t"; tail -n 80 $(FUZZ_DIR)/$$t.log; \
	  fi; \
	done; \
	if [ -n "$$failed" ]; then echo "fuzz: FAILED:$$failed (inputs in $(FUZZ_DIR)/crashes)"; exit 1; fi

# ---- sanitizers -----------------------------------------------------------------------
# The Catch2 tests and the Python module built with g++ -fsanitize=address,undefined in
# build/sanitize (CMake option TOOLCOMP_SANITIZE), then every C++ test and the Python tests
# against that module. The module and the pure-Python package are assembled in
# build/sanitize/site/toolcomp; Python runs from a second venv, build/sanitize/venv, which
# sees the packages of .venv through a .pth path entry but not .venv's editable-install hook
# (a .pth file inside a directory added that way is not executed), so `import toolcomp`
# resolves to build/sanitize/site first. libasan is preloaded into Python; leak checking is
# off there (the interpreter keeps its memory at exit). Sanitizer reports go to
# build/sanitize/logs (also from subprocesses) and any report fails the target. Left out of
# the Python run: test_notebooks.py (Jupyter kernels and matplotlib under ASan take minutes
# and add no engine coverage the other tests lack).
SAN_DIR      := build/sanitize
SAN_PY_SKIP  := --ignore=tests/python/test_notebooks.py
# libstdc++ is preloaded too: python does not link it, and ASan's __cxa_throw interceptor
# must find it when ASan starts.
SAN_PRELOAD   = $(shell g++ -print-file-name=libasan.so) $(shell g++ -print-file-name=libstdc++.so.6)
SAN_OPTIONS  := halt_on_error=1:abort_on_error=0:log_path=$(abspath $(SAN_DIR))/logs/report

test-sanitize: bootstrap
	PATH=$(abspath $(VENV))/bin:$$PATH cmake -S . -B $(SAN_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DTOOLCOMP_SANITIZE=ON -DTOOLCOMP_TESTS=ON -DTOOLCOMP_PYTHON=ON \
	  -DPython_EXECUTABLE=$(abspath $(PY)) -Dpybind11_DIR=$$($(PY) -m pybind11 --cmakedir) >/dev/null
	PATH=$(abspath $(VENV))/bin:$$PATH cmake --build $(SAN_DIR) -j$(JOBS)
	@rm -rf $(SAN_DIR)/logs $(SAN_DIR)/site && mkdir -p $(SAN_DIR)/logs $(SAN_DIR)/site
	cp -r python/toolcomp $(SAN_DIR)/site/toolcomp && cp $(SAN_DIR)/_core.*.so $(SAN_DIR)/site/toolcomp/
	test -x $(SAN_DIR)/venv/bin/python || $(PY) -m venv --without-pip $(SAN_DIR)/venv
	$(PY) -c "import sysconfig; print(sysconfig.get_paths()['purelib'])" > \
	  $$($(SAN_DIR)/venv/bin/python -c "import sysconfig; print(sysconfig.get_paths()['purelib'])")/_toolcomp_dev_venv.pth
	ASAN_OPTIONS=$(SAN_OPTIONS):detect_leaks=1 UBSAN_OPTIONS=$(SAN_OPTIONS):print_stacktrace=1 \
	  $(SAN_DIR)/toolcomp_tests || { cat $(SAN_DIR)/logs/report* 2>/dev/null; exit 1; }
	LD_PRELOAD="$(SAN_PRELOAD)" PYTHONPATH=$(abspath $(SAN_DIR))/site \
	  ASAN_OPTIONS=$(SAN_OPTIONS):detect_leaks=0 UBSAN_OPTIONS=$(SAN_OPTIONS):print_stacktrace=1 \
	  MPLBACKEND=Agg $(SAN_DIR)/venv/bin/python -c \
	  "import toolcomp._core as c, sys; assert c.__file__.startswith('$(abspath $(SAN_DIR))/site/'), c.__file__"
	LD_PRELOAD="$(SAN_PRELOAD)" PYTHONPATH=$(abspath $(SAN_DIR))/site \
	  ASAN_OPTIONS=$(SAN_OPTIONS):detect_leaks=0 UBSAN_OPTIONS=$(SAN_OPTIONS):print_stacktrace=1 \
	  MPLBACKEND=Agg $(SAN_DIR)/venv/bin/python -m pytest -q -p no:cacheprovider $(SAN_PY_SKIP) tests/python \
	  || { cat $(SAN_DIR)/logs/report* 2>/dev/null; exit 1; }
	@if ls $(SAN_DIR)/logs/report* >/dev/null 2>&1; then cat $(SAN_DIR)/logs/report*; \
	  echo "test-sanitize: sanitizer reports above"; exit 1; fi

# ---- type stub ---------------------------------------------------------------------------
# python/toolcomp/_core.pyi is generated from the built module (its signatures and the
# docstrings of the /// comments) by python/tools/gen_stub.py with pybind11-stubgen, and
# committed. tests/python/test_stub.py fails while it differs from what this target writes.
stub: build
	$(PY) python/tools/gen_stub.py

# ---- documentation ---------------------------------------------------------------------
# The Sphinx site in build/docs/html: the Markdown pages of doc/, the notebooks of notebooks/
# executed during the build (their figures are the current engine's), and the API reference
# read from the docstrings of the module `make build` installed. The packages are the `docs`
# extra of pyproject.toml, installed into .venv without reinstalling toolcomp itself. -E
# reads every page again: autodoc cannot see that the module changed. Warnings fail. The
# notebooks draw with Jupyter's inline backend (MPLBACKEND unset), as in the tests.
DOCS_DIR := build/docs

$(VENV)/.docs-stamp: $(VENV)/.stamp pyproject.toml
	$(PY) -c "import sys; toml = __import__('tomllib' if sys.version_info >= (3, 11) else 'tomli'); \
	  print('\n'.join(toml.load(open('pyproject.toml', 'rb'))['project']['optional-dependencies']['docs']))" \
	  > build/docs-requirements.txt
	$(PY) -m pip install -q -r build/docs-requirements.txt
	@touch $@

docs: build $(VENV)/.docs-stamp
	env -u MPLBACKEND $(PY) -m sphinx -q -E -W --keep-going -b html -d $(DOCS_DIR)/doctrees doc $(DOCS_DIR)/html
	@echo "documentation written to $(DOCS_DIR)/html/index.html"

clean:
	rm -rf build demo-out
