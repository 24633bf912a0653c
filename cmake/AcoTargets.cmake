# One place that says how every acodrill target is built: alias, public include
# directory, language standard and private warnings. Each folder's CMakeLists
# is then one call, and a fix here reaches every target (Clipper2 copy-pasted
# this per target and the copies drifted apart).

function(aco_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_17)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  if(ACO_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# aco_add_library(NAME ALIAS ns::name SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
function(aco_add_library name)
  cmake_parse_arguments(ARG "" "ALIAS" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  add_library(${ARG_ALIAS} ALIAS ${name})
  # Installed, the target keeps its alias's name: aco::dxf, not aco::aco_dxf.
  string(REPLACE "aco::" "" export_name ${ARG_ALIAS})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${export_name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                            $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
                                     PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  aco_target_defaults(${name})
endfunction()

# aco_add_executable(NAME SOURCES ... DEPS ...)
function(aco_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  aco_target_defaults(${name})
endfunction()

# aco_add_test(NAME [DEPS ...] [LOCK resource] [SERIAL]): tests/NAME.cpp linked
# with gtest_main and DEPS; LOCK keeps its tests from running in parallel with
# any other test holding the same lock; SERIAL runs them with no other test.
function(aco_add_test name)
  cmake_parse_arguments(ARG "SERIAL" "LOCK" "DEPS" ${ARGN})
  add_executable(${name} ${name}.cpp)
  target_link_libraries(${name} PRIVATE GTest::gtest GTest::gtest_main GTest::gmock ${ARG_DEPS})
  aco_target_defaults(${name})
  # Tests find the data and the built programs through these, wherever ctest runs them.
  target_compile_definitions(${name} PRIVATE ACO_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                             ACODRILL_BIN="$<TARGET_FILE:acodrill>" ACO_BUILD_DIR="${PROJECT_BINARY_DIR}")
  add_dependencies(${name} acodrill acobench)
  if(ARG_LOCK)
    gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} DISCOVERY_TIMEOUT 60
                         PROPERTIES RESOURCE_LOCK ${ARG_LOCK})
  elseif(ARG_SERIAL)
    gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} DISCOVERY_TIMEOUT 60
                         PROPERTIES RUN_SERIAL TRUE)
  else()
    gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} DISCOVERY_TIMEOUT 60)
  endif()
endfunction()

# aco_add_bench(NAME [DEPS ...]): bench/NAME.cpp linked with benchmark_main.
function(aco_add_bench name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  add_executable(${name} ${name}.cpp)
  target_link_libraries(${name} PRIVATE benchmark::benchmark benchmark::benchmark_main ${ARG_DEPS})
  aco_target_defaults(${name})
endfunction()
