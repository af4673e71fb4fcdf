# Thin wrapper over CMake: installs missing Debian packages, configures build/, builds, runs.
#   make demo   build and run the default scene (a window, or a headless capture to out/ without a display)
#   make test   build and run every test through ctest
#   make bench  build and print the per-pass frame benchmark
#   make bench-gpu  every bench under --backend egl at 1920x1080, one report in out/bench-gpu/ (BENCH_GPU_ARGS adds options)
#   make golden build and rewrite the golden images (tests/golden/*.png) from this build
#   make fuzz   build the libFuzzer targets with clang in build-fuzz/ and run each for FUZZ_SECONDS
#   make test-sanitize  build with AddressSanitizer + UBSan in build-sanitize/ and run every test
BUILD_DIR  ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
PACKAGES   := $(shell grep -v '^\#' tools/debian-packages.txt)
FUZZ_PACKAGES := $(shell grep -v '^\#' tools/fuzz-packages.txt)
SUDO       := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
FUZZ_DIR   ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := ini camera_path heightmap dem gltf
SANITIZE_DIR ?= build-sanitize
# Left out of the sanitizer run, to keep CI within its hour: drivers that only re-run vista's
# commands already run there (the quality sweep, the bench-gpu script, the Slurm cluster) and
# the extreme-scene sweep (minutes under the sanitizers; the plain build runs it). Also the
# image comparisons whose time is llvmpipe's rendering (not instrumented) and vista's CPU sky
# reference at full image sizes: the golden images (every post pass also runs in postfx_test),
# and the GPU sky and aerial perspective against the CPU reference (the reference runs under
# the sanitizers in the atmosphere unit tests, the sky and aerial passes in every GL scene test).
# Then the slowest image comparisons whose code the run covers elsewhere: EGL against OSMesa (the
# same passes, another context), the default scene's shards within a tolerance (the bit-identical
# shards, resume and mp4 tests drive the same farm code), bench sky and bench shadows (their
# scene isolation is the bench scene unit tests) and 100,000 lights (the light hash unit tests
# build 100,000 lights under the sanitizers), and the refit of the stored sky colour matrices (the
# spectral reference they come from runs under the sanitizers in the spectral agreement test).
# Every parser, file writer, CLI error path and every other unit test stays in the run.
SANITIZE_SKIP ?= vista quality writes|bench-gpu.s script|Slurm cluster|extreme scenes .config|golden images of the default scene|sky radiance from the GPU LUTs|aerial perspective on the ground matches|EGL backend renders the same image|shards of the default scene|bench sky measures|bench shadows, stabilised|100,000 lights and zero-radius|stored sky colour matrices are the fit
# Mesa (llvmpipe under OSMesa) is not built with the sanitizers and keeps allocations until exit:
# leaks are not checked in the tests; every other AddressSanitizer check is.
export ASAN_OPTIONS ?= detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS ?= print_stacktrace=1:halt_on_error=1

.PHONY: all deps fuzz-deps configure build demo test bench bench-gpu golden fuzz test-sanitize clean

all: build

# Installs only what is missing, so a machine that has everything never calls apt-get.
define install_missing
	@missing=$$(for p in $(1); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing Debian packages:" $$missing; \
	  $(SUDO) apt-get update && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
	fi
endef

deps:
	$(call install_missing,$(PACKAGES))

fuzz-deps: deps
	$(call install_missing,$(FUZZ_PACKAGES))

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

# Sized for under 5 minutes on a GPU; tools/bench_gpu.py --help lists the options.
bench-gpu: build
	python3 tools/bench_gpu.py --vista $(BUILD_DIR)/vista --out out/bench-gpu $(BENCH_GPU_ARGS)

golden: build
	VISTA_UPDATE_GOLDEN=1 ./$(BUILD_DIR)/tests/vista_gl_tests -tc="gl: golden images*"

# Each target runs for FUZZ_SECONDS from the seeds in tests/fuzz/corpus/NAME (new inputs go to
# $(FUZZ_DIR)/corpus/NAME); a crash is saved as $(FUZZ_DIR)/crash-NAME-* and fails the target.
# Leaks are checked except in the heightmap target: OpenImageIO's PNG reader leaks a string when
# libpng long-jumps out of a corrupt file (outside vista, not instrumented); nor in the DEM target:
# GDAL keeps its drivers, projection database and error contexts until exit.
fuzz: fuzz-deps
	@cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DVISTA_BUILD_TESTS=OFF -DVISTA_FUZZ=ON > $(FUZZ_DIR).configure.log 2>&1 || { cat $(FUZZ_DIR).configure.log; exit 1; }
	@cmake --build $(FUZZ_DIR) -j $(JOBS) --target $(addprefix vista_fuzz_,$(FUZZ_TARGETS))
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_DIR)/corpus/$$t; \
	  echo "fuzzing $$t for $(FUZZ_SECONDS) s"; \
	  leaks=1; case $$t in heightmap|dem) leaks=0;; esac; \
	  ASAN_OPTIONS=detect_leaks=$$leaks ./$(FUZZ_DIR)/tests/fuzz/vista_fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	    -print_final_stats=1 -artifact_prefix=$(FUZZ_DIR)/crash-$$t- $(FUZZ_DIR)/corpus/$$t tests/fuzz/corpus/$$t \
	    2> $(FUZZ_DIR)/$$t.log || { tail -50 $(FUZZ_DIR)/$$t.log; echo "make fuzz: $$t failed; the input is in $(FUZZ_DIR)/crash-$$t-*"; exit 1; }; \
	  grep -E '^stat::number_of_executed_units|^stat::new_units_added' $(FUZZ_DIR)/$$t.log | sed "s/^/  $$t /"; \
	done

# Unit and GL tests built with -fsanitize=address,undefined (VISTA_SANITIZE) in $(SANITIZE_DIR).
# -g1 (line tables, no variables): a report's stack trace still names functions, files and lines,
# and each file compiles in 15-28% less CPU time than with -g (measured on three files).
SANITIZE_CXXFLAGS ?= -O2 -g1 -DNDEBUG
test-sanitize: deps
	@cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISTA_BUILD_TESTS=ON -DVISTA_SANITIZE=address,undefined \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(SANITIZE_CXXFLAGS)" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(SANITIZE_CXXFLAGS)" \
	  > $(SANITIZE_DIR).configure.log 2>&1 || { cat $(SANITIZE_DIR).configure.log; exit 1; }
	@cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ctest --output-on-failure -j $(JOBS) --timeout 1800 -E "$(SANITIZE_SKIP)"

clean:
	rm -rf $(BUILD_DIR) $(BUILD_DIR).configure.log
