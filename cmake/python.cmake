# The Python module `gfield` (python/, docs/python.md): pybind11 (Debian pybind11-dev) against
# Debian's Python 3 (/usr/bin/python3, whose python3-numpy and python3-pytest the module's tests
# use; a pyenv or virtualenv python3 first on PATH may lack them: -DPython3_EXECUTABLE=... picks
# another). GFIELD_BUILD_PYTHON is AUTO (the default: built where pybind11 and Python's headers
# are found, looked for again at each configure, so installing them later turns it on), ON
# (required) or OFF; the module needs the preprocessing library, so builds without it (the fuzz
# build, the viewer alone) have no module.
#
# Sets GFIELD_BUILD_PYTHON to ON or OFF (a variable over the cache's choice) and, when ON,
# Python3_EXECUTABLE and GFIELD_INSTALL_PYTHON_DIR (the package's folder under the install prefix).
set(GFIELD_BUILD_PYTHON AUTO CACHE STRING
  "Build the Python module gfield: AUTO (where pybind11 and Python's headers are found), ON, OFF")
set_property(CACHE GFIELD_BUILD_PYTHON PROPERTY STRINGS AUTO ON OFF)
string(TOUPPER "${GFIELD_BUILD_PYTHON}" _python_wanted)
if(NOT GFIELD_BUILD_PREPROCESS)
  if(NOT _python_wanted STREQUAL "AUTO" AND GFIELD_BUILD_PYTHON)
    message(STATUS "GFIELD_BUILD_PREPROCESS=OFF: no Python module (it needs the gfield library)")
  endif()
  set(GFIELD_BUILD_PYTHON OFF)
  return()
endif()
if(NOT _python_wanted STREQUAL "AUTO" AND NOT GFIELD_BUILD_PYTHON)
  set(GFIELD_BUILD_PYTHON OFF)
  return()
endif()

if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
if(Python3_FOUND)
  # pybind11 uses the Python3 found above (its "new" FindPython mode).
  find_package(pybind11 CONFIG QUIET)
endif()
set(_python_found OFF)
if(Python3_FOUND AND pybind11_FOUND)
  set(_python_found ON)
endif()
if(_python_wanted STREQUAL "AUTO")
  if(NOT _python_found)
    message(STATUS "Python module: not built (no pybind11 or Python headers: Debian's "
      "pybind11-dev python3-dev; scripts/install-deps.sh)")
  endif()
elseif(NOT _python_found)
  message(FATAL_ERROR "GFIELD_BUILD_PYTHON=ON needs Python 3 with its headers and pybind11 "
    "(Debian: python3-dev pybind11-dev python3-numpy)")
endif()
set(GFIELD_BUILD_PYTHON ${_python_found})
if(GFIELD_BUILD_PYTHON)
  message(STATUS "Python module: ${Python3_EXECUTABLE} (${Python3_VERSION}), pybind11 "
    "${pybind11_VERSION}")
  # Debian's folder for Python packages of every python3 version (/usr/lib/python3/dist-packages
  # for the .deb, on sys.path of Debian's python3); under another prefix P, PYTHONPATH names it.
  set(GFIELD_INSTALL_PYTHON_DIR lib/python3/dist-packages CACHE STRING
    "Folder of the Python package gfield under the install prefix")
endif()
