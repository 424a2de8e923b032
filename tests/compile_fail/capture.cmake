# The compiler launcher of the compile-fail targets (tests/CMakeLists.txt):
#   cmake -DLOG=<file> -P capture.cmake -- <compile command...>
# runs the compile command, writes what the compiler printed (both streams, in order) to LOG,
# prints it too, and fails when the compiler failed. run.cmake reads LOG: the compiler's own
# lines, without what the build tool prints around them.
set(command)
set(after_dashes FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(after_dashes)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" STREQUAL "--")
    set(after_dashes TRUE)
  endif()
endforeach()
execute_process(COMMAND ${command} OUTPUT_VARIABLE out ERROR_VARIABLE out RESULT_VARIABLE status)
file(WRITE "${LOG}" "${out}")
message("${out}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the compiler failed (${status})")
endif()
