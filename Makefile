# The README's commands. Each target sets up what is missing first: Debian
# packages (apt-get), the virtual environment, the package; then runs.
PYTHON ?= python3
VENV ?= .venv
BUILD ?= build/cmake
OUT ?= out
JOBS ?= 2
# ROS 1 from Debian's archive, for fgdwa_node and its test (docs/ros.md).
ROS_PACKAGES := ros-core-dev ros-core-python-dev libtf2-ros-dev python3-tf2-ros libmove-base-msgs-dev \
	python3-move-base-msgs libactionlib-dev python3-actionlib python3-gencpp python3-genpy
# chromium: the test that opens a recording in Rerun's web viewer looks at it through headless Chromium.
# python3-venv and python3-dev: Debian's python3 makes no virtual environment
# without the one and builds no extension without the other's headers.
APT_PACKAGES := python3-venv python3-dev libeigen3-dev libfcl-dev libompl-dev libhwy-dev libboost-serialization-dev \
	libboost-filesystem-dev libboost-system-dev libgtest-dev libbenchmark-dev \
	chromium $(ROS_PACKAGES)

BIN := $(VENV)/bin
SOURCES := CMakeLists.txt pyproject.toml README.md $(shell find cpp python -type f -not -name '*.pyc' -not -path '*/__pycache__/*' -not -path 'cpp/ros/*')

.PHONY: setup system-packages demo test test-cpp test-python bench clean stubs sanitize tsan

setup: system-packages $(VENV)/.installed

system-packages:
	@missing=""; for p in $(APT_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" != "0" ]; then \
	    echo "fgdwa needs these Debian packages:$$missing"; \
	    echo "Install them as root, then run make again:"; \
	    echo "  sudo apt-get update && sudo apt-get install -y$$missing"; \
	    exit 1; \
	  fi; \
	  echo "Installing Debian packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)

$(VENV)/.tools: | $(BIN)/python
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q "scikit-build-core>=0.8" "pybind11>=2.11" "cmake>=3.16" ninja
	touch $@

# One build tree for everything: the wheel's build also compiles the C++
# suites, the benchmarks and the ROS node there, so the core is compiled once
# and test-cpp and bench only build what changed since.
BUILD_SETTINGS := -C build-dir=$(BUILD) -C cmake.define.BUILD_TESTING=ON \
	-C cmake.define.FGDWA_BUILD_BENCHMARKS=ON -C cmake.define.FGDWA_BUILD_ROS=AUTO \
	-C cmake.define.FGDWA_TEST_PYTHON=$(abspath $(BIN))/python

$(VENV)/.installed: $(SOURCES) | $(VENV)/.tools
	$(BIN)/python -m pip install -q --no-build-isolation $(BUILD_SETTINGS) ".[test,irsim,inspect]"
	touch $@

demo: setup
	$(BIN)/fgdwa demo --out $(OUT)/demo --gif $(OUT)/demo/demo.gif

test: setup test-cpp test-python

test-cpp: setup
	$(BIN)/cmake --build $(BUILD) -j $(JOBS)
	$(BIN)/ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# One worker per job, each test file on one worker: the fuzz module counts its
# calls across its own tests.
test-python: setup
	$(BIN)/python -m pytest -q -n $(JOBS) --dist loadfile tests/python

bench: setup
	$(BIN)/cmake --build $(BUILD) -j $(JOBS) --target bench_planner bench_global bench_fgdwa bench_navigator
	$(BUILD)/cpp/bench/bench_planner
	$(BUILD)/cpp/bench/bench_global
	$(BUILD)/cpp/bench/bench_fgdwa
	$(BUILD)/cpp/bench/bench_navigator

# The C++ suites and the extension built with AddressSanitizer and
# UndefinedBehaviorSanitizer in a tree of their own; ctest, then the fuzz and
# bad-input modules against the sanitized extension (the venv's Python with the
# sanitizers' runtimes preloaded; Python's own allocations are not leak-checked).
# -O1 with line tables: what ASan advises, and half the build time of -O2 -g.
SANITIZE_BUILD ?= build/sanitize
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
SANITIZE_ENV := ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

sanitize: setup
	$(BIN)/cmake -S . -B $(SANITIZE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" -DBUILD_TESTING=ON \
	  -DFGDWA_BUILD_PYTHON=ON -DFGDWA_BUILD_ROS=OFF -DPython_EXECUTABLE=$(abspath $(BIN))/python \
	  -Dpybind11_DIR="$$($(BIN)/python -m pybind11 --cmakedir)" -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE_FLAGS)" -DCMAKE_SHARED_LINKER_FLAGS="$(SANITIZE_FLAGS)" \
	  -DCMAKE_MAKE_PROGRAM=$(abspath $(BIN))/ninja
	$(BIN)/cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	$(SANITIZE_ENV) $(BIN)/ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j $(JOBS) -E install_and_build_example
	rm -rf $(SANITIZE_BUILD)/python && mkdir -p $(SANITIZE_BUILD)/python
	cp -r python/fgdwa $(SANITIZE_BUILD)/python/ && cp $(SANITIZE_BUILD)/cpp/bindings/_core*.so $(SANITIZE_BUILD)/python/fgdwa/
	LD_PRELOAD="$$(c++ -print-file-name=libasan.so) $$(c++ -print-file-name=libubsan.so)" $(SANITIZE_ENV) \
	  PYTHONPATH=$(abspath $(SANITIZE_BUILD))/python $(BIN)/python -m pytest -q -p no:cacheprovider \
	  tests/python/test_fuzz.py tests/python/test_bad_input.py

# The thread test (one planner per thread over a shared world, path, A*
# planner and scanner) built with ThreadSanitizer in a tree of its own.
TSAN_BUILD ?= build/tsan
TSAN_FLAGS := -fsanitize=thread -fno-omit-frame-pointer
tsan: setup
	$(BIN)/cmake -S . -B $(TSAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=ON \
	  -DFGDWA_BUILD_PYTHON=OFF -DFGDWA_BUILD_ROS=OFF -DCMAKE_CXX_FLAGS="$(TSAN_FLAGS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="$(TSAN_FLAGS)" -DCMAKE_SHARED_LINKER_FLAGS="$(TSAN_FLAGS)" \
	  -DCMAKE_MAKE_PROGRAM=$(abspath $(BIN))/ninja
	$(BIN)/cmake --build $(TSAN_BUILD) -j $(JOBS) --target test_threads
	TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 $(TSAN_BUILD)/tests/cpp/test_threads

clean:
	rm -rf build $(OUT) $(VENV)

# Regenerates the type stub of the C++ module after its bindings change.
stubs: setup
	$(BIN)/pybind11-stubgen fgdwa._core -o build/stubs
	cp build/stubs/fgdwa/_core.pyi python/fgdwa/_core.pyi
