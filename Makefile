# mpsdem build — GNU make, non-recursive, incremental (dependency files from -MMD).
#
#   make                 build every library, application (bin/<app>) and test
#   make bin/mpsFluid    build one application and only what it needs
#   make SAN=1           AddressSanitizer + UBSan build in build-san/ (bin-san/)
#   make clean
#
# Layout (doc/design.md §2):
#   src/<lib>/**.c                -> $(BUILD)/lib/lib<lib>.a
#   src/<lib>/Make/options        DEPS = libraries <lib> links against, in link order
#   applications/*/<app>/**.c     -> bin/<app>
#   applications/*/<app>/Make/options  LIBS = libraries, in link order
#   test/unit/<lib>/*.c, test/models/<lib>/*.c  -> $(BUILD)/test/<tier>/<lib>/<name>
#                                    (one executable per file, linked with <lib> and its DEPS)

SAN ?= 0
ifeq ($(SAN),1)
BUILD   := build-san
BINDIR  := bin-san
OPTFLAGS := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined
else
BUILD   := build
BINDIR  := bin
OPTFLAGS := -O2 -march=native -g
endif

CC      ?= gcc
CFLAGS  := -std=c17 -D_GNU_SOURCE -fopenmp -Wall -Wextra $(OPTFLAGS) \
           -Isrc -I/usr/include/suitesparse $(shell pkg-config --cflags libxml-2.0 2>/dev/null)
LDFLAGS := -fopenmp $(filter -fsanitize=%,$(OPTFLAGS))
EXTLIBS := -Wl,--as-needed $(shell pkg-config --libs libxml-2.0 2>/dev/null) \
           -lsundials_arkode -lsundials_nvecserial -lcholmod -lsuitesparseconfig \
           -lpthread -lm
TESTLIBS := $(shell pkg-config --libs cmocka 2>/dev/null)

# The MPI build: distributed runs (`mpirun -np N mpsFluid -parallel`,
# doc/design.md §8) and hypre, whose Debian build is an MPI one (`solver
# hypre;`, and every PPE of a distributed run). Everything is compiled with
# mpicc into separate directories (build-hypre/, bin-hypre/).
#   make MPI=1        (the same as make HYPRE=1)
MPI ?= 0
HYPRE ?= $(MPI)
ifeq ($(HYPRE),1)
BUILD   := $(BUILD)-hypre
BINDIR  := $(BINDIR)-hypre
CC      := mpicc
CFLAGS  += -DMPSDEM_HAVE_HYPRE -DMPSDEM_HAVE_MPI -I/usr/include/hypre
EXTLIBS += -lHYPRE
endif

