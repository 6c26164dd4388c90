# The SDK: `cmake --install build/release --prefix P` puts under P
#   include/gjk2d/...        the header-only GJK library        (gjk2d::gjk; gjk2d/distance.hpp)
#   include/gjk2d/batch.hpp  the batch in SIMD lanes            (gjk2d::batch, with
#   lib/libgjk2d_batch.a     its static library)
#   include/gjk2d/exact.hpp  the exact side's CGAL-free header   (gjk2d::exact, with
#   lib/libgjk2d_exact.a     its static library; links GMP and MPFR by name)
#   include/gjk2d/plugin.h   the plugin ABI                      (gjk2d::plugin)
#   include/gjk/, exact/     the old paths, each forwarding to gjk2d/ with a warning, for one release
#   bin/gjk-validate         the runner
#   lib/gjk2d/plugins/       the shipped plugins (the Box2D 2.4.1 adapter, the peers), loaded by `run`
#   share/gjk2d/cases/       the default campaign's case files
#   lib/cmake/gjk2d/         gjk2d-config.cmake, its version file and the exported targets
#   lib/pkgconfig/gjk2d.pc   for pkg-config (cflags of the headers, libs of the exact side)
# ("lib" is GNUInstallDirs' CMAKE_INSTALL_LIBDIR.) CPack makes the Debian package gjk2d from the
# same rules (docs/validate-your-gjk.md, "1. Install the SDK").
include(CMakePackageConfigHelpers)

# `cpack` (and `make install`) install what is built, without building every target first: the
# .deb test (tests/plugins) then costs the packaging alone. Build before installing.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(GJK2D_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gjk2d)

install(TARGETS gjk2d_gjk gjk2d_batch gjk2d_exact gjk2d_plugin EXPORT gjk2d-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/gjk/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/exact/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/validation/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS gjk-validate RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The shipped plugins: each plugin's CMakeLists.txt (validation/plugins/<folder>/) installs it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/validation/cases/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gjk2d/cases
        FILES_MATCHING PATTERN "*.json")

install(EXPORT gjk2d-targets NAMESPACE gjk2d:: DESTINATION ${GJK2D_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/gjk2d-config.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/gjk2d-config.cmake INSTALL_DESTINATION ${GJK2D_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_BINDIR GJK2D_INSTALL_PLUGIN_DIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/gjk2d-config-version.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gjk2d-config.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/gjk2d-config-version.cmake
        DESTINATION ${GJK2D_CMAKE_DIR})
# gjk2d.pc names its prefix relative to its own place (${pcfiledir}): the same file serves any
# --prefix and the .deb's /usr.
file(RELATIVE_PATH GJK2D_PC_TO_PREFIX /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
string(REGEX REPLACE "/$" "" GJK2D_PC_TO_PREFIX "${GJK2D_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/gjk2d.pc.in ${CMAKE_CURRENT_BINARY_DIR}/gjk2d.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/gjk2d.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The Debian package: `cpack -G DEB` in the build directory (docs/validate-your-gjk.md). Depends:
# the shared libraries gjk-validate and the Box2D adapter link (dpkg-shlibdeps), and the -dev
# packages a consumer of gjk2d::exact links with (GMP, MPFR).
set(CPACK_PACKAGE_NAME gjk2d)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "gjk2d")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "2D GJK distance library, exact ground truth and gjk-validate (validate any GJK via plugins)")
set(CPACK_PACKAGE_CONTACT "gjk2d maintainers <gjk2d@localhost>")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # gjk2d_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON) # dpkg-shlibdeps (dpkg-dev, scripts/setup.sh)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgmp-dev, libmpfr-dev")
# The Python package (python/, lib/python3/dist-packages/gjk2d) imports NumPy; C++ users need not.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-numpy")
include(CPack)
