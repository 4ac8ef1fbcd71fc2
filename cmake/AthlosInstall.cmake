# Installation, the SDK for plugins built outside the tree, desktop integration and the Debian
# package. Included from the top-level CMakeLists.txt after every target is defined.
#
# Installed layout (prefix /usr in the package, /usr/local by default):
#   bin/athlos
#   <libdir>/libathlos_core.so*, libathlos_ui.so*           (RUNPATH $ORIGIN, see CMakeLists.txt)
#   <libdir>/athlos/plugins/athlos_plugin_<family>.so      (where ProcessorRegistry looks)
#   <libdir>/cmake/Athlos/AthlosConfig.cmake …              (find_package(Athlos) → Athlos::core)
#   include/athlos/core/…                                   (SDK headers, BuildInfo.h)
#   share/athlos/demo/pipeline*.json                        (the demo's pipelines)
#   share/applications/athlos.desktop, share/mime/packages/athlos.xml, share/icons/hicolor/…
include(CMakePackageConfigHelpers)

set(ATHLOS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Athlos)
install(EXPORT AthlosTargets NAMESPACE Athlos:: DESTINATION ${ATHLOS_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/AthlosConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/AthlosConfig.cmake
  INSTALL_DESTINATION ${ATHLOS_CMAKE_DIR}
  PATH_VARS ATHLOS_INSTALL_PLUGIN_DIR)
# The plugin interface and the SDK's ABI may change between minor versions while Athlos is 0.x.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/AthlosConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/AthlosConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/AthlosConfigVersion.cmake
  DESTINATION ${ATHLOS_CMAKE_DIR})

# What the demo reads besides the recordings (scripts/demo.sh finds them here when run against an
# installed copy).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/demo/ DESTINATION ${CMAKE_INSTALL_DATADIR}/athlos/demo
  FILES_MATCHING PATTERN "*.json")

# Desktop integration: a launcher that opens .athlos files (Exec=athlos %f), the MIME type
# application/x-athlos-project and the icons. Debian's shared-mime-info, desktop-file-utils and
# hicolor-icon-theme triggers refresh their caches when the package is installed.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/linux/athlos.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/linux/athlos-mime.xml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages RENAME athlos.xml)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/athlos.svg
  DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/linux/application-x-athlos-project.svg
  DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/mimetypes)

# Debian package: `cpack -G DEB` in the build folder (scripts/package.sh) → athlos_<version>_<arch>.deb.
# One package holds the application and the SDK (headers, CMake package), so a plugin can be built
# against an installed copy; building one also needs qt6-base-dev and libeigen3-dev (Suggests).
set(CPACK_PACKAGE_NAME athlos)
set(CPACK_PACKAGE_VENDOR "Athlos")
set(CPACK_PACKAGE_CONTACT "Athlos maintainers <maintainers@athlos.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
  "Desktop and command-line analysis of sports recordings: local positioning (LPS), inertial sensors\n(IMU) and GNSS. Projects are HDF5 files (.athlos); processors are plugins that run the same in\nthe GUI and headless. Includes the SDK (headers, CMake package Athlos) for processor plugins.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://athlos.invalid")
# Library dependencies come from dpkg-shlibdeps (dpkg-dev); Qt's platform and SVG plugins are loaded
# at run time, so shlibdeps cannot see them.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6svg6")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "shared-mime-info, desktop-file-utils, hicolor-icon-theme, qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "cmake, g++, qt6-base-dev, libeigen3-dev")
include(CPack)
