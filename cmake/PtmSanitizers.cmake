# PTM_SANITIZE: builds the geometry core and its unit tests with AddressSanitizer
# and UndefinedBehaviorSanitizer, so memory errors, leaks and undefined
# behaviour in ptmcore fail the unit tests instead of passing unnoticed.
#
#   cmake -S . -B build-sanitize -DCMAKE_CXX_COMPILER=clang++ \
#         -DPTM_BUILD_PLUGIN=OFF -DPTM_SANITIZE=ON
#
# Every UB report is fatal (-fno-sanitize-recover): a report that only prints
# would let the test pass. The runtime options the tests run with are set in
# PtmSanitizerTestEnvironment.cmake.in.
option(PTM_SANITIZE "Build the core and its unit tests with AddressSanitizer and UBSan" OFF)

# The fuzzers (PtmFuzzers.cmake) need the same instrumentation of the core:
# a fuzzer only finds the memory errors that ASan can see.
if (PTM_SANITIZE OR PTM_BUILD_FUZZERS)
  if (PTM_BUILD_PLUGIN)
    # An ASan-instrumented plugin cannot be loaded into the uninstrumented
    # ParaView executables (the ASan runtime must come first in the process).
    message(FATAL_ERROR "PTM_SANITIZE and PTM_BUILD_FUZZERS build the core and its tests only: "
      "configure with -DPTM_BUILD_PLUGIN=OFF")
  endif ()
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang|GNU")
    message(FATAL_ERROR "PTM_SANITIZE needs clang or g++ (found ${CMAKE_CXX_COMPILER_ID})")
  endif ()
  set(PTM_SANITIZER_FLAGS
    -fsanitize=address,undefined
    -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
  # On every target defined after this point: ptmcore, the unit tests, the
  # benchmark drivers and the fuzzers.
  add_compile_options(${PTM_SANITIZER_FLAGS})
  add_link_options(${PTM_SANITIZER_FLAGS})
  message(STATUS "PTM_SANITIZE: building with ${PTM_SANITIZER_FLAGS}")

  # Runtime options for every test CTest runs in this build tree (the unit
  # tests are registered by gtest_discover_tests at build time, so their
  # properties cannot be set here; CTest evaluates this file before it starts
  # any test, and the environment it sets is inherited by all of them).
  configure_file("${CMAKE_CURRENT_LIST_DIR}/PtmSanitizerTestEnvironment.cmake.in"
    "${PROJECT_BINARY_DIR}/PtmSanitizerTestEnvironment.cmake" @ONLY)
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY
    TEST_INCLUDE_FILES "${PROJECT_BINARY_DIR}/PtmSanitizerTestEnvironment.cmake")
endif ()
