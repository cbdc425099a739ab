#pragma once
// [texture]: where the roughness PSD comes from (self-affine, table, measured profiles, ISO 8608,
// ISO 3095), its amplitudes and the extension beyond a table's band, read once. Scenes without
// [texture] parse to present = false.
#include <string>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/tabulated_psd.hpp"
#include "src/study/key_spec.hpp"
#include "src/study/sections/amplitudes_choice.hpp"
#include "src/study/sections/declared_section.hpp"

namespace rollspec::study {

class KeyReader;

enum class TextureSource { self_affine, table, profiles, iso8608, iso3095 };

inline constexpr ChoiceTable<TextureSource, 5> kTextureSources{{
    {TextureSource::self_affine, "self-affine", "hurst, the wavelengths and rms below"},
    {TextureSource::table, "table", "the PSD table CSV of `table`"},
    {TextureSource::profiles, "profiles", "estimated from the measured scans of `profiles`"},
    {TextureSource::iso8608, "iso8608", "the ISO 8608 PSD of `road_class`"},
    {TextureSource::iso3095, "iso3095", "the ISO 3095 rail roughness limit"},
}};
inline constexpr ChoiceTable<texture::Extension, 4> kTableExtensions{{
    {texture::Extension::error, "error", "a wavenumber outside is refused"},
    {texture::Extension::constant, "constant", "the end values"},
    {texture::Extension::power_law, "power_law", "the end segments' slopes continued"},
    {texture::Extension::zero, "zero", ""},
}};
inline constexpr ChoiceTable<texture::RmsTarget, 2> kRmsKinds{{
    {texture::RmsTarget::height, "height", ""},
    {texture::RmsTarget::slope, "slope", ""},
}};
// ISO 8608's road classes, as the letter its PSD takes.
inline constexpr ChoiceTable<char, 8> kRoadClasses{{
    {'A', "A", ""},
    {'B', "B", ""},
    {'C', "C", ""},
    {'D', "D", ""},
    {'E', "E", ""},
    {'F', "F", ""},
    {'G', "G", ""},
    {'H', "H", ""},
}};

struct TextureSection : DeclaredSection<TextureSection> {
  bool present = false;  // the scene has [texture]
  TextureSource source = TextureSource::self_affine;
  std::string table_path;  // usable from the current directory (its text: the table as written)
  bool has_table = false;  // table is a file, not "none"
  texture::Extension table_extension = texture::Extension::error;
  std::vector<std::string> profile_paths;  // [texture] profiles, relative to the study file
  bool median_filter = false;
  double hurst = 0.8, long_wavelength = 0.0, rolloff_wavelength = 1e-3, short_wavelength = 1e-5, rms = 1e-6;
  texture::RmsTarget rms_kind = texture::RmsTarget::height;
  char road_class = 'A';
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;

  static SectionKeys<TextureSection> declare();
  void finish();  // present, has_table
};

}  // namespace rollspec::study
