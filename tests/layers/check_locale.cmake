# SPDX-License-Identifier: GPL-3.0-or-later
# Fails when core/, app/ or widgets/ use a C library or iostream number conversion that follows the
# locale (docs/formats.md "Numbers"): atof/strtod/stod & co., printf-family calls with a
# floating-point conversion, ostream precision settings. core/model/Number.h is the way to do it.
# Tests read program output with testutil::stod (tests/NumberText.h): std::stod & co. read "0.5" as 0
# under de_DE.UTF-8, where scripts/test runs the suite a second time.
set(_bad 0)
set(_parse "(^|[^A-Za-z0-9_:])(std::)?(atof|strtod|strtof|strtold|stod|stof|stold)[ \t]*\\(")

# Reports every non-comment line of `files` that matches one of the regular expressions after them.
function(check_lines what files)
  foreach(_f ${files})
    file(STRINGS ${_f} _lines)
    set(_n 0)
    foreach(_l IN LISTS _lines)
      math(EXPR _n "${_n} + 1")
      if(_l MATCHES "^[ \t]*//")
        continue()
      endif()
      foreach(_re IN LISTS ARGN)
        if(_l MATCHES "${_re}")
          message(SEVERE_WARNING "${_f}:${_n}: locale-dependent ${what}: ${_l}")
          set(_bad 1 PARENT_SCOPE)
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()

file(GLOB_RECURSE _files ${ROOT}/core/*.h ${ROOT}/core/*.cpp ${ROOT}/app/*.h ${ROOT}/app/*.cpp
     ${ROOT}/widgets/*.h ${ROOT}/widgets/*.cpp)
check_lines("number conversion" "${_files}" "${_parse}" "printf[ \t]*\\(.*%[-+ #0-9.*]*[aAeEfFgG]"
            "setprecision|\\.precision[ \t]*\\(")
file(GLOB_RECURSE _tests ${ROOT}/tests/*.h ${ROOT}/tests/*.cpp)
list(FILTER _tests EXCLUDE REGEX "tests/NumberText\\.h$")
check_lines("number parsing in a test" "${_tests}" "${_parse}")
if(_bad)
  message(FATAL_ERROR "use core/model/Number.h (std::to_chars / std::from_chars) for numbers")
endif()
message(STATUS "no locale-dependent number conversions")
