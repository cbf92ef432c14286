# SPDX-License-Identifier: GPL-3.0-or-later
# Issue 16: no amplitude, current or speed limit of the simulator is referenced outside the simulator and
# its server. Everything else asks the drive (Drive::limits, Drive::planTest; docs/drive-seam.md).
# Fails when one of the simulator's limit constants (core/device/SimulatedDriveLimits.h) appears in a
# source file of core/, app/, widgets/, bench/ or tests/ other than the simulated drive, its Modbus
# server and the circle check they share.
set(_names kMaxFrfAmplitudePct kMaxCurrentStepFraction kMaxCurrentStepS kMaxCurrentStepSpeedRadS
           kMaxMotorSpeedRadS kCurrentStepHoldS kMaxTestDurationS kTravelWindowM kScopeMaxChannels
           kScopeMaxDivider kScopeMaxValues kScopeRingValues)
set(_allowed "/core/device/SimulatedDrive[A-Za-z]*\\.(h|cpp)$" "/core/device/SimDriveServer[A-Za-z]*\\.(h|cpp)$"
             "/core/device/CircleDriveTest\\.h$" "/core/sim/")
file(GLOB_RECURSE _files ${ROOT}/core/*.h ${ROOT}/core/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp ${ROOT}/widgets/*.h
     ${ROOT}/widgets/*.cpp ${ROOT}/bench/*.h ${ROOT}/bench/*.cpp ${ROOT}/tests/*.h ${ROOT}/tests/*.cpp)
set(_bad 0)
set(_checked 0)
foreach(_f ${_files})
  set(_skip 0)
  foreach(_a IN LISTS _allowed)
    if(_f MATCHES "${_a}")
      set(_skip 1)
    endif()
  endforeach()
  if(_skip)
    continue()
  endif()
  math(EXPR _checked "${_checked} + 1")
  # One list element per line: ';' would split a line into list elements, so it is masked first.
  file(READ ${_f} _text)
  string(REPLACE ";" "<semicolon>" _text "${_text}")
  string(REPLACE "\n" ";" _lines "${_text}")
  set(_n 0)
  foreach(_l IN LISTS _lines)
    math(EXPR _n "${_n} + 1")
    foreach(_name IN LISTS _names)
      if(_l MATCHES "(^|[^A-Za-z0-9_])${_name}([^A-Za-z0-9_]|$)")
        message(SEVERE_WARNING "${_f}:${_n}: the simulator's limit ${_name} outside the simulator: ${_l}")
        set(_bad 1)
      endif()
    endforeach()
  endforeach()
endforeach()
if(_checked LESS 100)
  message(FATAL_ERROR "only ${_checked} files checked under ${ROOT}: the scan found too few sources")
endif()
if(_bad)
  message(FATAL_ERROR "ask the drive for its limits and plans (Drive::limits, Drive::planTest)")
endif()
message(STATUS "the simulator's limits stay in the simulator (${_checked} files checked)")
