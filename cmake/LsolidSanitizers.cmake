# Sanitizers and fuzzing as an INTERFACE target that every project target
# links through lsolid::warnings, never as global flags.
#   LSOLID_SANITIZE: AddressSanitizer and UndefinedBehaviorSanitizer; any
#     report stops the program (-fno-sanitize-recover), so a test fails.
#   LSOLID_FUZZ: coverage for libFuzzer on every target and the fuzz targets
#     of tests/fuzz; needs Clang (Debian's clang and libclang-rt-14-dev).
# scripts/fuzz configures a build with both.
option(LSOLID_SANITIZE "Build with AddressSanitizer and UBSan" OFF)
option(LSOLID_FUZZ "Build the libFuzzer targets (Clang)" OFF)

add_library(lsolid_sanitizers INTERFACE)
if(LSOLID_SANITIZE)
  target_compile_options(lsolid_sanitizers INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  target_link_options(lsolid_sanitizers INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all)
endif()
if(LSOLID_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "LSOLID_FUZZ needs Clang: -DCMAKE_CXX_COMPILER=clang++")
  endif()
  target_compile_options(lsolid_sanitizers INTERFACE -fsanitize=fuzzer-no-link)
endif()