LIBNAMES := $(notdir $(patsubst %/,%,$(wildcard src/*/)))
APPDIRS  := $(patsubst %/,%,$(wildcard applications/*/*/))
APPS     := $(notdir $(APPDIRS))

all: libs apps tests
libs:  $(foreach l,$(LIBNAMES),$(BUILD)/lib/lib$(l).a)
apps:  $(addprefix $(BINDIR)/,$(APPS))

# ---- git revision, regenerated only when it changes ---------------------------
GITREV := $(shell git rev-parse --short HEAD 2>/dev/null || echo unknown)$(shell \
            git diff --quiet HEAD -- 2>/dev/null || echo -dirty)
$(shell mkdir -p $(BUILD)/gen; f=$(BUILD)/gen/gitrev.c; \
    t='const char *const mpsdem_git_revision = "$(GITREV)";'; \
    [ -f $$f ] && [ "$$(cat $$f)" = "$$t" ] || echo "$$t" > $$f)

$(BUILD)/obj/gen/gitrev.o: $(BUILD)/gen/gitrev.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -c $< -o $@

# ---- libraries ---------------------------------------------------------------
define LIB_template
$(1)_SRCS := $$(shell find src/$(1) -name '*.c' 2>/dev/null)
$(1)_OBJS := $$(patsubst %.c,$(BUILD)/obj/%.o,$$($(1)_SRCS))
DEPS :=
-include src/$(1)/Make/options
$(1)_DEPS := $$(DEPS)
# The object list is a prerequisite too, so that deleting a source file
# rebuilds the archive instead of leaving the stale object in it.
$$(shell mkdir -p $(BUILD)/lib; f=$(BUILD)/lib/lib$(1).objs; \
    t='$$(sort $$($(1)_OBJS))'; [ -f $$$$f ] && [ "$$$$(cat $$$$f)" = "$$$$t" ] || echo "$$$$t" > $$$$f)
$(BUILD)/lib/lib$(1).a: $$($(1)_OBJS) $(BUILD)/lib/lib$(1).objs $(if $(filter core,$(1)),$(BUILD)/obj/gen/gitrev.o)
	@mkdir -p $$(@D)
	@rm -f $$@
	ar rcs $$@ $$(filter %.o,$$^)
endef
$(foreach l,$(LIBNAMES),$(eval $(call LIB_template,$(l))))

libfiles = $(foreach l,$(1),$(BUILD)/lib/lib$(l).a)

# ---- applications ------------------------------------------------------------
define APP_template
$(notdir $(1))_SRCS := $$(shell find $(1) -name '*.c')
$(notdir $(1))_OBJS := $$(patsubst %.c,$(BUILD)/obj/%.o,$$($(notdir $(1))_SRCS))
LIBS :=
-include $(1)/Make/options
$(notdir $(1))_LIBS := $$(LIBS)
$(BINDIR)/$(notdir $(1)): $$($(notdir $(1))_OBJS) $$(call libfiles,$$($(notdir $(1))_LIBS))
	@mkdir -p $$(@D)
	$(CC) $(LDFLAGS) -o $$@ $$^ $(EXTLIBS)
endef
$(foreach a,$(APPDIRS),$(eval $(call APP_template,$(a))))

# ---- tests -------------------------------------------------------------------
TEST_SRCS := $(wildcard test/unit/*/*.c test/models/*/*.c)
TESTS     := $(patsubst test/%.c,$(BUILD)/test/%,$(TEST_SRCS))
tests: $(TESTS)
testlib = $(word 3,$(subst /, ,$(1)))
# A test folder named after a library links it and its DEPS; a folder that
# tests several libraries together (test/unit/coupled) lists them in its
# Make/options (LIBS = ..., in link order).
define TESTDIR_template
LIBS :=
-include $(1)/Make/options
$(1)_LIBS := $$(LIBS)
endef
TESTDIRS := $(sort $(dir $(TEST_SRCS)))
$(foreach d,$(TESTDIRS),$(eval $(call TESTDIR_template,$(patsubst %/,%,$(d)))))
testlibs = $(or $($(patsubst %/,%,$(dir $(1)))_LIBS),$(call testlib,$(1)) $($(call testlib,$(1))_DEPS))
define TEST_template
$(patsubst test/%.c,$(BUILD)/test/%,$(1)): $(patsubst %.c,$(BUILD)/obj/%.o,$(1)) \
        $$(call libfiles,$$(call testlibs,$(1)))
	@mkdir -p $$(@D)
	$(CC) $(LDFLAGS) -o $$@ $$^ $(EXTLIBS) $(TESTLIBS)
endef
$(foreach t,$(TEST_SRCS),$(eval $(call TEST_template,$(t))))

# ---- compile -----------------------------------------------------------------
$(BUILD)/obj/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -MMD -MP -c $< -o $@

# The DEM pair kernel is vectorised (#pragma omp simd, dem_forces_fast.c):
# no errno from sqrt, and values may be computed before the select that
# discards them (sqrt, division of a lane not sliding, a wall candidate out
# of contact). Neither changes
# a result: the flags only drop errno and the floating-point exception
# flags, which nothing reads.
$(BUILD)/obj/src/dem/dem_forces_fast.o: CFLAGS += -fno-math-errno -fno-trapping-math

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)

clean:
	rm -rf build build-san bin bin-san build-hypre build-san-hypre bin-hypre bin-san-hypre

.PHONY: all libs apps tests clean
.DELETE_ON_ERROR:
