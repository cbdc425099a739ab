# The Python module rollspec (python/CMakeLists.txt), when ROLLSPEC_PYTHON_MODULE is on and Debian's
# pybind11-dev and python3-dev are there: sets ROLLSPEC_PYTHON_MODULE_BUILT. Found here, before the
# kernels and the engine are defined, because the module links their static libraries into a shared
# object: rollspec_library_pic(TARGET) then compiles a library position-independent (-fPIC instead of
# Debian's default -fPIE; -fno-semantic-interposition keeps the inlining -fPIE allows, so the command's
# code and its numbers stay as they were).
set(ROLLSPEC_PYTHON_MODULE_BUILT OFF)
if(ROLLSPEC_PYTHON_MODULE)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)  # Debian's, with numpy; not the first python3 on PATH
  endif()
  find_package(Python 3 COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    find_package(pybind11 2.6 CONFIG)
  endif()
  if(Python_FOUND AND pybind11_FOUND)
    set(ROLLSPEC_PYTHON_MODULE_BUILT ON)
  else()
    message(STATUS "Python module rollspec: not built (needs pybind11-dev and python3-dev)")
  endif()
endif()

function(rollspec_library_pic target)
  if(ROLLSPEC_PYTHON_MODULE_BUILT)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  endif()
endfunction()
