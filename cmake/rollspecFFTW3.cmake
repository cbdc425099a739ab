# FFTW3 as imported targets: PkgConfig::FFTW3 (pkg-config fftw3) and FFTW3::fftw3_omp (its OpenMP
# threads library, which has no pkg-config file). Debian's libfftw3-dev ships no CMake package, so
# this file does the finding, for the build (CMakeLists.txt) and, installed beside it, for
# rollspecConfig.cmake. Needs PkgConfig found first. Leaves FFTW3::fftw3_omp undefined when either
# library is missing; the caller reports it.
pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
if(FFTW3_FOUND AND NOT TARGET FFTW3::fftw3_omp)
  find_library(FFTW3_OMP_LIB NAMES fftw3_omp HINTS ${FFTW3_LIBRARY_DIRS})
  if(FFTW3_OMP_LIB)
    add_library(FFTW3::fftw3_omp UNKNOWN IMPORTED)
    set_target_properties(FFTW3::fftw3_omp PROPERTIES
      IMPORTED_LOCATION "${FFTW3_OMP_LIB}"
      INTERFACE_LINK_LIBRARIES PkgConfig::FFTW3)
  endif()
endif()
