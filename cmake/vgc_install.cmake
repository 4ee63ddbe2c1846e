# vgc_install.cmake — what `cmake --install` puts under a prefix and how
# `cpack -G DEB` packages the same install (docs/ci.md). Included from the
# top CMakeLists.txt after the vgc target exists.
#
#   bin/vgc                                  the program
#   include/vgc/vgc_plugin.h                 the plugin ABI header
#   lib/vgc/libvgc_coverage.a, vgc_coverage.o  the coverage runtime for implementations (runtime/)
#   include/vgc/vgc_coverage_shm.h           its shared memory layout
#   share/doc/vgc/README.md, docs/*.md       the documentation
#   lib/cmake/vgc/vgcConfig.cmake, vgcConfigVersion.cmake, vgcTargets*.cmake,
#                vgcCertification.cmake      the CMake package
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# vgc::plugin_header: the include directory holding vgc_plugin.h.
add_library(vgc_plugin_header INTERFACE)
target_include_directories(vgc_plugin_header INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/conformance/adapter>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/vgc>)
set_target_properties(vgc_plugin_header PROPERTIES EXPORT_NAME plugin_header)
add_library(vgc::plugin_header ALIAS vgc_plugin_header)

# Not the arch-dependent libdir: lib/cmake/<name>/ is searched under every
# prefix, and the one library (lib/vgc/, the coverage runtime) is linked by
# path (-L<prefix>/lib/vgc, or vgc::coverage).
set(VGC_INSTALL_CMAKEDIR lib/cmake/vgc)

# The coverage runtime is installed beside the program: building vgc builds it.
add_dependencies(vgc vgc_coverage)

install(TARGETS vgc vgc_plugin_header EXPORT vgc_targets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/conformance/adapter/vgc_plugin.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vgc)
file(GLOB VGC_DOCS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${VGC_DOCS} DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)

install(EXPORT vgc_targets NAMESPACE vgc:: FILE vgcTargets.cmake DESTINATION ${VGC_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/vgc_config.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/vgcConfig.cmake INSTALL_DESTINATION ${VGC_INSTALL_CMAKEDIR})
# 0.x: a consumer asking for 0.1 gets 0.1.*, not 0.2.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/vgcConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/vgcConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/vgcConfigVersion.cmake
  DESTINATION ${VGC_INSTALL_CMAKEDIR})
install(FILES ${CMAKE_CURRENT_LIST_DIR}/vgc_certification.cmake
  DESTINATION ${VGC_INSTALL_CMAKEDIR} RENAME vgcCertification.cmake)

# cpack -G DEB: the same install under /usr; dpkg-shlibdeps names the
# Debian packages of the shared libraries vgc links (libfmt9, libosdcpu3.5.0, ...).
set(CPACK_PACKAGE_NAME vgc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Verse geometry node conformance and fuzz suite")
set(CPACK_PACKAGE_CONTACT "vgc maintainers <vgc@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
