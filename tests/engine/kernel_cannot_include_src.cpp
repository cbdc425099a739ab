// Compiled with the kernels' include path only (tests/CMakeLists.txt): a kernel header resolves, an
// engine header must not. The test passes when the compiler reports exactly that.
#include "kernels/spectral/welch.hpp"
#include "src/error.hpp"
