# Quickstart targets: `make demo` and `make test` work on a fresh machine.
# They create .venv, install urdfcli (demo: with what it needs to run; test: with
# the test extras too), and install the system programs (graphviz; for tests also
# liburdfdom-tools, poppler-utils, and the consumers that are not Python packages:
# sdformat's `ign sdf` for Gazebo, kdl_parser and a C++ compiler for KDL) with
# apt-get when they are missing.

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
DEMO := fixtures/urdf02_gazebo/urdf/car.urdf.xacro
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: demo test bench system-runtime system-test clean

demo: $(VENV)/.installed system-runtime
	$(BIN)/urdfcli check $(DEMO)
	$(BIN)/urdfcli tree $(DEMO)

# Tests run in parallel, one worker per core; `--dist worksteal` evens out the slow files.
test: $(VENV)/.tested system-test
	$(BIN)/python -m pytest -n auto --dist worksteal

bench: $(VENV)/.tested system-test
	$(BIN)/python benchmarks/run.py

# urdfcli and what it needs to run
$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e .
	touch $@

# the test extras too: pytest, the published models, the programs urdfcli is compared with,
# and the consumers --target is checked against (MuJoCo, Drake, Pinocchio, PyBullet, Isaac Sim's converter)
$(VENV)/.tested: $(VENV)/.installed
	$(BIN)/python -m pip install --quiet -e '.[test,targets]'
	touch $@

# apt-get only when a program (or, for a name starting with /, a file) is missing;
# `apt-get update` once before it.
define apt_install
	@missing=""; \
	for pair in $(1); do prog=$${pair%%:*}; pkg=$${pair##*:}; \
	  case $$prog in /*) test -e $$prog ;; *) command -v $$prog >/dev/null 2>&1 ;; esac || missing="$$missing $$pkg"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing$$missing with apt-get"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing >/dev/null; \
	fi
endef

system-runtime:
	$(call apt_install,dot:graphviz)

# Gazebo: `ign sdf` needs sdformat's command plugin, which libsdformat-dev ships (Debian 12: sdformat 12).
# KDL: check --target kdl --load and tests/test_targets.py compile src/urdfcli/targets/kdl/kdl_tree.cpp against kdl_parser with g++.
SDFORMAT_PLUGIN := /usr/share/ignition/sdformat12.yaml
KDL_PARSER := /usr/include/kdl_parser/kdl_parser.hpp

system-test:
	$(call apt_install,dot:graphviz check_urdf:liburdfdom-tools pdfinfo:poppler-utils \
	  ign:ignition-tools $(SDFORMAT_PLUGIN):libsdformat-dev g++:g++ $(KDL_PARSER):libkdl-parser-dev)

clean:
	rm -rf $(VENV) build *.egg-info src/*.egg-info .pytest_cache benchmarks/generated
