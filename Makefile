# arclen -- build, test, demo, bench, install.
#   make                 the module for Lua 5.4 (build/5.4/arclen.so)
#   make LUA=5.1|5.2|5.3|jit
#   make lib             the core as build/libarclen.a (no Lua dependency)
#   make test            the spec suite under Lua 5.4 (ends "N passed, N failed")
#   make demo            Henkel's six arcs by every method
#   make bench           speed ratios within one run
#   make bench-icount    instructions per call under callgrind (valgrind)
#   make bench-latency   each set-up step's time as a dependent chain
#   make bench-engines   the Lua engine against the C core (Lua 5.3, LuaJIT)
#   make install PREFIX=/usr/local
#   make rock            the LuaRocks source rocks in build/rock (tools/pack-rock.sh)
#
# GNU make is required: `gmake` on the BSDs (macOS's make 3.81 is GNU make).
# Lua's headers come from pkg-config when it knows this Lua, else from
# Debian's place; point LUA_INC at others, e.g. Homebrew's Lua:
#   make LUA_INC=$(brew --prefix lua)/include/lua
# Shared objects: `-bundle -undefined dynamic_lookup` on macOS (UNAME_S=Darwin),
# `-shared` elsewhere.

LUA ?= 5.4
PREFIX ?= /usr/local
CC ?= cc
CFLAGS ?= -O2 -g
WARN = -std=c99 -Wall -Wextra -Wpedantic -Werror=implicit-function-declaration
# No FMA contraction: a belt, not the proof.  The results do not depend on
# it (fma() where a fused product is meant, MetaPost's squares rounded by
# hand; `make check-builds` runs the specs on contracted and clang builds).
# No errno from libm (nothing reads it): sqrt becomes one instruction.
CORE_FLAGS = $(WARN) -ffp-contract=off -fno-math-errno -fPIC -D_POSIX_C_SOURCE=200809L

ifeq ($(LUA),jit)
  LUA_BIN ?= luajit
  LUA_ABI = 5.1
  LUA_PC_NAMES = luajit
  LUA_PC_VERSION = 2.
  LUA_INC_DEFAULT = /usr/include/luajit-2.1
else
  LUA_BIN ?= lua$(LUA)
  LUA_ABI = $(LUA)
  # The names Debian and Alpine (lua5.4), FreeBSD (lua-5.4, lua54) and
  # Homebrew (lua) give Lua's pkg-config file; "lua" only if its version is ours.
  LUA_PC_NAMES = lua$(LUA) lua-$(LUA) lua$(subst .,,$(LUA)) lua
  LUA_PC_VERSION = $(LUA).
  LUA_INC_DEFAULT = /usr/include/lua$(LUA)
endif
ifndef LUA_INC
  LUA_PC := $(shell for n in $(LUA_PC_NAMES); do \
    v=$$(pkg-config --modversion $$n 2>/dev/null) || continue; \
    case "$$v." in ($(LUA_PC_VERSION)*) echo $$n; break ;; esac; done)
  ifneq ($(LUA_PC),)
    LUA_INC := $(patsubst -I%,%,$(firstword $(shell pkg-config --cflags-only-I $(LUA_PC))))
  endif
  ifeq ($(LUA_INC),)
    LUA_INC := $(LUA_INC_DEFAULT)
  endif
endif

# A Lua module is a shared object that leaves lua_* to the interpreter;
# Apple's linker accepts that only for a bundle told so (ld(1), -undefined).
UNAME_S ?= $(shell uname -s 2>/dev/null)
ifeq ($(UNAME_S),Darwin)
  MODULE_LDFLAGS = -bundle -undefined dynamic_lookup
else
  MODULE_LDFLAGS = -shared
endif

