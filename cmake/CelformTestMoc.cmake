# moc for the tests, without AUTOMOC.
#
# A QtTest file declares its test class in the .cpp and ends with `#include "<name>.moc"`. AUTOMOC
# hands moc every include directory of the target (Eigen, CGAL, Qt, the project), and moc then
# preprocesses each header it can find: about 4 s of one core per test, some 90 tests, twice per
# CI run (release and sanitize). The class moc has to read is in the .cpp itself, so moc runs here
# on the .cpp alone, with no include path; the output is the same byte for byte (checked on
# test_cli_fit.cpp) and takes 15 ms.
function(celform_test_moc target)
  set_target_properties(${target} PROPERTIES AUTOMOC OFF)
  get_target_property(_sources ${target} SOURCES)
  set(_out_dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_moc)
  foreach(_src IN LISTS _sources)
    if(NOT _src MATCHES "\\.cpp$")
      continue()
    endif()
    get_filename_component(_abs ${_src} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    get_filename_component(_stem ${_src} NAME_WE)
    file(STRINGS ${_abs} _includes_moc REGEX "^#include \"${_stem}\\.moc\"")
    if(NOT _includes_moc)
      continue()
    endif()
    add_custom_command(
      OUTPUT ${_out_dir}/${_stem}.moc
      COMMAND ${CMAKE_COMMAND} -E make_directory ${_out_dir}
      COMMAND Qt6::moc ${_abs} -o ${_out_dir}/${_stem}.moc
      DEPENDS ${_abs} Qt6::moc
      COMMENT "moc ${_stem}.cpp"
      VERBATIM)
    # The generated file is #included by the .cpp: the dependency makes it exist first.
    set_property(SOURCE ${_abs} APPEND PROPERTY OBJECT_DEPENDS ${_out_dir}/${_stem}.moc)
    target_sources(${target} PRIVATE ${_out_dir}/${_stem}.moc)
    set_source_files_properties(${_out_dir}/${_stem}.moc PROPERTIES HEADER_FILE_ONLY ON)
    target_include_directories(${target} PRIVATE ${_out_dir})
  endforeach()
endfunction()
