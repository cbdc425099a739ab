#pragma once
// The draws rollspec.surfaces.line/isotropic (a PSD table) and ProfilePsd.line/isotropic (measured
// profiles) share: the engine's generators on `rollspec texture`'s streams for (seed, index), so the
// same PSD and keys give the command's bits, and the dicts they return. Defined in surface_bindings.cpp.
#include <optional>
#include <string>

#include "kernels/texture/psd.hpp"
#include "python/bindings.hpp"

namespace rollspec::python {

// [surface]'s key `name`, checked against its range as a study's value is (ValueError naming it).
double surface_key(const std::string& name, double value);
// A grid side nx or ny: in [surface]'s range and even.
std::size_t even_side(const std::string& name, long long n);

// Line `index` of the line texture generator (D-3) of `psd`: heights, spacing, harmonics, target PSD
// and rms, period, seed, index. `refused_as` prefixes the generator's refusals (ValueError).
py::dict draw_line(const texture::Psd& psd, double spacing, long long samples, unsigned long long seed,
                   unsigned long long index, const std::string& amplitudes, const std::string& refused_as);

// The keys of an isotropic surface; sigma and the correlation lengths are the seed method's, checked
// by the caller (a table's are keys, measured profiles' may be their own estimates).
struct IsotropicDraw {
  double spacing = 0.0;
  long long nx = 0;
  std::optional<long long> ny;
  unsigned long long seed = 0, index = 0;
  std::string method, amplitudes;
  double anisotropy = 1.0, sigma = 0.0, correlation_x = 0.0, correlation_y = 0.0;
};

// Surface `index` of the spectral (D-5) or seed line-sum (D-4) generator of `psd`: heights (ny x nx),
// spacing, method, target rms (spectral) or the boxes and expected correlation lengths (seed), seed,
// index. `refused_as` prefixes the generator's refusals (ValueError).
py::dict draw_isotropic(const texture::Psd& psd, const IsotropicDraw& k, const std::string& refused_as);

}  // namespace rollspec::python
