# package.cmake: `make package` (cpack) builds one Debian package, coverage-axis, installing into
# /usr: the static and shared libraries, the header, the CMake package and the pkg-config file
# (component library) and, when built, the tool (component tool). The Python package is left out.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME coverage-axis)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Coverage Axis medial skeletons: C library, header and command-line tool")
set(CPACK_PACKAGE_DESCRIPTION "coverage-axis turns a triangle mesh or a point cloud into a compact
medial skeleton (Coverage Axis, Dou et al., Eurographics 2022): the fewest medial balls that cover
the surface, joined by edges and triangles. This package holds the C library (static and shared),
its header, CMake package and pkg-config file, and the coverage-axis command-line tool.")
set(CPACK_PACKAGE_CONTACT "The coverage-axis authors <dev@coverage-axis.invalid>")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_CMAKE_PROJECTS ${PROJECT_BINARY_DIR} ${PROJECT_NAME} library /)
if(CA_BUILD_TOOLS)
  list(APPEND CPACK_INSTALL_CMAKE_PROJECTS ${PROJECT_BINARY_DIR} ${PROJECT_NAME} tool /)
endif()
set(CPACK_STRIP_FILES ON)  # the shared library and the tool; a static library is never stripped
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # coverage-axis_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
# The run-time dependencies of the shared library and the tool come from dpkg-shlibdeps. The
# static library and the CMake package need the development packages: Qhull's CMake package and
# static archive, CBC's pkg-config file, and pkg-config itself (coverage_axisConfig.cmake and
# coverage_axis.pc both ask for cbc).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "coinor-libcbc-dev, libqhull-dev, pkg-config")
# a shlibs file for libcoverage_axis.so.<SOVERSION>, and ldconfig run on install and removal
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
include(CPack)