BUILD = build
OUT = $(BUILD)/$(LUA)
# src/<area>/*.c is the core (no Lua); src/lua/ is the binding.  See
# doc/architecture.md for the areas and the one-way order between them.
AREAS = curve roots gauss elliptic metapost fit conic baseline segment svg methods
CORE_SRC = $(foreach a,$(AREAS),$(wildcard src/$(a)/*.c))
BIND_SRC = $(filter-out src/lua/svgdoc%.c,$(wildcard src/lua/*.c))
CORE_OBJ = $(patsubst src/%.c,$(BUILD)/core/%.o,$(CORE_SRC))
BIND_OBJ = $(patsubst src/%.c,$(OUT)/%.o,$(BIND_SRC))
HEADERS = $(wildcard src/*.h src/*/*.h)
# The SVG document reader (src/svgdoc/, over libexpat) is a module of its
# own, arclen.svgdoc, so that arclen.core needs nothing but libm.
DOC_SRC = $(wildcard src/svgdoc/*.c)
DOC_OBJ = $(patsubst src/%.c,$(BUILD)/core/%.o,$(DOC_SRC))
# The C part is the module arclen.core; require "arclen" is lua/arclen/init.lua.
MODULE = $(OUT)/arclen/core.so
DOC_MODULE = $(OUT)/arclen/svgdoc.so
# expat from pkg-config when it knows it, else the compiler's own paths
# (EXPAT_CFLAGS, EXPAT_LIBS override).  Without expat.h (Debian
# libexpat1-dev) the core still builds.
ifndef EXPAT_LIBS
  ifeq ($(shell pkg-config --exists expat 2>/dev/null && echo yes),yes)
    EXPAT_CFLAGS := $(shell pkg-config --cflags expat)
    EXPAT_LIBS := $(shell pkg-config --libs expat)
  else
    EXPAT_LIBS := -lexpat
  endif
endif
HAVE_EXPAT := $(shell printf '\043include <expat.h>\n' | $(CC) $(EXPAT_CFLAGS) -E - >/dev/null 2>&1 && echo yes)
# zlib, optional too: gzip-compressed documents (.svgz) are read when the
# reader is built with it (Debian zlib1g-dev; ZLIB_CFLAGS, ZLIB_LIBS
# override), and said to need it otherwise.
ifndef ZLIB_LIBS
  ifeq ($(shell pkg-config --exists zlib 2>/dev/null && echo yes),yes)
    ZLIB_CFLAGS := $(shell pkg-config --cflags zlib)
    ZLIB_LIBS := $(shell pkg-config --libs zlib)
  else
    ZLIB_LIBS := -lz
  endif
endif
HAVE_ZLIB := $(shell printf '\043include <zlib.h>\n' | $(CC) $(ZLIB_CFLAGS) -E - >/dev/null 2>&1 && echo yes)
ifeq ($(HAVE_ZLIB),yes)
  ZLIB_DEFS = -DARCLEN_HAVE_ZLIB
else
  ZLIB_LIBS :=
endif
ifeq ($(HAVE_EXPAT),yes)
  ALL_MODULES = $(MODULE) $(DOC_MODULE)
else
  ALL_MODULES = $(MODULE) no-expat
endif
LIBDIR = $(PREFIX)/lib/lua/$(LUA_ABI)
SHAREDIR = $(PREFIX)/share/lua/$(LUA_ABI)

.PHONY: all lib check-layers test deps demo bench bench-icount bench-latency install uninstall clean rock

all: $(ALL_MODULES)

.PHONY: no-expat
no-expat:
	@echo "make: expat.h not found: arclen.svg (SVG documents) is not built;" \
	  "install expat's headers (sh tools/deps.sh says how) or set EXPAT_CFLAGS, EXPAT_LIBS" >&2

lib: $(BUILD)/libarclen.a

# The areas depend one way and no two object files on each other (nm).
check-layers: $(CORE_OBJ) $(DOC_OBJ)
	python3 tools/check_layers.py $(BUILD)/core

# The document reader's files see expat's header (XFLAGS: per target).
$(DOC_OBJ) $(OUT)/lua/svgdoc.o: XFLAGS = $(EXPAT_CFLAGS)
# zlib's header for the inflater only (the object records whether it had
# zlib: a stamp of the choice rebuilds it when that changes)
$(BUILD)/core/svgdoc/gzip.o: XFLAGS = $(ZLIB_CFLAGS) $(ZLIB_DEFS)
$(BUILD)/core/svgdoc/gzip.o: $(BUILD)/zlib-$(if $(ZLIB_DEFS),yes,no)
$(BUILD)/zlib-yes $(BUILD)/zlib-no:
	@mkdir -p $(BUILD)
	@rm -f $(BUILD)/zlib-yes $(BUILD)/zlib-no
	@touch $@

$(BUILD)/core/%.o: src/%.c $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(CORE_FLAGS) $(XFLAGS) -Isrc -c $< -o $@

$(OUT)/%.o: src/%.c $(HEADERS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(CORE_FLAGS) $(XFLAGS) -Isrc -I$(LUA_INC) -c $< -o $@

$(BUILD)/libarclen.a: $(CORE_OBJ)
	rm -f $@
	ar rcs $@ $^

$(MODULE): $(CORE_OBJ) $(BIND_OBJ)
	@mkdir -p $(dir $@)
	$(CC) $(MODULE_LDFLAGS) -o $@ $^ -lm

$(DOC_MODULE): $(OUT)/lua/svgdoc.o $(OUT)/lua/svgdoc_gzip.o $(OUT)/lua/subpaths.o $(DOC_OBJ) $(BUILD)/libarclen.a
	@mkdir -p $(dir $@)
	$(CC) $(MODULE_LDFLAGS) -o $@ $^ $(EXPAT_LIBS) $(ZLIB_LIBS) -lm

# The test command builds the module for every Lua on the machine (5.4 and,
# where installed, 5.1, 5.2, 5.3 -- also LuaTeX's texlua -- and LuaJIT).
test:
	$(MAKE) LUA=5.4
	@for v in 5.1 5.2 5.3 jit; do \
	  if [ -f /usr/include/lua$$v/lua.h ] || [ $$v = jit -a -f /usr/include/luajit-2.1/lua.h ]; then \
	    $(MAKE) LUA=$$v || exit 1; fi; done
	sh tools/run-tests.sh

deps:
	@sh tools/deps.sh base

# The core rock and the SVG reader's rock, packed by `luarocks pack` from a
# source archive of the work tree (doc/testing.md, "LuaRocks").
rock:
	sh tools/pack-rock.sh $(BUILD)/rock

demo: $(MODULE)
	LUA_CPATH='$(OUT)/?.so' LUA_PATH='lua/?.lua;lua/?/init.lua' $(LUA_BIN) lua/arclen/cli.lua henkel

bench: $(BUILD)/libarclen.a
	$(MAKE) -C bench run

bench-icount: $(BUILD)/libarclen.a
	$(MAKE) -C bench icount

bench-latency: $(BUILD)/libarclen.a
	$(MAKE) -C bench latency

# The Lua engine (lua/arclen/pure.lua) against the C core on the same
# curves, as ratios within one run, under texlua's Lua (5.3) and LuaJIT.
.PHONY: bench-engines
bench-engines:
	$(MAKE) LUA=5.3
	$(MAKE) LUA=jit
	LUA_PATH='lua/?.lua;lua/?/init.lua' LUA_CPATH='$(BUILD)/5.3/?.so' lua5.3 bench/bench_engines.lua
	LUA_PATH='lua/?.lua;lua/?/init.lua' LUA_CPATH='$(BUILD)/jit/?.so' luajit bench/bench_engines.lua

install: $(ALL_MODULES)
	mkdir -p $(DESTDIR)$(LIBDIR)/arclen $(DESTDIR)$(SHAREDIR)/arclen/repro $(DESTDIR)$(PREFIX)/bin
	cp $(MODULE) $(DESTDIR)$(LIBDIR)/arclen/core.so
	if [ -f $(DOC_MODULE) ]; then cp $(DOC_MODULE) $(DESTDIR)$(LIBDIR)/arclen/svgdoc.so; fi
	cp lua/arclen/*.lua $(DESTDIR)$(SHAREDIR)/arclen/
	cp lua/arclen/repro/*.lua $(DESTDIR)$(SHAREDIR)/arclen/repro/
	sed '1s|.*|#!/usr/bin/env $(LUA_BIN)|' bin/arclen > $(DESTDIR)$(PREFIX)/bin/arclen
	chmod 755 $(DESTDIR)$(PREFIX)/bin/arclen

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/arclen/core.so $(DESTDIR)$(LIBDIR)/arclen/svgdoc.so $(DESTDIR)$(PREFIX)/bin/arclen
	-rmdir $(DESTDIR)$(LIBDIR)/arclen
	rm -rf $(DESTDIR)$(SHAREDIR)/arclen

clean:
	rm -rf $(BUILD)
	$(MAKE) -C bench clean

# ---- the fit: Walter & Fournier's Table 1, paper vs default ----------
.PHONY: fit-stats fit-plots
fit-stats: $(MODULE)
	LUA_CPATH='$(OUT)/?.so' LUA_PATH='lua/?.lua;lua/?/init.lua' $(LUA_BIN) lua/arclen/repro/fitstats.lua

fit-plots: $(MODULE)
	@mkdir -p $(BUILD)/plots
	LUA_CPATH='$(OUT)/?.so' LUA_PATH='lua/?.lua;lua/?/init.lua' $(LUA_BIN) lua/arclen/repro/plot.lua all $(BUILD)/plots

# The README's accuracy table: worst relative error per reference family.
.PHONY: accuracy
accuracy: $(MODULE)
	LUA_CPATH='$(OUT)/?.so' LUA_PATH='lua/?.lua;lua/?/init.lua;spec/?.lua' $(LUA_BIN) bench/accuracy.lua

# ---- reliability and peers ---------------------------------------------
#   make fuzz [FUZZ_SECONDS=15]   every libFuzzer harness in fuzz/ (clang)
#   make sanitize                 the spec suite on an ASan+UBSan build
#   make valgrind                 the spec suite under valgrind memcheck
#   make check-builds             the spec suite on contracted and clang builds
#   make bench-peers              arclen vs GSL, kurbo, bezier-js, paper.js,
#                                 MetaPost on the same curves, one run
#   make bench-scale              10^6 curves through the Lua API
#   make bench-svg-token          one 12.5 .. 100 MB attribute: time, RSS
#   make bench-svg                whole SVG documents: arclen.svg vs
#                                 svgelements, svg-path-properties, paper.js;
#                                 generated ones: time, peak RSS
#   make bench-svg-big            length and stat on 10 MB .. 1 GB of paths
#   make bench-paths              points along paths, with node/kurbo peers
FUZZ_SECONDS ?= 15
.PHONY: fuzz sanitize valgrind check-builds bench-peers bench-scale bench-svg bench-svg-token bench-paths bench-svg-big

fuzz:
	FUZZ_SECONDS=$(FUZZ_SECONDS) sh tools/fuzz.sh

sanitize:
	sh tools/check-sanitizers.sh

valgrind:
	sh tools/check-valgrind.sh

# The spec suite on GCC with -ffp-contract=fast -mfma, on clang, and on
# clang contracting (build/contract, build/clang, build/clang-contract).
check-builds:
	sh tools/check-builds.sh

bench-peers: $(BUILD)/libarclen.a
	sh bench/peers/run.sh

# librsvg's opinion on spec/data/svg/: spec/data/svg_rsvg.tsv (sh tools/deps.sh refs)
ref-rsvg:
	/usr/bin/python3 tools/ref_rsvg.py >/dev/null
.PHONY: ref-rsvg

bench-svg:
	sh bench/bench_svg.sh

# Memory against the file's size: arclen length and stat on generated files
# of paths of 10 MB, 100 MB and 1 GB (written to a temporary directory).
bench-svg-big: $(MODULE)
	BIG_FILES="paths:10 paths:100 paths:1000" BIG_TOOLS="length stat" sh bench/svg/big.sh

# One path whose d is 12.5 .. 100 MB: time and peak RSS of arclen length
# (linear in the token's size; GNU time).
bench-svg-token:
	sh bench/bench_svg_token.sh

# Points along paths: resample, points, dash on 10 .. 10^4 segments, k = 10
# .. 10^5, per point as ratios to one length call, with the node and kurbo
# peers (bench/peers/paths/) and their errors.
bench-paths: $(MODULE)
	@mkdir -p $(BUILD)/peers/paths
	PEERS_OUT=$(BUILD)/peers/paths LUA_CPATH='$(OUT)/?.so' LUA_PATH='lua/?.lua;lua/?/init.lua' $(LUA_BIN) bench/bench_paths.lua

# The floor: the binding with no lengths measured (bench/bench_scale_floor.c).
FLOOR = $(OUT)/bench_scale_floor.so
$(FLOOR): bench/bench_scale_floor.c src/lua/batch.c $(HEADERS) $(BIND_OBJ) $(BUILD)/libarclen.a
	$(CC) $(CFLAGS) $(CORE_FLAGS) -Isrc -I$(LUA_INC) $(MODULE_LDFLAGS) -o $@ $< \
	  $(filter-out %/batch.o,$(BIND_OBJ)) $(BUILD)/libarclen.a -lm

bench-scale: $(MODULE) $(BUILD)/libarclen.a $(FLOOR)
	$(MAKE) -s -C bench bin/bench_scale_c
	FLOOR=$(FLOOR) C_LOOP=bench/bin/bench_scale_c LUA_CPATH='$(OUT)/?.so' LUA_PATH='lua/?.lua;lua/?/init.lua' $(LUA_BIN) bench/bench_scale.lua

# ---- TeX: install-tex, ctan, luatex ----------------------------------
#   make install-tex [TEXMFHOME=DIR]   the TDS layout (tools/install-tex.sh):
#                 arclen.sty, the TikZ library, the Lua files, arclen.mp,
#                 the 5.3 C core for --shell-escape runs
#   make ctan     build/ctan/arclen.zip, with arclen.pdf typeset by lualatex
#                 from tex/arclen-doc.tex (tools/ctan.sh)
#   make luatex   the example documents in real LuaLaTeX and LuaTeX runs,
#                 with and without --shell-escape (build/luatex/), checked
#                 against mpmath references and arclen
.PHONY: install-tex ctan luatex
install-tex:
	$(MAKE) LUA=5.3
	sh tools/install-tex.sh $(TEXMFHOME)

ctan:
	$(MAKE) LUA=5.3
	sh tools/ctan.sh

luatex:
	$(MAKE) LUA=5.3
	sh tools/check-luatex.sh

# ---- thread safety -----------------------------------------------------
#   make check-threads   spec/c/threads.c: every family of the C API (and the
#                        SVG document reader, with expat) from 6 threads at
#                        once, each result bit for bit as on one thread,
#                        under ThreadSanitizer (tools/check-threads.sh; the
#                        core compiled anew in build/tsan/; clang, or CC=gcc)
.PHONY: check-threads
check-threads:
	sh tools/check-threads.sh

# ---- Windows: a MinGW cross-build --------------------------------------
#   make windows   build/windows/arclen/core.dll and svgdoc.dll for a
#                  Windows Lua 5.4, cross-built with x86_64-w64-mingw32-gcc
#                  (Debian gcc-mingw-w64-x86-64), no warnings allowed,
#                  against lua54.dll (tools/windows-lua.sh) and a static
#                  expat (tools/windows-expat.sh), both built from Debian's
#                  source packages, and Debian's static zlib for MinGW.  tools/check-windows.sh runs the specs
#                  under Wine.
WIN_CC ?= x86_64-w64-mingw32-gcc
WIN_AR ?= x86_64-w64-mingw32-ar
WIN_OUT = $(BUILD)/windows
WIN_LUA ?= $(WIN_OUT)/lua
WIN_EXPAT ?= $(WIN_OUT)/expat
WIN_FLAGS = $(WARN) -Werror -Wvla -ffp-contract=off -fno-math-errno
WIN_CORE_OBJ = $(patsubst src/%.c,$(WIN_OUT)/obj/%.o,$(CORE_SRC))
WIN_BIND_OBJ = $(patsubst src/%.c,$(WIN_OUT)/obj/%.o,$(BIND_SRC))
WIN_DOC_OBJ = $(patsubst src/%.c,$(WIN_OUT)/obj/%.o,$(DOC_SRC) src/lua/svgdoc.c src/lua/svgdoc_gzip.c)
# zlib for gzip input: Debian's libz-mingw-w64-dev, linked static (its
# libz.a; tools/check-windows.sh installs it).  Without it the DLL is
# built without gzip, which says so when it meets a .svgz.
WIN_ZLIB ?= /usr/x86_64-w64-mingw32/lib/libz.a
WIN_ZLIB_LIB = $(wildcard $(WIN_ZLIB))
.PHONY: windows
windows: $(WIN_OUT)/arclen/core.dll $(WIN_OUT)/arclen/svgdoc.dll

$(WIN_LUA)/lua54.dll:
	sh tools/windows-lua.sh $(WIN_LUA)

$(WIN_EXPAT)/lib/libexpat.a:
	sh tools/windows-expat.sh $(WIN_EXPAT)

# The document reader's files see expat's header, for a static libexpat
$(WIN_DOC_OBJ): WIN_DOC_FLAGS = -DXML_STATIC -I$(WIN_EXPAT)/include
$(WIN_DOC_OBJ): $(WIN_EXPAT)/lib/libexpat.a
$(WIN_OUT)/obj/svgdoc/gzip.o: WIN_DOC_FLAGS = $(if $(WIN_ZLIB_LIB),-DARCLEN_HAVE_ZLIB)

$(WIN_OUT)/obj/%.o: src/%.c $(HEADERS) $(WIN_LUA)/lua54.dll
	@mkdir -p $(dir $@)
	$(WIN_CC) $(CFLAGS) $(WIN_FLAGS) $(WIN_DOC_FLAGS) -Isrc -I$(WIN_LUA)/include -c $< -o $@

$(WIN_OUT)/libarclen.a: $(WIN_CORE_OBJ)
	rm -f $@
	$(WIN_AR) rcs $@ $^

# Linked against lua54.dll itself, and against nothing else but the C
# runtime: no -static-libgcc, so that a libgcc_s import shows in the check
$(WIN_OUT)/arclen/core.dll: $(WIN_CORE_OBJ) $(WIN_BIND_OBJ)
	@mkdir -p $(dir $@)
	$(WIN_CC) -shared -o $@ $^ $(WIN_LUA)/lua54.dll

$(WIN_OUT)/arclen/svgdoc.dll: $(WIN_DOC_OBJ) $(WIN_OUT)/obj/lua/subpaths.o $(WIN_OUT)/libarclen.a
	@mkdir -p $(dir $@)
	$(WIN_CC) -shared -o $@ $^ $(WIN_EXPAT)/lib/libexpat.a $(WIN_ZLIB_LIB) $(WIN_LUA)/lua54.dll
