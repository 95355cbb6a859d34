# Warnings as errors on our own targets only (generated and third-party code is not ours).
function(penshape_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror)
endfunction()

# Test binaries: discovered by ctest. PRE_TEST discovery works for sanitizer builds too.
function(penshape_add_test target)
  # RESOURCE_LOCK name: tests sharing a resource (e.g. an X server) never run at once.
  cmake_parse_arguments(ARG "" "RESOURCE_LOCK" "SOURCES;LIBS" ${ARGN})
  add_executable(${target} ${ARG_SOURCES})
  penshape_warnings(${target})
  # Test data is located by penshape_test_data alone (tests/support/test_data.hpp), so that
  # PENSHAPE_SHARED_DATA_DIR in the environment overrides the cache variable without a rebuild.
  target_link_libraries(${target} PRIVATE ${ARG_LIBS} penshape_test_data GTest::gtest
    GTest::gtest_main)
  target_compile_definitions(${target} PRIVATE
    PENSHAPE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    PENSHAPE_BINARY_DIR="${PROJECT_BINARY_DIR}")
  set(properties)
  if(ARG_RESOURCE_LOCK)
    set(properties PROPERTIES RESOURCE_LOCK ${ARG_RESOURCE_LOCK})
  endif()
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 DISCOVERY_MODE PRE_TEST ${properties})
endfunction()
