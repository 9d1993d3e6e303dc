# SPDX-License-Identifier: GPL-2.0-only
# SPDX-FileCopyrightText: 2026 The rdc authors
# rdc top-level build.  `make` builds userspace (librdc, rdcctl) optimised;
# `make check` builds everything with AddressSanitizer and
# UndefinedBehaviorSanitizer and runs every test; `make demo` runs
# examples/demo.rdl.  `make help` lists the rest.

CC ?= cc
O ?= build
PKG_CONFIG ?= pkg-config

WARN := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
	-Wpointer-arith -Wvla -Wformat=2 -Wundef
ifneq ($(CI),)
WARN += -Werror
endif
ifneq ($(WERROR),)
WARN += -Werror
endif

# Every user-space target sees the public headers (and the register map
# beside them); the private ones (librdc's rdc_priv.h, the display
# processor's, the driver's ioctl headers) only what is given PRIV_INC
# below: librdc itself and the programs that test or measure it from
# inside, so a private header cannot leak into rdcd or rdcctl unseen.
INC := -Ihw-sim -Iuserspace/include
PRIV_INC := -Ifirmware-model -Iuserspace/lib -Idriver
BASE_CFLAGS := -std=gnu11 $(WARN) $(INC) -D_GNU_SOURCE
REL_CFLAGS := $(BASE_CFLAGS) -O2 -g
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all \
	-fno-omit-frame-pointer
SAN_CFLAGS := $(BASE_CFLAGS) -O1 -g $(SAN_FLAGS)

LIBS := $(shell $(PKG_CONFIG) --libs libpng zlib 2>/dev/null || echo -lpng -lz)
# Optional libraries: a build without one says so when it builds librdc
# (not while make reads this file: `make demo` and `make check` install
# them first, and their inner make is the one that builds).
MISSING :=
# The vnc frame sink needs libvncserver; without it the build goes on and
# that sink answers RDC_E_NOSYS.
HAVE_VNC := $(shell $(PKG_CONFIG) --exists libvncserver 2>/dev/null && echo 1)
ifeq ($(HAVE_VNC),1)
VNC_CFLAGS := -DRDC_HAVE_VNC $(shell $(PKG_CONFIG) --cflags libvncserver)
REL_CFLAGS += $(VNC_CFLAGS)
SAN_CFLAGS += $(VNC_CFLAGS)
LIBS += $(shell $(PKG_CONFIG) --libs libvncserver)
else
MISSING += "libvncserver not found (Debian: libvncserver-dev): building without the vnc sink"
endif
# The usb: backend and rdcd's FunctionFS listener need libusb-1.0 (the
# listener itself only the kernel's FunctionFS headers); without it usb:
# answers RDC_E_NOSYS.
HAVE_USB := $(shell $(PKG_CONFIG) --exists libusb-1.0 2>/dev/null && echo 1)
ifeq ($(HAVE_USB),1)
USB_CFLAGS := -DRDC_HAVE_USB $(shell $(PKG_CONFIG) --cflags libusb-1.0)
REL_CFLAGS += $(USB_CFLAGS)
SAN_CFLAGS += $(USB_CFLAGS)
LIBS += $(shell $(PKG_CONFIG) --libs libusb-1.0)
else
MISSING += "libusb-1.0 not found (Debian: libusb-1.0-0-dev): building without the usb: backend"
endif
# GPIO lines (fbdev: pins, rdcd's gpio-sim bridge) need libgpiod's v2 API;
# Debian 12 has it in bookworm-backports (scripts/deps.sh).
HAVE_GPIOD := $(shell $(PKG_CONFIG) --atleast-version=2.0 libgpiod 2>/dev/null && echo 1)
ifeq ($(HAVE_GPIOD),1)
GPIOD_CFLAGS := -DRDC_HAVE_GPIOD $(shell $(PKG_CONFIG) --cflags libgpiod)
REL_CFLAGS += $(GPIOD_CFLAGS)
SAN_CFLAGS += $(GPIOD_CFLAGS)
LIBS += $(shell $(PKG_CONFIG) --libs libgpiod)
else
MISSING += "libgpiod >= 2.0 not found (Debian 12: libgpiod-dev from bookworm-backports): building without GPIO lines"
endif
# The drm: backend (rdcdrm.ko's cards) and the KMS test programs need
# libdrm; without it drm: answers RDC_E_NOSYS and the VM tests that use
# them skip.
HAVE_DRM := $(shell $(PKG_CONFIG) --exists libdrm 2>/dev/null && echo 1)
ifeq ($(HAVE_DRM),1)
DRM_CFLAGS := -DRDC_HAVE_DRM $(shell $(PKG_CONFIG) --cflags libdrm)
REL_CFLAGS += $(DRM_CFLAGS)
SAN_CFLAGS += $(DRM_CFLAGS)
LIBS += $(shell $(PKG_CONFIG) --libs libdrm)
else
MISSING += "libdrm not found (Debian: libdrm-dev): building without the drm: backend"
endif
LIBS += -lpthread
CMOCKA_LIBS := $(shell $(PKG_CONFIG) --libs cmocka 2>/dev/null || echo -lcmocka)

