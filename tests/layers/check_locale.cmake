# SPDX-License-Identifier: GPL-3.0-or-later
# Fails when core/, app/ or widgets/ use a C library or iostream number conversion that follows the
# locale (docs/formats.md "Numbers"): atof/strtod/stod & co., printf-family calls with a
# floating-point conversion, ostream precision settings. core/model/Number.h is the way to do it.
file(GLOB_RECURSE _files ${ROOT}/core/*.h ${ROOT}/core/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp
     ${ROOT}/widgets/*.h ${ROOT}/widgets/*.cpp)
set(_bad 0)
foreach(_f ${_files})
  file(STRINGS ${_f} _lines)
  set(_n 0)
  foreach(_l IN LISTS _lines)
    math(EXPR _n "${_n} + 1")
    if(_l MATCHES "^[ \t]*//")
      continue()
    endif()
    if(_l MATCHES "(^|[^A-Za-z0-9_])(atof|strtod|strtof|strtold|stod|stof|stold)[ \t]*\\("
       OR _l MATCHES "printf[ \t]*\\(.*%[-+ #0-9.*]*[aAeEfFgG]"
       OR _l MATCHES "setprecision|\\.precision[ \t]*\\(")
      message(SEVERE_WARNING "${_f}:${_n}: locale-dependent number conversion: ${_l}")
      set(_bad 1)
    endif()
  endforeach()
endforeach()
# Tests read program output with testutil::stod (tests/NumberText.h): std::stod & co. read "0.5" as 0
# under de_DE.UTF-8, where scripts/test runs the suite a second time.
file(GLOB_RECURSE _tests ${ROOT}/tests/*.h ${ROOT}/tests/*.cpp)
list(FILTER _tests EXCLUDE REGEX "tests/NumberText\\.h$")
foreach(_f ${_tests})
  file(STRINGS ${_f} _lines)
  set(_n 0)
  foreach(_l IN LISTS _lines)
    math(EXPR _n "${_n} + 1")
    if(_l MATCHES "^[ \t]*//")
      continue()
    endif()
    if(_l MATCHES "(^|[^A-Za-z0-9_:])(std::)?(atof|strtod|strtof|strtold|stod|stof|stold)[ \t]*\\(")
      message(SEVERE_WARNING "${_f}:${_n}: locale-dependent number parsing in a test: ${_l}")
      set(_bad 1)
    endif()
  endforeach()
endforeach()
if(_bad)
  message(FATAL_ERROR "use core/model/Number.h (std::to_chars / std::from_chars) for numbers")
endif()
message(STATUS "no locale-dependent number conversions")
