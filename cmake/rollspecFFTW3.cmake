# FFTW3 as the imported target PkgConfig::FFTW3 (pkg-config fftw3). Debian's libfftw3-dev ships no
# CMake package, so this file does the finding, for the build (CMakeLists.txt) and, installed beside
# it, for rollspecConfig.cmake. Needs PkgConfig found first. Leaves PkgConfig::FFTW3 undefined when
# the library is missing; the caller reports it.
pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
