# install_path.cmake (run by `cmake --install`): writes coverage_axis/_install_path.py, the path of
# the installed shared library, so the installed package finds it without $CA_LIBRARY.
if(IS_ABSOLUTE "${CA_PYTHON_INSTALL_DIR}")
  set(_dir "${CA_PYTHON_INSTALL_DIR}")
else()
  set(_dir "${CMAKE_INSTALL_PREFIX}/${CA_PYTHON_INSTALL_DIR}")
endif()
set(_file "$ENV{DESTDIR}${_dir}/coverage_axis/_install_path.py")
message(STATUS "Installing: ${_file}")
file(WRITE "${_file}" "\"\"\"_install_path.py: written by `cmake --install`: the installed shared library.\"\"\"\nLIBRARY = \"${CMAKE_INSTALL_PREFIX}/lib/${CA_LIBRARY_NAME}\"\n")
