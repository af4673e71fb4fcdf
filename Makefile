# Thin wrapper over CMake: installs missing Debian packages, configures build/, builds, runs.
#   make demo   build and run the default scene (a window, or a headless capture to out/ without a display)
#   make test   build and run every test through ctest
#   make bench  build and print the per-pass frame benchmark
#   make golden build and rewrite the golden images (tests/golden/*.png) from this build
BUILD_DIR  ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
PACKAGES   := $(shell grep -v '^\#' tools/debian-packages.txt)
SUDO       := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build demo test bench golden clean

all: build

# Installs only what is missing, so a machine that has everything never calls apt-get.
deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing Debian packages:" $$missing; \
	  $(SUDO) apt-get update && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
	fi

configure: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DVISTA_BUILD_TESTS=ON > $(BUILD_DIR).configure.log 2>&1 || { cat $(BUILD_DIR).configure.log; exit 1; }

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	./$(BUILD_DIR)/vista

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	./$(BUILD_DIR)/vista bench frame

golden: build
	VISTA_UPDATE_GOLDEN=1 ./$(BUILD_DIR)/tests/vista_gl_tests -tc="gl: golden images*"

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log
