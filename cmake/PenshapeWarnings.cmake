# Our targets' common setup: warnings as errors (generated and third-party code is not ours),
# tests, libraries.
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

# One of our libraries: penshape_NAME with the alias penshape::NAME, the public headers in the
# calling folder's include/, and our warnings.
#   penshape_add_library(NAME [STATIC] SOURCES ... [PUBLIC deps...] [PRIVATE deps...])
function(penshape_add_library name)
  cmake_parse_arguments(ARG "STATIC" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  set(kind)
  if(ARG_STATIC)
    set(kind STATIC)
  endif()
  add_library(penshape_${name} ${kind} ${ARG_SOURCES})
  add_library(penshape::${name} ALIAS penshape_${name})
  target_include_directories(penshape_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(penshape_${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  penshape_warnings(penshape_${name})
endfunction()
