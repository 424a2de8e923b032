# One compile-fail test (tests/CMakeLists.txt):
#   cmake -DBUILD_DIR=… -DTARGET=… -DCONFIG=… -DLOG=… -DEXPECT=<regex> -DFIRST_LINES=<n> -P run.cmake
# Building TARGET must fail, and the compiler's output (LOG, written by capture.cmake, the
# target's compiler launcher) must match EXPECT, a CMake regular expression: within its first
# FIRST_LINES lines, or anywhere when FIRST_LINES is 0.
file(REMOVE "${LOG}")
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --target "${TARGET}" --config "${CONFIG}"
                OUTPUT_VARIABLE build_output ERROR_VARIABLE build_output RESULT_VARIABLE status)
if(status EQUAL 0)
  message(FATAL_ERROR "${TARGET} compiled, and must not")
endif()
if(NOT EXISTS "${LOG}")
  message(FATAL_ERROR "the compiler did not run (or not through capture.cmake):\n${build_output}")
endif()
file(READ "${LOG}" output)

# the first FIRST_LINES lines (by their line feeds: GCC's and Clang's lines hold brackets and
# semicolons, which a CMake list would not keep)
set(shown "${output}")
if(FIRST_LINES GREATER 0)
  set(shown "")
  set(rest "${output}")
  foreach(i RANGE 1 ${FIRST_LINES})
    string(FIND "${rest}" "\n" end)
    if(end EQUAL -1)
      string(APPEND shown "${rest}")
      break()
    endif()
    math(EXPR end "${end} + 1")
    string(SUBSTRING "${rest}" 0 ${end} line)
    string(APPEND shown "${line}")
    string(SUBSTRING "${rest}" ${end} -1 rest)
  endforeach()
endif()

# (plain message(): FATAL_ERROR would rewrap the compiler's lines)
if(FIRST_LINES GREATER 0)
  message("the first ${FIRST_LINES} lines of the compiler's output:\n${shown}")
endif()
if(NOT shown MATCHES "${EXPECT}")
  if(FIRST_LINES GREATER 0)
    message(FATAL_ERROR "'${EXPECT}' is not in the first ${FIRST_LINES} lines of the compiler's output")
  endif()
  message("${output}")
  message(FATAL_ERROR "'${EXPECT}' is not in the compiler's output")
endif()
