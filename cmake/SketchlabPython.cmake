# Finds Debian's Python with pybind11 and numpy, then builds python/ (the
# `sketchlab` module) and sets:
#   SKETCHLAB_HAVE_PYTHON         ON when found
#   SKETCHLAB_PYTHON_INSTALL_DIR  lib/python3.X/dist-packages: on sys.path of
#                                 Debian's python3 for the /usr/local prefix
#   SKETCHLAB_PYTHON_BUILD_DIR    <build>/python: PYTHONPATH for the build tree
# Debian's pybind11, numpy and pytest packages are for /usr/bin/python3, not
# for another python3 on PATH (pyenv): that one is the default here.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module Development.Embed NumPy)
if(Python3_FOUND)
  # Found after Python3, pybind11 uses it (its FindPython mode).
  find_package(pybind11 2.10 CONFIG)
endif()
if(Python3_FOUND AND pybind11_FOUND)
  set(SKETCHLAB_HAVE_PYTHON ON)
  set(SKETCHLAB_PYTHON_INSTALL_DIR
      ${CMAKE_INSTALL_LIBDIR}/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages)
  set(SKETCHLAB_PYTHON_BUILD_DIR ${CMAKE_BINARY_DIR}/python)
  add_subdirectory(${CMAKE_SOURCE_DIR}/python)
else()
  message(STATUS "sketchlab: Python module not built: needs python3-dev, pybind11-dev and "
                 "python3-numpy for ${Python3_EXECUTABLE} (scripts/setup.sh)")
endif()
