# Helpers shared by every module, test suite and benchmark.

include(GNUInstallDirs)

set(HRSPACE_WARNINGS -Wall -Wextra -Wpedantic)

# hrspace_cgal_sources(file ...): the files that include CGAL headers (called
# in the directory that defines their target). In builds with
# UndefinedBehaviorSanitizer they are compiled without its `vptr` check:
# CGAL's arrangement iterators downcast a base-class pointer the check cannot
# follow (a false positive inside CGAL's own headers), and every miss of the
# check's type cache probes memory through a pipe, which made the unit suites
# of the exact reference run for hours. Every other file keeps the check.
function(hrspace_cgal_sources)
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*undefined")
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
  endif()
endfunction()

# hrspace_add_module(name SOURCES ... [DEPS ...] [PRIVATE_DEPS ...])
# Defines library hrspace_<name> with alias hrspace::<name>.
function(hrspace_add_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(hrspace_${name} STATIC ${M_SOURCES})
  add_library(hrspace::${name} ALIAS hrspace_${name})
  # Installed headers live in include/hrspace/<module>/ and include each
  # other as "geometry/scene.h" (include/hrspace on the path); include/ is on
  # it too, so that consumers may write <hrspace/geometry/scene.h>.
  target_include_directories(hrspace_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/hrspace>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # Position-independent, so that the Python module (a shared object) links
  # the same static libraries; exported as hrspace::<name> (cmake/install.cmake).
  set_target_properties(hrspace_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${name})
  set_property(GLOBAL APPEND PROPERTY HRSPACE_MODULES ${name})
  target_compile_options(hrspace_${name} PRIVATE ${HRSPACE_WARNINGS})
  target_link_libraries(hrspace_${name} PUBLIC ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
endfunction()

# OMPL's exported variables differ between versions; wrap them in one target.
function(hrspace_ompl_target)
  if(NOT TARGET hrspace_ompl)
    add_library(hrspace_ompl INTERFACE)
    target_include_directories(hrspace_ompl SYSTEM INTERFACE ${OMPL_INCLUDE_DIRS})
    # omplConfig lists boost's unversioned .so files, which exist only with the
    # boost -dev packages; libompl.so records its own runtime dependencies, so
    # skip listed files that are missing.
    set(_ompl_libs "")
    foreach(_lib ${OMPL_LIBRARIES})
      if(NOT IS_ABSOLUTE "${_lib}" OR EXISTS "${_lib}")
        list(APPEND _ompl_libs "${_lib}")
      endif()
    endforeach()
    target_link_libraries(hrspace_ompl INTERFACE ${_ompl_libs})
  endif()
endfunction()

# hrspace_add_test(name SOURCES ... LIBS ... [ARGS ...] [LABELS unit|slow [no_sanitize] ...] [OMPL])
# ARGS go to the test's command line (e.g. a --gtest_filter).
function(hrspace_add_test name)
  cmake_parse_arguments(T "OMPL" "" "SOURCES;LIBS;ARGS;LABELS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_compile_options(${name} PRIVATE ${HRSPACE_WARNINGS})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  if(T_OMPL)
    hrspace_ompl_target()
    target_link_libraries(${name} PRIVATE hrspace_ompl)
  endif()
  target_compile_definitions(${name} PRIVATE HRSPACE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  if(NOT T_LABELS)
    set(T_LABELS unit)
  endif()
  add_test(NAME ${name} COMMAND ${name} ${T_ARGS})
  set_tests_properties(${name} PROPERTIES LABELS "${T_LABELS}" TIMEOUT 1800)
endfunction()

# hrspace_add_test_run(name TARGET executable ARGS ... [LABELS unit|slow ...])
# One more test of an executable that hrspace_add_test made, with its own
# command line: one source split into fast and slow suites by gtest filters.
function(hrspace_add_test_run name)
  cmake_parse_arguments(T "" "TARGET" "ARGS;LABELS" ${ARGN})
  if(NOT T_LABELS)
    set(T_LABELS unit)
  endif()
  add_test(NAME ${name} COMMAND ${T_TARGET} ${T_ARGS})
  set_tests_properties(${name} PROPERTIES LABELS "${T_LABELS}" TIMEOUT 1800)
endfunction()

# hrspace_add_bench(name SOURCES ... LIBS ... [OMPL])
function(hrspace_add_bench name)
  cmake_parse_arguments(B "OMPL" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${B_SOURCES})
  target_compile_options(${name} PRIVATE ${HRSPACE_WARNINGS})
  target_link_libraries(${name} PRIVATE ${B_LIBS} benchmark::benchmark)
  if(B_OMPL)
    hrspace_ompl_target()
    target_link_libraries(${name} PRIVATE hrspace_ompl)
  endif()
  target_compile_definitions(${name} PRIVATE HRSPACE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endfunction()