CORE_SRCS := $(sort $(wildcard hw-sim/*.c firmware-model/*.c))
LIB_SRCS := $(sort $(wildcard userspace/lib/*.c userspace/sink/*.c))
CTL_SRCS := $(sort $(wildcard userspace/rdcctl/*.c))
RDCD_SRCS := $(sort $(wildcard userspace/rdcd/*.c))
TEST_SRCS := $(sort $(wildcard tests/unit/test_*.c))
# Shared test code, the plain reference rasterisers (tests/unit/ref*.c)
# among it: linked into the unit tests only, never into librdc or rdcfb.ko.
TEST_HELPERS := $(sort $(filter-out $(TEST_SRCS),$(wildcard tests/unit/*.c)))

REL_OBJS := $(patsubst %.c,$(O)/rel/%.o,$(CORE_SRCS) $(LIB_SRCS))
SAN_OBJS := $(patsubst %.c,$(O)/san/%.o,$(CORE_SRCS) $(LIB_SRCS))
TEST_BINS := $(patsubst tests/unit/%.c,$(O)/san/tests/%,$(TEST_SRCS))
TEST_HELPER_OBJS := $(patsubst %.c,$(O)/san/%.o,$(TEST_HELPERS))

.PHONY: all deps demo check test golden freestanding speed bench clean help \
	shared install uninstall install-check debs FORCE \
	bench-sink vm-test bench-net bench-idle bench-usb fuzz fuzz-long \
	fuzz-bins fuzz-cov \
	bench-peers bench-stream-vm module dkms-source \
	module-clean checkpatch format format-check firmware-mcu mcu-test \
	python-check
all: $(O)/rel/rdcctl $(O)/rel/rdcd $(O)/rel/librdc.a shared $(O)/rel/rdc.pc

help:
	@echo "make              build librdc (.a, .so), rdcctl and rdcd (optimised) in $(O)/rel"
	@echo "make install      install them, the headers, rdc.pc (PREFIX=, DESTDIR=, LIBDIR=...)"
	@echo "make uninstall    remove what make install put there (the same variables)"
	@echo "make install-check install into a scratch DESTDIR, build examples/hello.c against it"
	@echo "make debs         the Debian packages (debian/) in $(O)-debs, lintian, and the packaged tools run"
	@echo "make demo         install missing packages, build, run examples/demo.rdl"
	@echo "make python-check the Python bindings' and pytest plugin's tests (docs/python.md)"
	@echo "make check        install missing packages, build with ASan+UBSan, run every test"
	@echo "make golden       regenerate tests/golden/golden.txt and write PNGs to $(O)/golden"
	@echo "make freestanding compile hw-sim/ and firmware-model/ with no libc headers"
	@echo "make firmware-mcu the core for a Cortex-M3 (QEMU mps2-an385), replaying the golden scenes"
	@echo "make mcu-test     run it under QEMU: CRCs and cycles equal the host's"
	@echo "make speed        time a full-screen fill through the command path against memset"
	@echo "make bench        the workloads (bench/README.md) against plain-C limits, then rdcd, sinks"
	@echo "make bench-peers  the same, also against pixman, cairo and SDL2_gfx"
	@echo "make bench-sink   v4l2 sink conversion cost per frame against memcpy"
	@echo "make bench-net    rdcd over a UNIX socket: submit rate, register round trip, frames"
	@echo "make bench-idle   an idle paced rdcd's share of a core over 60 s (two minutes)"
	@echo "make bench-usb    the same over USB against the socket, in the VM (figures only)"
	@echo "make bench-stream-vm  rdcctl stream at 1920x1080 into v4l2loopback, in the VM (figures only)"
	@echo "make fuzz         short libFuzzer runs: protocol codec, USB framing, rdcd, .rdl, traces"
	@echo "make fuzz-long    the same targets, ten minutes in all (FUZZ_LONG_TIME s each)"
	@echo "make fuzz-cov     line coverage per file of the fuzz corpora (llvm-14)"
	@echo "make vm-test      boot Debian's kernel in QEMU and run tests/vm/tests/* (RDC_VM_KERNEL=)"
	@echo "make module       build rdcfb.ko and rdcdrm.ko in $(O)/kmod (KDIR= for another kernel)"
	@echo "make dkms-source  rdcfb.ko's source for dkms in $(O)/dkms/rdcfb-VERSION"
	@echo "make checkpatch   the kernel's checkpatch.pl over driver/ and the core"
	@echo "make format-check clang-format 14 over every C file: fails on any difference"
	@echo "make format       apply it"

deps:
	@scripts/deps.sh

$(O)/rel/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(REL_CFLAGS) -MMD -MP -c $< -o $@

$(O)/san/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(SAN_CFLAGS) -MMD -MP -c $< -o $@

# Who may include private headers (see INC).
PRIV_DIRS := userspace/lib userspace/sink tests/unit tests/vm bench
$(foreach d,$(PRIV_DIRS),$(O)/rel/$(d)/%.o $(O)/san/$(d)/%.o): \
	REL_CFLAGS += $(PRIV_INC)
$(foreach d,$(PRIV_DIRS),$(O)/rel/$(d)/%.o $(O)/san/$(d)/%.o): \
	SAN_CFLAGS += $(PRIV_INC)
$(O)/pic/userspace/lib/%.o $(O)/pic/userspace/sink/%.o: \
	REL_CFLAGS += $(PRIV_INC)
$(O)/rel/rdc-bench-peers: REL_CFLAGS += $(PRIV_INC)
# The core's own structs (hw-sim/hw.h, firmware-model/dp.h) are open to
# the core and its unit tests only; every other host sees rdc_chip.h.
$(O)/rel/tests/unit/%.o $(O)/san/tests/unit/%.o: \
	REL_CFLAGS += -DRDC_CORE_INTERNAL
$(O)/rel/tests/unit/%.o $(O)/san/tests/unit/%.o: \
	SAN_CFLAGS += -DRDC_CORE_INTERNAL

$(O)/rel/librdc.a: $(REL_OBJS)
	@rm -f $@
	@for m in $(MISSING); do echo "$$m"; done
	ar rcs $@ $^

$(O)/san/librdc.a: $(SAN_OBJS)
	@rm -f $@
	@for m in $(MISSING); do echo "$$m"; done
	ar rcs $@ $^

$(O)/rel/rdcctl: $(patsubst %.c,$(O)/rel/%.o,$(CTL_SRCS)) $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

$(O)/rel/rdcd: $(patsubst %.c,$(O)/rel/%.o,$(RDCD_SRCS)) $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

$(O)/san/rdcd: $(patsubst %.c,$(O)/san/%.o,$(RDCD_SRCS)) $(O)/san/librdc.a
	$(CC) $(SAN_CFLAGS) $^ $(LIBS) -o $@

$(O)/san/rdcctl: $(patsubst %.c,$(O)/san/%.o,$(CTL_SRCS)) $(O)/san/librdc.a
	$(CC) $(SAN_CFLAGS) $^ $(LIBS) -o $@

$(O)/san/tests/%: $(O)/san/tests/unit/%.o $(TEST_HELPER_OBJS) $(O)/san/librdc.a
	@mkdir -p $(dir $@)
	$(CC) $(SAN_CFLAGS) $^ $(CMOCKA_LIBS) $(LIBS) -lm -o $@
# Tests run the rdcctl and rdcd beside them ($(O)/san): building one test
# (`make $(O)/san/tests/test_vcd`) builds those too.
$(TEST_BINS): | $(O)/san/rdcctl $(O)/san/rdcd

# The DisplayLink decoder is rdcd's (userspace/rdcd/udl_decode.c).
$(O)/san/tests/unit/test_udl_decode.o: SAN_CFLAGS += -Iuserspace/rdcd
$(O)/san/tests/test_udl_decode: $(O)/san/tests/unit/test_udl_decode.o \
		$(O)/san/userspace/rdcd/udl_decode.o $(TEST_HELPER_OBJS) \
		$(O)/san/librdc.a
	@mkdir -p $(dir $@)
	$(CC) $(SAN_CFLAGS) $^ $(CMOCKA_LIBS) $(LIBS) -lm -o $@

# The web sink's page is built into web_page.o (.incbin of web/); its
# unit test reads the sink's protocol header.
WEB_PAGE := web/index.html web/rdc.js web/rdc.css
$(O)/rel/userspace/sink/web_page.o $(O)/san/userspace/sink/web_page.o \
	$(O)/pic/userspace/sink/web_page.o: $(WEB_PAGE)
$(O)/san/tests/unit/test_web.o: SAN_CFLAGS += -Iuserspace/sink

# ---- librdc as a shared library, and make install --------------------------
# The version is rdc.h's RDC_VERSION_MAJOR/MINOR/PATCH; the SONAME follows
# the major number.  librdc.so exports what its installed headers declare
# and nothing else: scripts/librdc-map.sh writes the version script from
# them (the public API under RDC_<major>; rdc_server.h and rdc_chip.h,
# what rdcd uses, under RDC_PRIVATE_<version>).  Its objects are built
# position-independent in $(O)/pic; librdc.a keeps the $(O)/rel ones.
# $(O)/include/rdc is the header tree `make install` copies, with the
# register map under RDC_ names only (scripts/public-regs.sh).  The
# rdcctl and rdcd that get installed are linked against librdc.so
# ($(O)/rel/dyn); the ones in $(O)/rel carry librdc.a, so they run from
# the build directory as they are.
RDC_VERSION := $(shell awk '/^\#define[ \t]+RDC_VERSION_(MAJOR|MINOR|PATCH)[ \t]/ \
	{ v = v (v == "" ? "" : ".") $$3 } END { print v }' \
	userspace/include/rdc.h)
RDC_SO_NAME := librdc.so.$(firstword $(subst ., ,$(RDC_VERSION)))
RDC_SO_FILE := librdc.so.$(RDC_VERSION)
PIC_OBJS := $(patsubst %.c,$(O)/pic/%.o,$(CORE_SRCS) $(LIB_SRCS))
HDR_DIR := $(O)/include/rdc
HDR_SRCS := $(sort $(wildcard userspace/include/rdc*.h)) hw-sim/rdc_chip.h \
	hw-sim/rdc_image.h
SO_LINKS := $(O)/rel/$(RDC_SO_NAME) $(O)/rel/librdc.so

$(O)/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(REL_CFLAGS) -fPIC -MMD -MP -c $< -o $@

$(HDR_DIR)/.stamp: $(HDR_SRCS) hw-sim/rdc_regs.h scripts/public-regs.sh
	@rm -rf $(HDR_DIR) && mkdir -p $(HDR_DIR)
	cp $(HDR_SRCS) $(HDR_DIR)/
	scripts/public-regs.sh hw-sim/rdc_regs.h >$(HDR_DIR)/rdc_regs.h
	@touch $@

$(O)/rel/librdc.map: $(HDR_DIR)/.stamp scripts/librdc-map.sh
	scripts/librdc-map.sh "$(CC)" $(HDR_DIR) $(RDC_VERSION) >$@.tmp
	@mv $@.tmp $@

$(O)/rel/$(RDC_SO_FILE): $(PIC_OBJS) $(O)/rel/librdc.map
	$(CC) -shared -Wl,-soname,$(RDC_SO_NAME) -Wl,--no-undefined \
		-Wl,--version-script=$(O)/rel/librdc.map $(LDFLAGS) \
		$(PIC_OBJS) $(LIBS) -o $@
$(SO_LINKS): $(O)/rel/$(RDC_SO_FILE)
	ln -sf $(RDC_SO_FILE) $@

# -Wl,--as-needed: a library the program itself does not call (libpng for
# rdcd) is librdc.so's to load, not its.  $(RDC_RUNPATH): see make
# install; the stamp relinks them when it changes (another LIBDIR).
$(O)/rel/dyn/rdcctl: $(patsubst %.c,$(O)/rel/%.o,$(CTL_SRCS)) $(SO_LINKS) \
		$(O)/rel/dyn/runpath
	@mkdir -p $(dir $@)
	$(CC) $(REL_CFLAGS) $(LDFLAGS) -Wl,--as-needed $(RDC_RUNPATH) \
		$(filter %.o,$^) $(O)/rel/librdc.so $(LIBS) -o $@
$(O)/rel/dyn/rdcd: $(patsubst %.c,$(O)/rel/%.o,$(RDCD_SRCS)) $(SO_LINKS) \
		$(O)/rel/dyn/runpath
	@mkdir -p $(dir $@)
	$(CC) $(REL_CFLAGS) $(LDFLAGS) -Wl,--as-needed $(RDC_RUNPATH) \
		$(filter %.o,$^) $(O)/rel/librdc.so $(LIBS) -o $@
$(O)/rel/dyn/runpath: FORCE
	@mkdir -p $(dir $@)
	@echo '$(RDC_RUNPATH)' | cmp -s - $@ 2>/dev/null || \
		echo '$(RDC_RUNPATH)' >$@
FORCE:

# rdc.pc (written by make install): the optional libraries this build
# links are its Requires.private.
RDC_PC_REQUIRES := libpng zlib $(if $(HAVE_VNC),libvncserver) \
	$(if $(HAVE_USB),libusb-1.0) $(if $(HAVE_GPIOD),libgpiod) \
	$(if $(HAVE_DRM),libdrm)

shared: $(SO_LINKS) $(O)/rel/dyn/rdcctl $(O)/rel/dyn/rdcd

# Directories, as GNU's coding standards name them; DESTDIR stages.
PREFIX ?= /usr/local
EXEC_PREFIX ?= $(PREFIX)
BINDIR ?= $(EXEC_PREFIX)/bin
LIBDIR ?= $(EXEC_PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
DATAROOTDIR ?= $(PREFIX)/share
MANDIR ?= $(DATAROOTDIR)/man
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
BASHCOMPDIR ?= $(DATAROOTDIR)/bash-completion/completions
SYSTEMDUSERUNITDIR ?= $(PREFIX)/lib/systemd/user
UDEVRULESDIR ?= $(PREFIX)/lib/udev/rules.d
INSTALL ?= install
INSTALL_PROGRAM ?= $(INSTALL) -m 755
INSTALL_DATA ?= $(INSTALL) -m 644

# The installed rdcctl and rdcd find librdc.so.1 where the loader looks:
# in a directory of ldconfig's (/usr/lib/<triplet>, /usr/local/lib ...:
# RDC_LOADER_DIRS, symlinks resolved), where make install into the live
# system (no DESTDIR) then runs ldconfig, as autotools and meson installs
# do; any other LIBDIR is named by their RUNPATH, as libtool links them.
LDCONFIG ?= /sbin/ldconfig
# (a directory not made yet is one ldconfig "can't stat").
RDC_LOADER_DIRS ?= $(eval RDC_LOADER_DIRS := $(shell LC_ALL=C $(LDCONFIG) \
	-v -N 2>&1 | sed -n -e 's/^\(\/[^:]*\): .from .*/\1/p' \
	-e "s/.*Can't stat \(\/[^:]*\):.*/\1/p" | \
	xargs -r realpath -m))$(RDC_LOADER_DIRS)
RDC_LIBDIR_LOADER = $(filter $(shell realpath -m '$(LIBDIR)'),$(RDC_LOADER_DIRS))
RDC_RUNPATH = $(if $(RDC_LIBDIR_LOADER),,-Wl,-rpath,$(LIBDIR))
# The directories make install creates (parents too) are listed in
# $(RDC_INSTALL_DIRS), so that make uninstall removes them when empty,
# and only them.
RDC_INSTALL_DIRS := $(O)/install-dirs

# What the rest of the tree brings, picked up as it lands: manual pages
# (man/*.[1-8], or generated into $(O)/man), bash completion
# (dist/bash-completion/), systemd user units (dist/systemd/*.service,
# *.socket) and udev rules (dist/udev/*.rules).
INSTALL_MAN = $(wildcard man/*.[1-8] $(O)/man/*.[1-8])
INSTALL_BASHCOMP = $(wildcard dist/bash-completion/*)
INSTALL_UNITS = $(wildcard dist/systemd/*.service dist/systemd/*.socket)
INSTALL_UDEV = $(wildcard dist/udev/*.rules)

define RDC_PC
prefix=$(PREFIX)
exec_prefix=$(EXEC_PREFIX)
libdir=$(LIBDIR)
includedir=$(INCLUDEDIR)

Name: rdc
Description: librdc, the host library of the RDC-1 simulated raster display controller
Version: $(RDC_VERSION)
Requires.private: $(strip $(RDC_PC_REQUIRES))
Libs: -L$${libdir} -lrdc
Libs.private: -lpthread
Cflags: -I$${includedir}/rdc
endef
export RDC_PC

# $(O)/rel/rdc.pc: librdc where `make` leaves it, for a program built
# against the tree as against an install: `PKG_CONFIG_PATH=$(O)/rel
# pkg-config --cflags --libs rdc` names librdc.a, every library this
# build links into it, and the headers as make install lays them out.
define RDC_PC_BUILD
libdir=$(abspath $(O))/rel
includedir=$(abspath $(HDR_DIR))

Name: rdc
Description: librdc, the host library of the RDC-1 simulated raster display controller (build tree, librdc.a)
Version: $(RDC_VERSION)
Requires: $(strip $(RDC_PC_REQUIRES))
Libs: $${libdir}/librdc.a -lpthread
Cflags: -I$${includedir}
endef
export RDC_PC_BUILD

$(O)/rel/rdc.pc: $(HDR_DIR)/.stamp Makefile
	@mkdir -p $(dir $@)
	printf '%s\n' "$$RDC_PC_BUILD" >$@

# The Python package python/rdc (docs/python.md), for PYTHON, Debian's
# interpreter unless told, in PYTHONDIR: the dist-packages directory
# Debian's python3 reads for PREFIX /usr or /usr/local, else
# PREFIX/lib/python3.X/site-packages (scripts/python-sitedir.py).  The
# constants it reads from the headers in the tree go into its
# _constants.py; its dist-info's pytest11 entry point has pytest load
# the plugin.  Without PYTHON, make install leaves it out and says so.
PYTHON ?= /usr/bin/python3
PYTHONDIR ?= $(eval PYTHONDIR := $(shell $(PYTHON) scripts/python-sitedir.py \
	'$(PREFIX)' 2>/dev/null))$(PYTHONDIR)
PY_SRCS := $(sort $(wildcard python/rdc/*.py))
PY_DISTINFO = $(PYTHONDIR)/rdc-$(RDC_VERSION).dist-info
define RDC_PY_METADATA
Metadata-Version: 2.1
Name: rdc
Version: $(RDC_VERSION)
Summary: librdc, the host library of the RDC-1 simulated raster display controller
License: LGPL-2.1-or-later
endef
export RDC_PY_METADATA
define RDC_PY_ENTRY_POINTS
[pytest11]
rdc.pytest_plugin = rdc.pytest_plugin
endef
export RDC_PY_ENTRY_POINTS

# Where make install puts files; make uninstall removes those of them,
# and their parents, that make install created, when they are empty.
RDC_DEST_DIRS = $(BINDIR) $(LIBDIR) $(INCLUDEDIR)/rdc $(PKGCONFIGDIR) \
	$(sort $(foreach f,$(INSTALL_MAN),$(MANDIR)/man$(subst .,,$(suffix $(f))))) \
	$(if $(INSTALL_BASHCOMP),$(BASHCOMPDIR)) \
	$(if $(INSTALL_UNITS),$(SYSTEMDUSERUNITDIR)) \
	$(if $(INSTALL_UDEV),$(UDEVRULESDIR)) \
	$(if $(PYTHONDIR),$(PYTHONDIR)/rdc $(PY_DISTINFO))

install: all shared
	@set -e; mkdir -p $(O); for d in $(RDC_DEST_DIRS); do \
		d=$(DESTDIR)$$d; p=$$d; new=; \
		while [ ! -d "$$p" ]; do new="$$p $$new"; p=$$(dirname "$$p"); done; \
		echo "$(INSTALL) -d $$d"; $(INSTALL) -d "$$d"; \
		for n in $$new; do echo "$$n" >>$(RDC_INSTALL_DIRS); done; done
	$(INSTALL_PROGRAM) $(O)/rel/dyn/rdcctl $(O)/rel/dyn/rdcd \
		$(DESTDIR)$(BINDIR)/
	$(INSTALL_DATA) $(O)/rel/$(RDC_SO_FILE) $(O)/rel/librdc.a \
		$(DESTDIR)$(LIBDIR)/
	ln -sf $(RDC_SO_FILE) $(DESTDIR)$(LIBDIR)/$(RDC_SO_NAME)
	ln -sf $(RDC_SO_NAME) $(DESTDIR)$(LIBDIR)/librdc.so
	$(INSTALL_DATA) $(HDR_DIR)/*.h $(DESTDIR)$(INCLUDEDIR)/rdc/
	printf '%s\n' "$$RDC_PC" >$(DESTDIR)$(PKGCONFIGDIR)/rdc.pc
	@set -e; for f in $(INSTALL_MAN); do \
		d=$(DESTDIR)$(MANDIR)/man$${f##*.}; $(INSTALL) -d $$d; \
		echo "$(INSTALL_DATA) $$f $$d/"; $(INSTALL_DATA) $$f $$d/; done
	@set -e; for p in "$(INSTALL_BASHCOMP):$(BASHCOMPDIR)" \
		"$(INSTALL_UNITS):$(SYSTEMDUSERUNITDIR)" \
		"$(INSTALL_UDEV):$(UDEVRULESDIR)"; do \
		files=$${p%%:*}; dir=$(DESTDIR)$${p##*:}; \
		[ -n "$$files" ] || continue; $(INSTALL) -d $$dir; \
		echo "$(INSTALL_DATA) $$files $$dir/"; \
		$(INSTALL_DATA) $$files $$dir/; done
	@set -e; if [ -z "$(PYTHONDIR)" ]; then echo "install: $(PYTHON)" \
		"not found: the Python package rdc left out"; exit 0; fi; \
	d=$(DESTDIR)$(PYTHONDIR); \
	echo "$(INSTALL_DATA) $(PY_SRCS) $$d/rdc/"; \
	$(INSTALL_DATA) $(PY_SRCS) $$d/rdc/; \
	echo "$(PYTHON) python/rdc/_headers.py ... >$$d/rdc/_constants.py"; \
	$(PYTHON) python/rdc/_headers.py hw-sim/rdc_regs.h \
		hw-sim/rdc_image.h userspace/include/rdc.h \
		>$$d/rdc/_constants.py; \
	chmod 644 $$d/rdc/_constants.py; \
	echo "$(DESTDIR)$(PY_DISTINFO)/METADATA, entry_points.txt"; \
	printf '%s\n' "$$RDC_PY_METADATA" >$(DESTDIR)$(PY_DISTINFO)/METADATA; \
	printf '%s\n' "$$RDC_PY_ENTRY_POINTS" \
		>$(DESTDIR)$(PY_DISTINFO)/entry_points.txt; \
	echo rdc >$(DESTDIR)$(PY_DISTINFO)/top_level.txt
	@if [ -z "$(DESTDIR)" ] && [ -n "$(RDC_LIBDIR_LOADER)" ]; then \
		echo "$(LDCONFIG)"; $(LDCONFIG) || { echo "install:" \
		"$(LDCONFIG) failed: until it runs as root, programs do not" \
		"find $(RDC_SO_NAME) in $(LIBDIR)"; exit 1; }; fi

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/rdcctl $(DESTDIR)$(BINDIR)/rdcd \
		$(DESTDIR)$(LIBDIR)/$(RDC_SO_FILE) \
		$(DESTDIR)$(LIBDIR)/$(RDC_SO_NAME) \
		$(DESTDIR)$(LIBDIR)/librdc.so $(DESTDIR)$(LIBDIR)/librdc.a \
		$(DESTDIR)$(PKGCONFIGDIR)/rdc.pc
	rm -rf $(DESTDIR)$(INCLUDEDIR)/rdc
	$(if $(PYTHONDIR),rm -rf $(DESTDIR)$(PYTHONDIR)/rdc $(DESTDIR)$(PY_DISTINFO))
	@set -e; for f in $(notdir $(INSTALL_MAN)); do \
		rm -f $(DESTDIR)$(MANDIR)/man$${f##*.}/$$f; done; \
	for f in $(notdir $(INSTALL_BASHCOMP)); do \
		rm -f $(DESTDIR)$(BASHCOMPDIR)/$$f; done; \
	for f in $(notdir $(INSTALL_UNITS)); do \
		rm -f $(DESTDIR)$(SYSTEMDUSERUNITDIR)/$$f; done; \
	for f in $(notdir $(INSTALL_UDEV)); do \
		rm -f $(DESTDIR)$(UDEVRULESDIR)/$$f; done
	@[ -f $(RDC_INSTALL_DIRS) ] || exit 0; \
	for d in $(RDC_DEST_DIRS); do d=$(DESTDIR)$$d; \
		while [ "$$d" != / ] && [ "$$d" != . ]; do \
			if grep -qxF "$$d" $(RDC_INSTALL_DIRS) && \
				rmdir "$$d" 2>/dev/null; then echo "rmdir $$d"; fi; \
			d=$$(dirname "$$d"); done; done; \
	while read -r d; do [ ! -d "$$d" ] || echo "$$d"; done \
		<$(RDC_INSTALL_DIRS) >$(RDC_INSTALL_DIRS).tmp; \
	mv $(RDC_INSTALL_DIRS).tmp $(RDC_INSTALL_DIRS)

# The Python bindings' and pytest plugin's tests on this build, from the
# tree (tests/python/run.sh; make check runs them in tests/run.sh).
python-check: shared $(O)/rel/rdcctl $(O)/rel/rdcd
	@tests/python/run.sh $(O)

# Install into a scratch directory and build examples/hello.c against it
# with pkg-config alone (tests/install/run.sh says what it checks).
install-check: all shared
	@tests/install/run.sh $(O)

# The Debian packages (debian/): dpkg-buildpackage -us -uc -b in a copy
# of the tree in $(O)-debs, lintian, and the packaged rdcctl, rdcd and
# rdc.pc tried from the unpacked packages (tests/pkg/debs.sh): a whole
# build, 42 to 46 s on a quiet 2-core machine.  make check runs it and
# gives the VM test rdcfb-dkms the rdcfb-dkms package to install.
debs:
	@scripts/deps.sh --debs
	@tests/pkg/debs.sh $(O)

demo: deps
	$(MAKE) all
	$(O)/rel/rdcctl run examples/demo.rdl -o demo.png

check test: deps
	$(MAKE) format-check
	$(MAKE) licence-check
	$(MAKE) $(TEST_BINS) $(O)/san/rdcctl $(O)/san/rdcd freestanding $(VM_BINS)
	$(MAKE) mcu-test
	$(MAKE) fuzz
	$(MAKE) shared
	$(MAKE) debs
	@vm=0; RDC_DKMS_DEB=$$(ls $(abspath $(O))-debs/rdcfb-dkms_*.deb 2>/dev/null | \
		head -n 1) tests/vm/run.sh --auto --all-kernels $(O) || vm=1; \
	tests/install/run.sh $(O) || vm=1; \
	tests/run.sh $(O)/san && exit $$vm

# rdc-bench's parts: bench/parts.h lists what each one does.
RDC_BENCH_SRCS := bench/rdc_bench.c bench/common.c bench/input.c bench/pixels.c \
	bench/draw.c bench/limits.c bench/measure.c bench/report.c \
	bench/targets.c bench/growth.c
$(O)/rel/rdc-bench: $(patsubst %.c,$(O)/rel/%.o,$(RDC_BENCH_SRCS)) \
		$(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

# The workloads defined in bench/README.md, then rdcd's and the
# v4l2 sink's figures; BENCH_ARGS="-w fill -r 5" runs only the
# workloads it names (make bench-net, bench-sink: the rest alone).
BENCH_REST := $(O)/rel/sink-bench $(O)/rel/net_bench $(O)/rel/rdcd \
	$(O)/rel/stream-bench
define BENCH_RUN_REST
	@if [ -n '$(BENCH_ARGS)' ]; then echo "bench: BENCH_ARGS" \
		"names workloads: rdcd's, the sink's and the stream's" \
		"figures left out (make bench-net, make bench-sink)"; \
	else set -e; \
	echo "== rdcd over a UNIX socket =="; \
	echo "$(O)/rel/net_bench $(O)/rel/rdcd"; \
	$(O)/rel/net_bench $(O)/rel/rdcd; \
	echo "== v4l2 sink conversion per frame =="; \
	echo "$(O)/rel/sink-bench"; $(O)/rel/sink-bench; \
	echo "== rdcctl stream of the demo at 1920x1080 into v4l2 =="; \
	echo "$(O)/rel/stream-bench"; $(O)/rel/stream-bench; fi
endef
bench: $(O)/rel/rdc-bench $(if $(BENCH_ARGS),,$(BENCH_REST))
	$(O)/rel/rdc-bench $(BENCH_ARGS)
	$(BENCH_RUN_REST)

# The same with the peer libraries (pixman, cairo, SDL2_gfx) whose
# pkg-config files are found; scripts/deps.sh --peers installs them.
BENCH_PEERS := pixman-1:PIXMAN:pixman cairo:CAIRO:cairo \
	SDL2_gfx:SDL2_GFX:sdl2_gfx
$(O)/rel/rdc-bench-peers: $(RDC_BENCH_SRCS) bench/parts.h bench/bench.h \
		bench/peer_*.c $(O)/rel/librdc.a
	@set -e; defs=; srcs=; pkgs=; \
	for p in $(BENCH_PEERS); do \
		pc=$${p%%:*}; rest=$${p#*:}; \
		if $(PKG_CONFIG) --exists $$pc 2>/dev/null; then \
			defs="$$defs -DBENCH_HAVE_$${rest%%:*}"; \
			srcs="$$srcs bench/peer_$${rest#*:}.c"; pkgs="$$pkgs $$pc"; \
		else echo "bench: $$pc not found: that peer is left out"; fi; \
	done; \
	cflags=; libs=; if [ -n "$$pkgs" ]; then \
		cflags=$$($(PKG_CONFIG) --cflags $$pkgs); \
		libs=$$($(PKG_CONFIG) --libs $$pkgs); fi; \
	cmd="$(CC) $(REL_CFLAGS) $$defs $$cflags $(RDC_BENCH_SRCS) $$srcs"; \
	cmd="$$cmd $(O)/rel/librdc.a $(LIBS) $$libs -lm -o $@"; \
	echo "$$cmd"; $$cmd

bench-peers:
	@scripts/deps.sh --peers || \
		echo "bench: going on with the peers that are installed"
	$(MAKE) $(O)/rel/rdc-bench-peers $(if $(BENCH_ARGS),,$(BENCH_REST))
	$(O)/rel/rdc-bench-peers --peers $(BENCH_ARGS)
	$(BENCH_RUN_REST)

$(O)/rel/sink-bench: $(O)/rel/bench/sink_bench.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

# rdcctl stream's own loop into the v4l2 sink, a pipe for the device.
$(O)/rel/bench/stream_bench.o: REL_CFLAGS += -Iuserspace/sink
$(O)/rel/bench/stream_bench.o: REL_CFLAGS += -Iuserspace/rdcctl
$(O)/rel/stream-bench: $(O)/rel/bench/stream_bench.o \
		$(O)/rel/userspace/rdcctl/stream.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

# rdcd's figures (JSON lines): submit throughput, register-read round
# trip, 1024x768 frame subscription unpaced.
$(O)/rel/net_bench: $(O)/rel/bench/net_bench.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

bench-net: $(O)/rel/net_bench $(O)/rel/rdcd
	$(O)/rel/net_bench $(O)/rel/rdcd

# An idle paced rdcd at 1024x768@60 watched for 60 s, with no frame
# consumer and with one (bench/README.md "An idle rdcd").
bench-idle: $(O)/rel/net_bench $(O)/rel/rdcd
	$(O)/rel/net_bench --idle 60 $(O)/rel/rdcd

# The same figures over USB against the UNIX socket, in the VM (an RDC-1
# gadget on dummy_hcd): tests/vm/tests/usb-bench.sh prints them.
bench-usb: $(O)/rel/net_bench $(O)/rel/rdcd
	RDC_VM_TESTS=usb-bench tests/vm/run.sh $(O)

# rdcctl stream's pipeline at 1920x1080 into v4l2loopback, in the VM:
# tests/vm/tests/stream-1080-bench.sh prints the figures.
bench-stream-vm: $(O)/rel/stream-bench $(O)/rel/rdcctl $(O)/rel/v4l2_read
	RDC_VM_TESTS=stream-1080-bench tests/vm/run.sh $(O)

# libFuzzer targets (needs clang; tests/fuzz/README.md):
#   fuzz_proto   the wire protocol's codec (userspace/lib/proto.c)
#   fuzz_usb     the host side of the USB framing (usb_host.c)
#   fuzz_rdcd    rdcd's request handling, several clients (rdcd/serve.c)
#   fuzz_script  the .rdl interpreter on a sim: device (lib/script*.c)
#   fuzz_web     the web sink's HTTP and WebSocket parsers (sink/web_proto.c)
#   fuzz_trace   trace replay (lib/replay.c: rdcctl replay, why, diff)
#   fuzz_decode  DECODE's image streams, every codec (firmware-model/decode.c)
# `make fuzz` is the short run `make check` does (fuzz_proto, fuzz_usb and
# fuzz_web a million inputs each, fuzz_rdcd, fuzz_script, fuzz_trace and
# fuzz_decode FUZZ_TIME
# seconds each from their
# seeds in tests/fuzz/seeds/); `make fuzz-long` gives each target
# FUZZ_LONG_TIME seconds (150: ten minutes in all) and keeps its corpus in
# $(FUZZ_DIR)/corpus-NAME; `make fuzz-cov` runs the seeds and those corpora
# once through coverage builds and prints line coverage per file.
FUZZ_CC ?= clang
FUZZ_DIR ?= $(O)/fuzz
FUZZ_INSTR ?= -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_CFLAGS := -std=gnu11 -g -O1 -fsanitize=fuzzer $(FUZZ_INSTR) $(INC) \
	$(PRIV_INC) -D_GNU_SOURCE
FUZZ_RUNS ?= 1000000
FUZZ_TIME ?= 15
FUZZ_LONG_TIME ?= 150
FUZZ_TARGETS := proto usb rdcd script web trace decode
FUZZ_BINS := $(patsubst %,$(FUZZ_DIR)/fuzz_%,$(FUZZ_TARGETS))
$(FUZZ_DIR)/fuzz_proto: tests/fuzz/fuzz_proto.c userspace/lib/proto.c \
		userspace/include/rdc_proto.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) tests/fuzz/fuzz_proto.c userspace/lib/proto.c -o $@

# The host side of the USB framing: bulk chunks and interrupt transfers
# from a device into whole messages (userspace/lib/usb_host.c).
# fuzz_web: the web sink's HTTP request and WebSocket frame parsers.
$(FUZZ_DIR)/fuzz_web: tests/fuzz/fuzz_web.c userspace/sink/web_proto.c \
		userspace/sink/web_proto.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Iuserspace/sink tests/fuzz/fuzz_web.c \
		userspace/sink/web_proto.c -o $@
$(FUZZ_DIR)/obj/userspace/sink/web_page.o: $(WEB_PAGE)

$(FUZZ_DIR)/fuzz_usb: tests/fuzz/fuzz_usb.c userspace/lib/usb_host.c \
		userspace/lib/usb_host.h userspace/lib/proto.c \
		userspace/include/rdc_proto.h userspace/include/rdc_usb.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) tests/fuzz/fuzz_usb.c userspace/lib/usb_host.c \
		userspace/lib/proto.c -o $@

# fuzz_rdcd and fuzz_script run on the whole of librdc and rdcd's objects
# but rdcd.c (main and the poll loop: the target turns the loop itself),
# compiled once more with the fuzzer's instrumentation.  Some library
# calls are wrapped at link time (--wrap) to bound the work per input
# (waits in the simulator, `step`) and to keep `screenshot` from writing
# files: the targets' comments say which and why.
FUZZ_LIB_CFLAGS := -std=gnu11 -g -O1 -fsanitize=fuzzer-no-link $(FUZZ_INSTR) \
	$(INC) $(PRIV_INC) -D_GNU_SOURCE $(VNC_CFLAGS) $(USB_CFLAGS) \
	$(GPIOD_CFLAGS)
FUZZ_LIB_OBJS := $(patsubst %.c,$(FUZZ_DIR)/obj/%.o,$(CORE_SRCS) $(LIB_SRCS))
FUZZ_RDCD_OBJS := $(patsubst %.c,$(FUZZ_DIR)/obj/%.o,\
	$(filter-out userspace/rdcd/rdcd.c,$(RDCD_SRCS)))
$(FUZZ_DIR)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_LIB_CFLAGS) -MMD -MP -c $< -o $@
$(FUZZ_DIR)/obj/tests/fuzz/%.o: tests/fuzz/%.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_LIB_CFLAGS) $(WARN) -Iuserspace/rdcd -MMD -MP -c $< -o $@
$(FUZZ_DIR)/librdc.a: $(FUZZ_LIB_OBJS)
	@rm -f $@
	ar rcs $@ $^
$(FUZZ_DIR)/librdcd.a: $(FUZZ_RDCD_OBJS)
	@rm -f $@
	ar rcs $@ $^
FUZZ_ALLOC := $(FUZZ_DIR)/obj/tests/fuzz/fuzz_alloc.o
FUZZ_WRAP_ALLOC := -Wl,--wrap=calloc,--wrap=free
$(FUZZ_DIR)/fuzz_rdcd: $(FUZZ_DIR)/obj/tests/fuzz/fuzz_rdcd.o $(FUZZ_ALLOC) \
		$(FUZZ_DIR)/librdcd.a $(FUZZ_DIR)/librdc.a
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_WRAP_ALLOC) \
		-Wl,--wrap=rdc_hw_wait_begin $^ $(LIBS) -o $@
$(FUZZ_DIR)/fuzz_script: $(FUZZ_DIR)/obj/tests/fuzz/fuzz_script.o \
		$(FUZZ_ALLOC) $(FUZZ_DIR)/librdc.a
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_WRAP_ALLOC) \
		-Wl,--wrap=rdc_png_write,--wrap=rdc_sim_step \
		-Wl,--wrap=rdc_sim_run_until,--wrap=rdc_hw_wait_begin \
		-Wl,--wrap=fopen $^ $(LIBS) -o $@
$(FUZZ_DIR)/fuzz_trace: $(FUZZ_DIR)/obj/tests/fuzz/fuzz_trace.o \
		$(FUZZ_ALLOC) $(FUZZ_DIR)/librdc.a
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_WRAP_ALLOC) \
		-Wl,--wrap=rdc_hw_run_until,--wrap=rdc_hw_wait_begin \
		-Wl,--wrap=rdc_hw_set_frame_fn $^ $(LIBS) -o $@

# fuzz_decode: DECODE on the chip core alone (hw-sim and the DP).
$(FUZZ_DIR)/fuzz_decode: $(FUZZ_DIR)/obj/tests/fuzz/fuzz_decode.o \
		$(FUZZ_DIR)/librdc.a
	$(FUZZ_CC) $(FUZZ_CFLAGS) $^ $(LIBS) -o $@

fuzz-bins: $(FUZZ_BINS)

# A target's seed directories, in the shell variable seeds (t: the target):
# fuzz_script also starts from every .rdl of examples/ and the golden
# scenes (read only: libFuzzer writes to the first directory it is given).
FUZZ_SEEDS = case $$t in \
	rdcd) seeds=tests/fuzz/seeds/rdcd;; \
	script) seeds="tests/fuzz/seeds/script examples tests/golden/scenes";; \
	trace) seeds=tests/fuzz/seeds/trace;; \
	decode) seeds=tests/fuzz/seeds/decode;; \
	*) seeds=;; esac

# fuzz_rdcd, fuzz_script and fuzz_trace start from their seeds each time (a fresh
# $(FUZZ_DIR)/short-NAME, so a run does not depend on the last one).
fuzz: $(FUZZ_BINS)
	$(FUZZ_DIR)/fuzz_proto -runs=$(FUZZ_RUNS) -max_len=65536 -seed=1
	$(FUZZ_DIR)/fuzz_usb -runs=$(FUZZ_RUNS) -max_len=65536 -seed=1
	$(FUZZ_DIR)/fuzz_web -runs=$(FUZZ_RUNS) -max_len=16384 -seed=1 \
		-dict=tests/fuzz/web.dict
	@for t in rdcd script trace decode; do \
		rm -rf $(FUZZ_DIR)/short-$$t && mkdir -p $(FUZZ_DIR)/short-$$t; \
		dict=; [ -f tests/fuzz/$$t.dict ] && dict=-dict=tests/fuzz/$$t.dict; \
		cmd="$(FUZZ_DIR)/fuzz_$$t -max_total_time=$(FUZZ_TIME) -seed=1"; \
		cmd="$$cmd -timeout=60 -print_final_stats=1 $$dict"; \
		$(FUZZ_SEEDS); cmd="$$cmd $(FUZZ_DIR)/short-$$t $$seeds"; \
		echo "$$cmd (log: $(FUZZ_DIR)/short-$$t.log)"; \
		if ! $$cmd >$(FUZZ_DIR)/short-$$t.log 2>&1; then \
			tail -n 80 $(FUZZ_DIR)/short-$$t.log; exit 1; fi; \
		grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss)' \
			$(FUZZ_DIR)/short-$$t.log; \
	done

fuzz-long: $(FUZZ_BINS)
	@for t in $(FUZZ_TARGETS); do \
		mkdir -p $(FUZZ_DIR)/corpus-$$t; \
		$(FUZZ_SEEDS); \
		dict=; [ -f tests/fuzz/$$t.dict ] && dict=-dict=tests/fuzz/$$t.dict; \
		echo "$(FUZZ_DIR)/fuzz_$$t -max_total_time=$(FUZZ_LONG_TIME)" \
			"-max_len=65536 $$dict $(FUZZ_DIR)/corpus-$$t $$seeds"; \
		$(FUZZ_DIR)/fuzz_$$t -max_total_time=$(FUZZ_LONG_TIME) \
			-max_len=65536 -timeout=60 $$dict -print_final_stats=1 \
			$(FUZZ_DIR)/corpus-$$t $$seeds || exit 1; \
	done

# Line coverage per file of what the seeds and fuzz-long's corpora reach:
# the targets built with clang's source-based coverage in $(O)/fuzz-cov,
# each run once over its inputs (-runs=0), llvm-cov's report per file.
LLVM_PROFDATA ?= llvm-profdata-14
LLVM_COV ?= llvm-cov-14
FUZZ_COV_DIR := $(O)/fuzz-cov
FUZZ_COV_FILES := userspace/lib/proto.c userspace/lib/usb_host.c \
	userspace/rdcd/serve.c userspace/rdcd/dispatch.c \
	userspace/rdcd/pending.c userspace/rdcd/frames.c \
	userspace/rdcd/hist.c userspace/rdcd/out.c userspace/lib/record.c \
	userspace/lib/replay.c \
	$(sort $(wildcard userspace/lib/script*.c))
fuzz-cov:
	@command -v $(LLVM_COV) >/dev/null && command -v $(LLVM_PROFDATA) \
		>/dev/null || { echo "fuzz-cov: $(LLVM_COV) or $(LLVM_PROFDATA)" \
		"not found (Debian: apt-get install llvm-14)"; exit 1; }
	$(MAKE) FUZZ_DIR=$(FUZZ_COV_DIR) \
		FUZZ_INSTR="-fprofile-instr-generate -fcoverage-mapping" fuzz-bins
	@set -e; rm -f $(FUZZ_COV_DIR)/*.profraw; objs=; \
	for t in $(FUZZ_TARGETS); do \
		$(FUZZ_SEEDS); \
		ins=; for d in $(FUZZ_DIR)/corpus-$$t $$seeds; do \
			[ -d $$d ] && ins="$$ins $$d"; done; \
		[ -n "$$ins" ] || { echo "fuzz-cov: no inputs for $$t"; continue; }; \
		LLVM_PROFILE_FILE=$(FUZZ_COV_DIR)/$$t.profraw \
			$(FUZZ_COV_DIR)/fuzz_$$t -runs=0 $$ins >/dev/null 2>&1; \
		objs="$${objs:+$$objs -object }$(FUZZ_COV_DIR)/fuzz_$$t"; \
	done; \
	[ -n "$$objs" ] || { echo "fuzz-cov: nothing ran"; exit 1; }; \
	$(LLVM_PROFDATA) merge -sparse $(FUZZ_COV_DIR)/*.profraw \
		-o $(FUZZ_COV_DIR)/all.profdata; \
	$(LLVM_COV) report $$objs -instr-profile=$(FUZZ_COV_DIR)/all.profdata \
		$(FUZZ_COV_FILES)

# The v4l2 sink's conversions against memcpy, per frame.
bench-sink: $(O)/rel/sink-bench
	$(O)/rel/sink-bench

# The VM tests (tests/vm/README.md): Debian's kernel under QEMU runs the
# programs below against v4l2loopback.  `make check` runs them when QEMU
# can run here and skips them, saying why, when it cannot.
VM_BINS := $(O)/rel/rdcctl $(O)/rel/rdcd $(O)/rel/v4l2_read
VM_BINS += $(O)/rel/rdcfb_tool
$(O)/rel/rdcfb_tool: $(O)/rel/tests/vm/rdcfb_tool.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
$(O)/rel/v4l2_read: $(O)/rel/tests/vm/v4l2_read.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
VM_BINS += $(O)/rel/fbdev_ioctl $(O)/rel/rdcfb_fuzz
# frame_check: a compositor's screenshot against the chip's frame
VM_BINS += $(O)/rel/frame_check
$(O)/rel/frame_check: $(O)/rel/tests/vm/frame_check.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
$(O)/rel/fbdev_ioctl: $(O)/rel/tests/vm/fbdev_ioctl.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
$(O)/rel/rdcfb_fuzz: $(O)/rel/tests/vm/rdcfb_fuzz.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
# gpio_te: rdcfb's GPIO lines through libgpiod v2 (rdcfb-gpio skips without)
ifeq ($(HAVE_GPIOD),1)
VM_BINS += $(O)/rel/gpio_te
endif
$(O)/rel/gpio_te: $(O)/rel/tests/vm/gpio_te.o
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
# usb_raw: the USB device side (rdcd's ffs:) checked with libusb alone
ifeq ($(HAVE_USB),1)
VM_BINS += $(O)/rel/usb_raw
endif
$(O)/rel/usb_raw: $(O)/rel/tests/vm/usb_raw.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

# The conformance suite as a VM program: RDC_CONFORM_URI=usb: runs it
# against the RDC-1 on the guest's USB bus (tests/vm/tests/usb-conform.sh).
VM_BINS += $(O)/rel/test_net_conform
$(O)/rel/test_net_conform: $(O)/rel/tests/unit/test_net_conform.o \
		$(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(CMOCKA_LIBS) $(LIBS) -o $@

# usb_tool: long submits, frame subscriptions and interrupt events over
# usb: for tests/vm/tests/usb-*.sh.
# usb-unplug.sh runs the ASan+UBSan build: a leak or a use after free on
# the way out of a vanished device fails it.
VM_BINS += $(O)/rel/usb_tool $(O)/san/usb_tool
$(O)/rel/usb_tool: $(O)/rel/tests/vm/usb_tool.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
$(O)/san/usb_tool: $(O)/san/tests/vm/usb_tool.o $(O)/san/librdc.a
	$(CC) $(SAN_CFLAGS) $^ $(LIBS) -o $@

# drm_pattern: a DRM/KMS client (libdrm) of the udl card the DisplayLink
# personality brings up (tests/vm/tests/udl-*.sh, which skip without it).
# rdcdrm_tool: the client of rdcdrm.ko's card in the rdcdrm VM tests
# (tests/vm/tests/rdcdrm-*.sh, which skip without it).
ifeq ($(HAVE_DRM),1)
VM_BINS += $(O)/rel/rdcdrm_tool
endif
$(O)/rel/rdcdrm_tool: $(O)/rel/tests/vm/rdcdrm_tool.o
	$(CC) $(REL_CFLAGS) $^ $(shell $(PKG_CONFIG) --libs libdrm) -lz -o $@
# kms_conform: KMS conformance of rdcdrm.ko's card (libdrm; run by
# tests/vm/tests/rdcdrm-kms.sh, which skips without it).
ifeq ($(HAVE_DRM),1)
VM_BINS += $(O)/rel/drm_pattern $(O)/rel/kms_conform
endif
$(O)/rel/kms_conform: $(O)/rel/tests/vm/kms_conform.o
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
$(O)/rel/drm_pattern: tests/vm/drm_pattern.c $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) -Iuserspace/rdcd \
		$(shell $(PKG_CONFIG) --cflags libdrm) $^ \
		$(shell $(PKG_CONFIG) --libs libdrm) $(LIBS) -o $@

vm-test: $(VM_BINS)
	@tests/vm/run.sh $(O)

# rdcfb.ko's source as dkms wants it, in $(O)/dkms/rdcfb-VERSION
# (docs/driver.md: dkms add it, then dkms install).
dkms-source:
	@scripts/dkms-source.sh $(O)/dkms $(RDC_VERSION)

$(O)/rel/fill_speed: $(O)/rel/tests/perf/fill_speed.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

speed: $(O)/rel/fill_speed
	$(O)/rel/fill_speed

golden: $(O)/rel/rdcctl
	@tests/golden/regen.sh $(O)/rel/rdcctl $(O)/golden

# The portable core with the compiler's freestanding headers only: no libc.
FREESTANDING_FLAGS := -std=gnu11 $(WARN) -Werror -ffreestanding -nostdinc \
	-isystem $(shell $(CC) -print-file-name=include) -Ihw-sim -Ifirmware-model -O2
freestanding:
	@mkdir -p $(O)/freestanding
	@set -e; for f in $(CORE_SRCS); do \
		$(CC) $(FREESTANDING_FLAGS) -c $$f -o $(O)/freestanding/$$(basename $$f .c).o; \
	done
	@echo "freestanding: $(words $(CORE_SRCS)) core files compiled without libc headers"

# The firmware on a microcontroller (docs/mcu.md): hw-sim/ and
# firmware-model/ built for a Cortex-M3 with arm-none-eabi-gcc and no C
# library, into an image for QEMU's mps2-an385 board that replays every
# golden scene (mcu/gen_scenes turns each into operation words at build
# time) and prints each frame's CRC-32 and cycle counts.  firmware-mcu
# fails if the core calls anything but memcpy/memmove/memset and libgcc's
# integer helpers, if floating point or an allocator is in the image, or
# if the stack has no bound; `make mcu-test` (in `make check`) runs the
# image under QEMU against the host (mcu/check.sh).
MCU_CC ?= arm-none-eabi-gcc
MCU_LD ?= arm-none-eabi-ld
MCU_NM ?= arm-none-eabi-nm
MCU_SIZE ?= arm-none-eabi-size
MCU_QEMU ?= qemu-system-arm
MCU_DIR := $(O)/mcu
MCU_SCENES := $(sort $(wildcard tests/golden/scenes/*.rdl))
MCU_ARCH := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
# -mno-unaligned-access: the compiler makes no unaligned access, so the
# trap the firmware sets (CCR.UNALIGN_TRP) catches the core's own; every
# frame of static size and at most 2 KiB, as the kernel wants.
MCU_CFLAGS = -std=gnu11 $(WARN) -Werror $(MCU_ARCH) -mno-unaligned-access \
	-O2 -g -ffreestanding -nostdinc \
	-isystem $(shell $(MCU_CC) -print-file-name=include) \
	-ffunction-sections -fdata-sections -fno-common -fstack-usage \
	-fcallgraph-info=su -Wstack-usage=2048 -Ihw-sim -Ifirmware-model -Imcu
MCU_CORE_OBJS := $(patsubst %.c,$(MCU_DIR)/%.o,$(CORE_SRCS))
MCU_OBJS := $(MCU_CORE_OBJS) $(MCU_DIR)/mcu_scenes.o \
	$(patsubst %,$(MCU_DIR)/mcu/%.o,replay main startup string)
# What the core may leave to the MCU's runtime: the string functions
# rdc_base.h maps to, libgcc's integer division, shifts and bit counts.
MCU_CORE_EXTERNS := memcpy|memmove|memset|__aeabi_(u?ldivmod|u?idiv|u?idivmod|llsl|llsr|lasr|lmul|u?lcmp)|__(clz|ctz|popcount|ffs|parity|bswap)[sd]i2
MCU_NO_FLOAT := ^__aeabi_([fd]|u?[il]2[fd])|^__(fix|float|extend|trunc)|^__[a-z]+[sdtx]f[0-9]$$|^(malloc|calloc|realloc|free)$$

$(MCU_DIR)/%.o: %.c
	@mkdir -p $(dir $@)
	$(MCU_CC) $(MCU_CFLAGS) -MMD -MP -c $< -o $@
# its loops must not become calls to itself
$(MCU_DIR)/mcu/string.o: MCU_CFLAGS += -fno-tree-loop-distribute-patterns

# gen_scenes reads traces through librdc's private headers; the host
# replay the core's (scene.h).
$(O)/rel/mcu/%.o $(O)/rel/mcu_scenes.o: REL_CFLAGS += -Ifirmware-model
$(O)/rel/mcu/gen_scenes.o: REL_CFLAGS += -Iuserspace/lib
$(O)/rel/gen_scenes: $(O)/rel/mcu/gen_scenes.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@
# the scenes as C (and "name vram" lines for mcu/check.sh)
$(MCU_DIR)/mcu_scenes.c: $(O)/rel/gen_scenes $(MCU_SCENES)
	@mkdir -p $(dir $@)
	$(O)/rel/gen_scenes $@.tmp $(MCU_SCENES) >$(MCU_DIR)/scenes.txt.tmp
	mv $(MCU_DIR)/scenes.txt.tmp $(MCU_DIR)/scenes.txt
	mv $@.tmp $@
$(MCU_DIR)/mcu_scenes.o: $(MCU_DIR)/mcu_scenes.c
	$(MCU_CC) $(MCU_CFLAGS) -g0 -c $< -o $@
$(O)/rel/mcu_scenes.o: $(MCU_DIR)/mcu_scenes.c
	$(CC) $(REL_CFLAGS) -Imcu -g0 -c $< -o $@
# the same replay on the host, built as the rest of rdc is
$(O)/rel/mcu-host: $(O)/rel/mcu/host_main.o $(O)/rel/mcu/replay.o \
		$(O)/rel/mcu_scenes.o $(O)/rel/librdc.a
	$(CC) $(REL_CFLAGS) $^ $(LIBS) -o $@

$(MCU_DIR)/rdc-mcu.elf: $(MCU_OBJS) mcu/mps2.ld
	$(MCU_CC) $(MCU_ARCH) -nostdlib -T mcu/mps2.ld -Wl,--gc-sections \
		-Wl,-Map=$(MCU_DIR)/rdc-mcu.map $(MCU_OBJS) -lgcc -o $@

firmware-mcu: $(MCU_DIR)/rdc-mcu.elf
	@set -e; cd $(MCU_DIR); \
	$(MCU_LD) -r -o core.o $(patsubst $(MCU_DIR)/%,%,$(MCU_CORE_OBJS)); \
	bad=$$($(MCU_NM) -u core.o | awk '{ print $$2 }' | \
		grep -Ev '^($(MCU_CORE_EXTERNS))$$' || true); \
	[ -z "$$bad" ] || { echo "firmware-mcu: the core calls" $$bad \
		"(no C library, floating point or allocation on the MCU)"; \
		exit 1; }; \
	bad=$$($(MCU_NM) rdc-mcu.elf | awk '{ print $$NF }' | \
		grep -E '$(MCU_NO_FLOAT)' || true); \
	[ -z "$$bad" ] || { echo "firmware-mcu: the image has" $$bad \
		"(floating point or an allocator)"; exit 1; }; \
	bad=$$($(MCU_NM) rdc-mcu.elf | awk '{ print $$NF }' | grep -E \
		'^rdc_hw_set_(trace|poll|frame_fn)$$' || true); \
	[ -z "$$bad" ] || { echo "firmware-mcu: $$bad is in the image" \
		"(mcu/stack_bound.awk counts no hook)"; exit 1; }; \
	ci=$$(find . -name '*.ci'); \
	awk -v root=rdc_mcu_reset -f $(CURDIR)/mcu/stack_bound.awk $$ci \
		>stack.txt || { cat stack.txt; exit 1; }; \
	awk -v root=rdc_mcu_fault_report -f $(CURDIR)/mcu/stack_bound.awk $$ci \
		>>stack.txt || { cat stack.txt; exit 1; }; \
	{ $(MCU_SIZE) rdc-mcu.elf; \
	  echo "of which the scenes (mcu_scenes.o):"; \
	  $(MCU_SIZE) mcu_scenes.o | tail -n 1; \
	  echo "the core (hw-sim/, firmware-model/ objects before" \
		"--gc-sections):"; \
	  $(MCU_SIZE) -t $(patsubst $(MCU_DIR)/%,%,$(MCU_CORE_OBJS)) | \
		tail -n 1; cat stack.txt; } >figures.txt; \
	cat figures.txt
	@echo "firmware-mcu: $(MCU_DIR)/rdc-mcu.elf (qemu-system-arm -M mps2-an385)"

mcu-test:
	@command -v $(MCU_CC) >/dev/null && command -v $(MCU_QEMU) >/dev/null || \
		{ echo "mcu-test: skipped: $(MCU_CC) or $(MCU_QEMU) not found" \
		"(Debian: gcc-arm-none-eabi qemu-system-arm; make deps)"; \
		exit 0; }; \
	$(MAKE) firmware-mcu $(O)/rel/mcu-host $(O)/rel/rdcctl && \
	MCU_QEMU=$(MCU_QEMU) mcu/check.sh $(MCU_DIR)/rdc-mcu.elf \
		$(O)/rel/mcu-host $(O)/rel/rdcctl $(MCU_DIR)/scenes.txt \
		tests/golden/scenes $(MCU_DIR)/check

# rdcfb.ko and rdcdrm.ko (driver/, docs/driver.md) against the installed
# linux-headers-amd64's kernel, or KDIR=<kernel build dir>.  Kbuild runs in
# $(O)/kmod, a tree of links to the sources, so no object lands beside
# them.  The outer make's variables (O=, -j) mean other things to Kbuild.
KVER ?= $(shell dpkg-query -W -f='$${Depends}' linux-headers-amd64 2>/dev/null | \
	sed -n 's/^linux-headers-\([^ ,]*\).*/\1/p')
KDIR ?= /lib/modules/$(KVER)/build
KMOD_DIR := $(abspath $(O))/kmod
module:
	@test -f "$(KDIR)/Makefile" || { echo "module: no kernel build directory" \
		"'$(KDIR)' (install linux-headers-amd64, or give KDIR=)"; exit 1; }
	@set -e; for d in hw-sim firmware-model driver; do \
		mkdir -p $(KMOD_DIR)/$$d; \
		ln -sf $(CURDIR)/$$d/*.[ch] $(KMOD_DIR)/$$d/; done; \
	find $(KMOD_DIR) -xtype l -delete; ln -sf $(CURDIR)/Kbuild $(KMOD_DIR)/Kbuild
	env -u MAKEFLAGS -u MAKEOVERRIDES -u MFLAGS -u MAKELEVEL \
		$(MAKE) -C $(KDIR) M=$(KMOD_DIR) modules
	@echo "module: $(KMOD_DIR)/rdcfb.ko $(KMOD_DIR)/rdcdrm.ko"

module-clean:
	rm -rf $(KMOD_DIR)

# checkpatch.pl over driver/ and the core the module compiles.  Debian
# ships it in linux-source-6.1, not in the headers: extracted from there
# once, or CHECKPATCH= names one.
CHECKPATCH ?= $(O)/checkpatch/scripts/checkpatch.pl
checkpatch:
	@test -f $(CHECKPATCH) || { \
		tar=$$(ls /usr/src/linux-source-*.tar.xz 2>/dev/null | tail -n 1); \
		test -n "$$tar" || { echo "checkpatch: apt-get install" \
			"linux-source-6.1, or give CHECKPATCH="; exit 1; }; \
		mkdir -p $(O)/checkpatch; \
		tar -xJf $$tar -C $(O)/checkpatch --strip-components=1 \
			--wildcards '*/scripts/checkpatch.pl' \
			'*/scripts/spelling.txt' '*/scripts/const_structs.checkpatch'; }
	perl $(CHECKPATCH) --no-tree --terse --show-types -f Kbuild \
		$(filter-out driver/rdcfb_compat.h driver/rdcdrm_compat.h,$(wildcard driver/*.[ch])) \
		$(filter-out hw-sim/rdc_base.h,$(wildcard \
		hw-sim/*.[ch] firmware-model/*.[ch]))
	@# the kernel versions the module builds on are told apart here
	perl $(CHECKPATCH) --no-tree --terse --show-types -f \
		--ignore LINUX_VERSION_CODE,CONSTANT_COMPARISON \
		driver/rdcfb_compat.h driver/rdcdrm_compat.h
	@# the user-space branch spells out what the kernel's headers give
	perl $(CHECKPATCH) --no-tree --terse --show-types -f \
		--ignore PREFER_DEFINED_ATTRIBUTE_MACRO,COMPLEX_MACRO \
		hw-sim/rdc_base.h

# The layout of every C file is .clang-format's (see its comment).  Other
# clang-format versions than Debian 12's 14 lay some constructs out
# differently, so the check says it is skipped with another version.
FORMAT_FILES = $(shell git ls-files '*.c' '*.h' 2>/dev/null || \
	find . -name '*.[ch]' -not -path './build*')
CLANG_FORMAT ?= clang-format
format-check:
	@v=$$($(CLANG_FORMAT) --version 2>/dev/null | \
		sed -n 's/.*version \([0-9]*\)\..*/\1/p'); \
	if [ "$$v" != 14 ]; then \
		echo "format-check: skipped (needs clang-format 14, found" \
			"$${v:-none})"; exit 0; fi; \
	bad=0; for f in $(FORMAT_FILES); do \
		$(CLANG_FORMAT) --dry-run -Werror $$f 2>/dev/null || \
			{ echo "format-check: $$f differs" \
				"(clang-format -i $$f)"; bad=1; }; \
	done; \
	[ $$bad = 0 ] && echo "format-check: $(words $(FORMAT_FILES)) files laid out as .clang-format says"

# Every file's licence and copyright (SPDX lines, .reuse/dep5, LICENSES/):
# README.md, "Licence".
licence-check:
	@if command -v reuse >/dev/null; then reuse lint -q && \
		echo "licence-check: every file names its licence (reuse lint)"; \
	else echo "licence-check: skipped (reuse is not installed)"; fi

format:
	$(CLANG_FORMAT) -i $(FORMAT_FILES)

clean:
	rm -rf $(O) demo.png

-include $(shell find $(O) -name '*.d' 2>/dev/null)
