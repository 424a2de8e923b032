# ctga_urdf_header(TARGET <target> URDF <file.urdf> NAME <name> [FLOATING_BASE] [ARGS <more options>])
#
# Generates <name>.hpp from a URDF with ctga's converter at build time (re-run when the URDF or the
# converter changes) and makes it includable by <target> as #include "<name>.hpp". The header
# declares namespace <name> { using tree = ctga::chains::tree<...>; make_model<T>(); make_limits<T>();
# names }. ARGS are the converter's options (`ctga-urdf --help`: --massless, --lock, --armature, ...).
#
# The converter is tools/urdf_to_ctga.py in a checkout (add_subdirectory) and the installed
# command ctga-urdf next to an installed package (find_package(ctga): ctgaConfig.cmake sets
# CTGA_URDF_COMMAND before including this file). It needs a Python 3 interpreter.
if(NOT DEFINED CTGA_URDF_COMMAND)
  set(CTGA_URDF_COMMAND ${CMAKE_CURRENT_LIST_DIR}/../tools/urdf_to_ctga.py)
endif()
get_filename_component(_ctga_urdf_command "${CTGA_URDF_COMMAND}" ABSOLUTE)
find_package(Python3 COMPONENTS Interpreter QUIET)
# global properties: the function may be called from any directory of the project
set_property(GLOBAL PROPERTY CTGA_URDF_COMMAND "${_ctga_urdf_command}")
set_property(GLOBAL PROPERTY CTGA_URDF_PYTHON "${Python3_EXECUTABLE}")

function(ctga_urdf_header)
  cmake_parse_arguments(arg "FLOATING_BASE" "TARGET;URDF;NAME" "ARGS" ${ARGN})
  foreach(_required TARGET URDF NAME)
    if(NOT arg_${_required})
      message(FATAL_ERROR "ctga_urdf_header: ${_required} is required")
    endif()
  endforeach()
  get_property(command GLOBAL PROPERTY CTGA_URDF_COMMAND)
  get_property(python GLOBAL PROPERTY CTGA_URDF_PYTHON)
  if(NOT python)
    message(FATAL_ERROR "ctga_urdf_header: the URDF converter needs a Python 3 interpreter (Debian: apt install python3)")
  endif()
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  set(out ${out_dir}/${arg_NAME}.hpp)
  set(options --name ${arg_NAME} ${arg_ARGS})
  if(arg_FLOATING_BASE)
    list(APPEND options --floating-base)
  endif()
  get_filename_component(urdf ${arg_URDF} ABSOLUTE)
  get_filename_component(urdf_name ${arg_URDF} NAME)
  add_custom_command(OUTPUT ${out}
    COMMAND ${python} ${command} ${urdf} ${options} -o ${out}
    DEPENDS ${command} ${urdf}
    COMMENT "ctga-urdf: ${urdf_name} -> generated/${arg_NAME}.hpp" VERBATIM)
  target_sources(${arg_TARGET} PRIVATE ${out})
  target_include_directories(${arg_TARGET} PRIVATE ${out_dir})
endfunction()
