# Warnings for the project's own targets (never for third-party headers, which come in as SYSTEM).
function(celform_set_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    # -Wshadow=local is GCC's; Clang (the sanitize preset) would warn on every file that it is unknown.
    # Clang's -Wpedantic also flags QtTest's own macros (QTEST_APPLESS_MAIN, QSKIP) for an empty
    # variadic argument, a GNU extension that GCC accepts silently.
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>
                                             $<$<CXX_COMPILER_ID:Clang>:-Wno-gnu-zero-variadic-macro-arguments>
                                             -Wnon-virtual-dtor -Wno-unused-parameter)
  endif()
  # Release with assertions: RelWithDebInfo keeps assert() on (no NDEBUG).
  target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo>:-UNDEBUG>)
endfunction()
