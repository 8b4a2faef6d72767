# polygon.lua: `make test` runs every check, `make demo` the example scene, `make bench` the
# benchmark, `make docs` the API reference (docs/api/index.html). Missing Debian packages are
# installed first (apt-get, as root or through sudo).

LUAS     ?= lua5.1 lua5.2 lua5.3 lua5.4 luajit
LUA      ?= lua5.4
# lua-discount is LDoc's Markdown: Debian's lua-ldoc ships none of its own
PACKAGES  = lua5.1 lua5.2 lua5.3 lua5.4 luajit lua-busted lua-check luarocks lua-ldoc lua-discount
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all setup setup-love test lint docs demo bench bench-quick differential screenshots

all: test

# Installs whatever of $(PACKAGES) is missing: a package counts as there only when dpkg-query says
# "install ok installed" (dpkg -s also answers for one removed but not purged). apt-get update
# runs only when something is missing.
setup:
	@missing=""; for p in $(PACKAGES); do [ "$$(dpkg-query -W -f='$${Status}' $$p 2>/dev/null)" = "install ok installed" ] || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

# The LÖVE demos need love, a virtual X server and software OpenGL.
setup-love:
	@missing=""; for p in love xvfb xauth libgl1-mesa-dri; do [ "$$(dpkg-query -W -f='$${Status}' $$p 2>/dev/null)" = "install ok installed" ] || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

# Every check: luacheck, the specs on each interpreter, the rockspec, the quick benchmark and,
# when love is installed, the demo screenshots. Ends with "N passed, N failed".
test: setup
	@LUAS="$(LUAS)" bash .ci/test

lint: setup
	luacheck .

# The API reference from the doc comments of the front (docs/config.ld says which file); fails on
# any LDoc warning, as make test's check does.
docs: setup
	ldoc --fatalwarnings -c docs/config.ld .

demo: setup
	$(LUA) examples/scene.lua

bench: setup
	bash bench/bench.sh

# Every public function against v0.7.0's polygon.lua (git history), a million random calls each,
# bit for bit (about 11 minutes on LuaJIT; `make test` runs 20,000 a function).
differential: setup
	luajit bench/differential.lua 1000000

bench-quick: setup
	BENCH_QUICK=1 bash bench/bench.sh

screenshots: setup-love
	bash examples/love/check-screenshots.sh docs
