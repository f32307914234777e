# Install rules: `cmake --install build [--prefix DIR]` puts
#   lib/libhrspace_<module>.a            every library (hrspace::<module>)
#   include/hrspace/<module>/*.h         their public headers
#   bin/hrspace                          the command
#   lib/cmake/hrspace/                   the CMake package: find_package(hrspace CONFIG)
#   ${HRSPACE_PYTHON_INSTALL_DIR}/hrspace  the Python package (python/CMakeLists.txt)
# Every destination is relative, so --prefix moves them all.
include(CMakePackageConfigHelpers)

get_property(_hrspace_modules GLOBAL PROPERTY HRSPACE_MODULES)
foreach(_module ${_hrspace_modules})
  install(TARGETS hrspace_${_module} EXPORT hrspaceTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB _headers CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/${_module}/*.h")
  install(FILES ${_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hrspace/${_module})
endforeach()

if(TARGET hrspace)
  install(TARGETS hrspace RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(HRSPACE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/hrspace)
install(EXPORT hrspaceTargets NAMESPACE hrspace:: DESTINATION ${HRSPACE_CMAKE_DIR})
configure_package_config_file(cmake/hrspaceConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/hrspaceConfig.cmake INSTALL_DESTINATION ${HRSPACE_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hrspaceConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hrspaceConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/hrspaceConfigVersion.cmake DESTINATION ${HRSPACE_CMAKE_DIR})
