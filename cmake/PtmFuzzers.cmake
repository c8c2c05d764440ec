# PTM_BUILD_FUZZERS: libFuzzer targets for the core (Testing/Fuzz), with a
# short CTest run of each. libFuzzer ships with clang only, hence the check.
#
# The fuzzers steer by coverage of ptmcore itself, so ptmcore (and everything
# else in this build) is compiled with the coverage instrumentation of
# -fsanitize=fuzzer-no-link; the fuzz targets link libFuzzer's main with
# -fsanitize=fuzzer. ASan and UBSan come from PtmSanitizers.cmake.
option(PTM_BUILD_FUZZERS "Build the libFuzzer targets of the core (clang only)" OFF)

if (PTM_BUILD_FUZZERS)
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "PTM_BUILD_FUZZERS needs clang++ for libFuzzer, but the C++ compiler is "
      "${CMAKE_CXX_COMPILER_ID} (${CMAKE_CXX_COMPILER}). Configure a fresh build directory with "
      "CC=clang CXX=clang++ (Debian: apt-get install clang libclang-rt-14-dev).")
  endif ()
  if (NOT BUILD_TESTING)
    message(FATAL_ERROR "PTM_BUILD_FUZZERS needs BUILD_TESTING=ON (the fuzzers live in Testing/Fuzz)")
  endif ()
  add_compile_options(-fsanitize=fuzzer-no-link)
  # How long CTest's short run of each fuzzer lasts, in seconds.
  set(PTM_FUZZ_SECONDS 120 CACHE STRING "Seconds of each fuzzer's CTest run")
  # libFuzzer's seed for those runs. Fixed by default, so a CI failure can be
  # replayed exactly (session 9's CI run of DecompositionFuzzer.Short failed
  # with a random seed, and 20-odd local runs of 120 s did not find it again);
  # 0 lets libFuzzer pick one. Random fuzzing: Testing/Fuzz/README.md.
  set(PTM_FUZZ_SEED 1 CACHE STRING "libFuzzer -seed of the CTest runs (0: random)")
  message(STATUS "PTM_BUILD_FUZZERS: fuzz targets in Testing/Fuzz, ${PTM_FUZZ_SECONDS} s each in CTest, seed ${PTM_FUZZ_SEED}")
endif ()
