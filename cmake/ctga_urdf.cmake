# ctga_urdf_header(TARGET <target> URDF <file.urdf> NAME <name> [FLOATING_BASE] [ARGS <more options>])
#
# Generates <name>.hpp from a URDF with tools/urdf_to_ctga.py at build time (re-run when the URDF
# or the script changes) and makes it includable by <target> as #include "<name>.hpp". The header
# declares namespace <name> { using tree = ctga::chains::tree<...>; make_model<T>(); names }.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(CTGA_URDF_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/../tools/urdf_to_ctga.py)
function(ctga_urdf_header)
  cmake_parse_arguments(arg "FLOATING_BASE" "TARGET;URDF;NAME" "ARGS" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  set(out ${out_dir}/${arg_NAME}.hpp)
  set(options --name ${arg_NAME} ${arg_ARGS})
  if(arg_FLOATING_BASE)
    list(APPEND options --floating-base)
  endif()
  get_filename_component(urdf_name ${arg_URDF} NAME)
  add_custom_command(OUTPUT ${out}
    COMMAND ${Python3_EXECUTABLE} ${CTGA_URDF_SCRIPT} ${arg_URDF} ${options} -o ${out}
    DEPENDS ${CTGA_URDF_SCRIPT} ${arg_URDF}
    COMMENT "urdf_to_ctga: ${urdf_name} -> generated/${arg_NAME}.hpp" VERBATIM)
  target_sources(${arg_TARGET} PRIVATE ${out})
  target_include_directories(${arg_TARGET} PRIVATE ${out_dir})
endfunction()
