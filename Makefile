# Makefile: drives CMake. `make demo` and `make test` install missing Debian packages first.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
DEMO_MODEL ?= tests/data/fox.obj
# the fox stands on the xy plane: z is its up axis
DEMO_PREVIEW ?= --up z
DATA ?= ../shared/data
# Compiles go through ccache when it is installed (scripts/install-deps.sh installs it): a rebuild,
# and consumer_subproject's build of the library inside a parent project (the same compile
# commands), then reuse the objects compiled before. Checked when a build folder is configured, after
# deps has installed it; CCACHE= turns it off; a launcher in CMAKE_FLAGS wins.
CCACHE ?= ccache
LAUNCHER = $(if $(CCACHE),$$(command -v $(CCACHE) > /dev/null && echo -DCMAKE_C_COMPILER_LAUNCHER=$(CCACHE) \
  -DCMAKE_CXX_COMPILER_LAUNCHER=$(CCACHE)))

.PHONY: all deps configure build demo test tsan bench install package clean fuzz fuzz-build fuzz-pipeline fuzz-long fuzz-assimp blender-addon test-blender test-distributed

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(LAUNCHER) $(CMAKE_FLAGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@mkdir -p demo-output
	./$(BUILD)/coverage-axis $(DEMO_MODEL) -o demo-output/skeleton.ma --obj demo-output/skeleton.obj --ply demo-output/skeleton.ply \
	  --gltf demo-output/skeleton.glb --preview demo-output/skeleton.png $(DEMO_PREVIEW)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# the concurrency stress test (several contexts in threads, CBC and Clp included) under
# ThreadSanitizer, in its own build folder
tsan: deps
	@cmake -S . -B build-tsan $(LAUNCHER) -DCA_TSAN=ON -DCA_BUILD_BINDINGS=OFF -DCA_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
	@cmake --build build-tsan -j $(JOBS) --target test_concurrent_contexts
	@cd build-tsan && ctest --output-on-failure -R '^concurrent_contexts$$'

# the Blender add-on as an installable zip, the Python binding and the library bundled inside
blender-addon: build
	@bash bindings/blender/pack.sh $(BUILD) $(BUILD)/coverage_axis_blender.zip

# the add-on in headless Blender (installs Debian's blender first)
test-blender: build
	@bash scripts/install-deps.sh blender
	@bash bindings/blender/tests/run_test.sh $(BUILD) .

# the cluster route (examples/distributed) on a 2-worker Dask LocalCluster over TLS on 127.0.0.1
# (installs Debian's python3-distributed and python3-cryptography first)
test-distributed: build
	@bash scripts/install-deps.sh python3-distributed python3-cryptography
	@bash examples/distributed/tests/run_test.sh $(BUILD) .

# every bench program, its output written to docs/benchmarks.md (stamped with date, machine, commit);
# BENCH_ONLY="bench_a bench_b" reruns only those and keeps the other sections
bench: build
	@BENCH_ONLY="$(BENCH_ONLY)" bash scripts/bench_report.sh $(BUILD) $(DATA) docs/benchmarks.md

install: build
	@cmake --install $(BUILD) $(if $(PREFIX),--prefix $(PREFIX),)

# the Debian package (libraries, header, CMake package, pkg-config file, the tool; docs/building.md):
# $(BUILD)/coverage-axis_<version>_<arch>.deb
package: build
	@cmake --build $(BUILD) --target package

# libFuzzer (clang, ASan/UBSan): the C ABI (fuzz_pipeline, seeded with the small bundled meshes in
# its structured format, tests/fuzz/make_seeds.py) and every file reader (fuzz_read_<format>, seeded
# with the test models of that format), FUZZ_SECONDS each, one after the other
FUZZ_SECONDS ?= 60
FUZZ_READERS ?= obj off ply xyz pts stl gltf glb dae fbx
FUZZ_SEEDS = tests/data/hourglass.obj tests/data/wall.obj tests/data/desk_table.obj tests/data/fox.obj \
  tests/data/chair_soup.obj
fuzz-build:
	@bash scripts/install-deps.sh clang libclang-rt-14-dev
	@cmake -S . -B build-fuzz $(LAUNCHER) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCA_FUZZ=ON -DCA_SANITIZE=ON \
	  -DCA_BUILD_TESTS=OFF -DCA_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
	@cmake --build build-fuzz -j $(JOBS) --target fuzz_pipeline $(addprefix fuzz_read_,$(FUZZ_READERS))
	@python3 tests/fuzz/make_seeds.py build-fuzz/seeds $(FUZZ_SEEDS)
	@mkdir -p build-fuzz/corpus

fuzz-pipeline: fuzz-build
	./build-fuzz/fuzz_pipeline -max_total_time=$(FUZZ_SECONDS) -max_len=16384 -timeout=30 \
	  -rss_limit_mb=3000 build-fuzz/corpus build-fuzz/seeds

fuzz: fuzz-pipeline
	@for f in $(FUZZ_READERS); do \
	  mkdir -p build-fuzz/corpus_$$f build-fuzz/seeds_$$f && \
	  find tests/data -name "*.$$f" -size -200k -exec cp {} build-fuzz/seeds_$$f/ \; && \
	  ./build-fuzz/fuzz_read_$$f -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    build-fuzz/corpus_$$f build-fuzz/seeds_$$f || exit 1; \
	done

# ten minutes of the pipeline harness, the run that reaches the deep steps
fuzz-long:
	@$(MAKE) --no-print-directory fuzz-pipeline FUZZ_SECONDS=600

# a mutation fuzzer of the formats read through assimp, run through the tool (tests/fuzz/fuzz_assimp.py;
# ctest runs a short one): seeded with the bundled models and hostile files, and with the shared
# real models and hostile files when $(DATA) is there; FUZZ_ASSIMP_SECONDS in all, the formats taking
# turns, JOBS runs at a time. Findings (the tool killed, past its time limit, an unclear failure)
# and the first inputs assimp crashed, hung or ran out of memory on go to $(BUILD)/fuzz-assimp.
FUZZ_ASSIMP_SECONDS ?= 600
FUZZ_ASSIMP_FORMATS ?= md3,ac,3ds,x,dae,fbx,blend,b3d
fuzz-assimp: configure
	@cmake --build $(BUILD) -j $(JOBS) --target coverage-axis
	python3 tests/fuzz/fuzz_assimp.py --tool $(BUILD)/coverage-axis --seconds $(FUZZ_ASSIMP_SECONDS) --jobs $(JOBS) \
	  --formats $(FUZZ_ASSIMP_FORMATS) --out $(BUILD)/fuzz-assimp tests/data/hostile tests/data/formats tests/data/dropped \
	  $(wildcard $(DATA)/real/openarena $(DATA)/real/flightgear $(DATA)/hostile)

clean:
	@rm -rf $(BUILD) build-fuzz demo-output
