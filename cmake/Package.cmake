# Installation and the CMake package `hrgbd` (find_package(hrgbd), targets hrgbd::<module>).
# hrgbd_module() and hrgbd_app() install what they make, so a new module or app needs no line here.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HRGBD_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/hrgbd)

# Library `name` (static archive and its public headers, include/<name>/) into the export set.
function(hrgbd_install_library name)
  install(TARGETS ${name} EXPORT hrgbdTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# The exported targets, package config and version files, and the default configuration
# (share/hrgbd/config.ini, HRGBD_CONFIG_INI for consumers).
function(hrgbd_install_package)
  install(EXPORT hrgbdTargets NAMESPACE hrgbd:: DESTINATION ${HRGBD_CMAKE_INSTALL_DIR})
  set(HRGBD_CONFIG_INI ${CMAKE_INSTALL_DATADIR}/hrgbd/config.ini)
  configure_package_config_file(
    ${PROJECT_SOURCE_DIR}/cmake/hrgbdConfig.cmake.in ${PROJECT_BINARY_DIR}/hrgbdConfig.cmake
    INSTALL_DESTINATION ${HRGBD_CMAKE_INSTALL_DIR} PATH_VARS HRGBD_CONFIG_INI)
  # 0.x: minor versions may break the interface.
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/hrgbdConfigVersion.cmake
                                   VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/hrgbdConfig.cmake
                ${PROJECT_BINARY_DIR}/hrgbdConfigVersion.cmake
                ${PROJECT_SOURCE_DIR}/cmake/hrgbdDependencies.cmake
          DESTINATION ${HRGBD_CMAKE_INSTALL_DIR})
  install(FILES ${PROJECT_SOURCE_DIR}/config.ini DESTINATION ${CMAKE_INSTALL_DATADIR}/hrgbd)
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff
          DESTINATION ${CMAKE_INSTALL_DOCDIR})
endfunction()
