# Sanitizers and libFuzzer coverage for the whole build (CELFORM_SANITIZERS, CELFORM_BUILD_FUZZERS).
# Added as directory options before any target, so the libraries, the tests and the fuzz targets
# share one instrumented build (the sanitize preset).
if(CELFORM_SANITIZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "CELFORM_SANITIZERS needs GCC or Clang")
  endif()
  list(JOIN CELFORM_SANITIZERS "," _celform_sanitizers)
  add_compile_options(-fsanitize=${_celform_sanitizers} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${_celform_sanitizers})
  if("undefined" IN_LIST CELFORM_SANITIZERS)
    # Undefined behaviour stops the program like an ASan report, so a test or a fuzzer fails on it.
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
endif()

if(CELFORM_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "CELFORM_BUILD_FUZZERS needs Clang (libFuzzer): configure with the sanitize preset")
  endif()
  # Coverage feedback from every library; only the fuzz targets link libFuzzer's main
  # (-fsanitize=fuzzer, tests/fuzz/CMakeLists.txt); the sanitizer runtime supplies the hooks elsewhere.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
