# toolcomp developer entry points. Everything is bootstrapped from a fresh Debian 12 machine
# (run as root, or with the Debian packages already installed).
#   make demo    run the example program and plot it
#   make test    build, then run every C++ and Python test
#   make build   bootstrap and build only
#   make oracle  differential tests against LinuxCNC's interpreter (installs linuxcnc-uspace)
#   make bench   benchmarks (print figures)
SHELL      := /bin/bash
PYTHON     ?= python3
VENV       := .venv
PY         := $(VENV)/bin/python
BUILD_DIR  := build/py
APT_PKGS   := g++ libeigen3-dev catch2 ninja-build
ORACLE_PKGS:= linuxcnc-uspace

.PHONY: all build test demo oracle bench clean bootstrap

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
	$(PY) -m pip install -q "numpy>=1.21" pytest hypothesis "shapely>=2" nbclient nbformat ipykernel matplotlib pandas tqdm
	@touch $@

bootstrap: $(VENV)/.stamp

# Editable install with a fixed build dir: CMake/Ninja rebuild only what changed.
build: bootstrap
	PATH=$(abspath $(VENV))/bin:$$PATH $(PY) -m pip install -q --no-build-isolation --no-deps -e . \
	  -Cbuild-dir=$(BUILD_DIR) -Ccmake.define.TOOLCOMP_TESTS=ON -Ccmake.build-type=Release
	$(PY) -c "import toolcomp"

test: build
	cd $(BUILD_DIR) && PATH=$(abspath $(VENV))/bin:$$PATH ctest --output-on-failure

demo: build
	@mkdir -p demo-out
	$(PY) -m toolcomp run examples/pocket.ngc --tools examples/tools.tbl --plot demo-out/pocket.png
	@echo "plot written to demo-out/pocket.png"

build/.oracle-stamp:
	@dpkg -s $(ORACLE_PKGS) >/dev/null 2>&1 || { apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(ORACLE_PKGS); }
	@touch $@

oracle: build build/.oracle-stamp
	$(PY) -m pytest -q tests/oracle

bench: build
	$(PY) tests/bench/run_bench.py

clean:
	rm -rf build demo-out
