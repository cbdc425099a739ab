#pragma once
// [surface]: grid and method of isotropic surfaces (spectral or seed), read once. Scenes without
// [surface] parse to present = false; count exists in the texture scene only (0 elsewhere).
#include <map>
#include <string>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class SurfaceMethod { spectral, seed };

inline constexpr ChoiceTable<SurfaceMethod, 2> kSurfaceMethods{{
    {SurfaceMethod::spectral, "spectral", "2D Fourier filter of the isotropic PSD"},
    {SurfaceMethod::seed, "seed", "seed 001 Eq. 9-10: sums of line textures"},
}};

struct SurfaceSection : DeclaredSection<SurfaceSection> {
  bool present = false;  // the scene has [surface]
  SurfaceMethod method = SurfaceMethod::spectral;
  long long nx = 128, ny = 128, count = 0;
  double spacing = 1e-6, anisotropy = 1.0, correlation_x = 1e-5, correlation_y = 1e-5, sigma = 3e-7;
  // The seed-method keys at their documented default (not set by the study or --set), which take
  // the measured profiles' values with [texture] source = profiles.
  bool sigma_default = true, correlation_x_default = true, correlation_y_default = true;
  bool spacing_set = false, ny_set = false;  // set by the study or --set (strip grids derive them otherwise)
  // The canonical value texts of the keys read (as the resolved study writes them), for the cached
  // tables' input texts (their hashes).
  std::map<std::string, std::string> texts;

  static std::vector<KeySpec> count_keys();  // [surface] count (texture scene)
  static SectionKeys<SurfaceSection> declare();
  void finish();  // present, the set flags and texts
};

}  // namespace rollspec::study
