# SPDX-License-Identifier: GPL-3.0-or-later
# Build time (issue 16 item 8, README "Build time"): the linker and the precompiled headers.
#
# AXISTUNE_LLD: link with LLVM's lld (Debian package lld). GNU ld took 11.7 s to link one GUI test executable
# (108 GUI objects with their debug information), lld 1.8 s; the tree links about 100 executables.
option(AXISTUNE_LLD "link with lld (faster than GNU ld)" ON)
if(AXISTUNE_LLD)
  find_program(AXISTUNE_LLD_PROGRAM ld.lld)
  if(NOT AXISTUNE_LLD_PROGRAM)
    message(FATAL_ERROR "AXISTUNE_LLD is ON but ld.lld was not found: run scripts/deps (Debian package lld) "
                        "or configure with -DAXISTUNE_LLD=OFF")
  endif()
  add_link_options(-fuse-ld=lld)
endif()

# AXISTUNE_SPLIT_DWARF: the debug information stays in one .dwo file beside each object file instead of being
# copied into every executable that links the object. Each GUI test executable links the whole GUI: with its debug
# information inside, each took 296 MB (7 MB without), the build tree 15 GB, and a CI run ran out of disk. gdb
# finds the .dwo files by their path in the build tree (docs/build-time.md "Disk").
# GCC writes name tables (.debug_gnu_pubnames/pubtypes) into every split object, the names of every Qt type once per
# file: they alone took 176 of a GUI test's 222 MB. lld's --gdb-index turns them into one index for gdb and drops
# them (73 MB).
option(AXISTUNE_SPLIT_DWARF "keep debug information in .dwo files, out of the executables" ON)
if(AXISTUNE_SPLIT_DWARF AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options($<$<CONFIG:Debug,RelWithDebInfo>:-gsplit-dwarf>)
  if(AXISTUNE_LLD)
    add_link_options($<$<CONFIG:Debug,RelWithDebInfo>:-Wl,--gdb-index>)
  endif()
endif()

# AXISTUNE_PCH: precompiled headers. Each group of targets with the same compiler flags shares one precompiled
# header, built once by a small "donor" target (axistune_pch_donor) and reused by the others (REUSE_FROM).
# Parsing the standard library, Eigen and nlohmann/json (and Qt, GoogleTest) took a third of a typical file's
# compile time. ccache caches files built with them (sloppiness pch_defines,time_macros, set in the launcher).
# The GUI's headers force-include <QtWidgets>: Qt's keywords signals, slots and emit are macros in every GUI file,
# so a core header the GUI includes must not use them as names. A missing include is hidden by the precompiled
# header: compile touched files once with -DAXISTUNE_PCH=OFF (docs/build-time.md).
option(AXISTUNE_PCH "precompiled headers for the standard library, Eigen, JSON, Qt and GoogleTest" ON)
# Clang stamps a precompiled header with the time its headers were last changed and refuses it after a fresh clone;
# without the stamp ccache can restore it (and the files built with it) from the cache.
if(AXISTUNE_PCH AND CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  add_compile_options("SHELL:-Xclang -fno-pch-timestamp")
endif()

set(AXISTUNE_PCH_CORE
    <algorithm> <array> <charconv> <cmath> <complex> <cstdint> <functional> <limits> <map> <memory>
    <numbers> <optional> <span> <sstream> <string> <string_view> <vector>
    <Eigen/Dense> <nlohmann/json.hpp>)
set(AXISTUNE_PCH_QT <QtWidgets>)

# axistune_pch_donor(<name> HEADERS <h>... LINK <target>... [DEFINITIONS <d>...]): an object library of one
# empty file that builds the precompiled header <h>... with the flags <target>... give.
function(axistune_pch_donor name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "HEADERS;LINK;DEFINITIONS")
  if(NOT AXISTUNE_PCH)
    return()
  endif()
  set(_src "${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp")
  if(NOT EXISTS "${_src}")
    file(WRITE "${_src}" "// the precompiled header's donor: no code\n")
  endif()
  add_library(${name} OBJECT "${_src}")
  target_link_libraries(${name} PRIVATE ${arg_LINK})
  if(arg_DEFINITIONS)
    target_compile_definitions(${name} PRIVATE ${arg_DEFINITIONS})
  endif()
  target_precompile_headers(${name} PRIVATE ${arg_HEADERS})
endfunction()

# axistune_use_pch(<donor> <target>...): the targets reuse the donor's precompiled header.
function(axistune_use_pch donor)
  if(NOT AXISTUNE_PCH)
    return()
  endif()
  foreach(_t ${ARGN})
    target_precompile_headers(${_t} REUSE_FROM ${donor})
  endforeach()
endfunction()

# AXISTUNE_TESTS_FULL_DEBUG_INFO: tests and benches are compiled with line tables only (-g1: backtraces and
# sanitizer reports still name file and line) unless this is ON. Full debug information (-g) took a third of the
# compile time of a typical file; the product (core, app, widgets) keeps it.
option(AXISTUNE_TESTS_FULL_DEBUG_INFO "full debug information (-g) in tests and benches" OFF)
macro(axistune_test_debug_info)
  if(NOT AXISTUNE_TESTS_FULL_DEBUG_INFO AND CMAKE_BUILD_TYPE STREQUAL "RelWithDebInfo")
    add_compile_options(-g1)
  endif()
endmacro()

