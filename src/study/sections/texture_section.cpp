#include "src/study/sections/texture_section.hpp"

#include <filesystem>

#include "src/study/sections/section_keys.hpp"

namespace rollspec::study {

namespace {
// Measured profiles are relative to the study file (not to a --set's directory).
std::vector<std::string> study_relative_files(const KeyReader& s, const std::string& key) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  for (const auto& f : s.list(key))
    out.push_back(fs::path(f).is_absolute() ? f : (fs::path(s.file()).parent_path() / f).string());
  return out;
}
}  // namespace

SectionKeys<TextureSection> TextureSection::declare() {
  using T = TextureSection;
  return SectionKeys<T>("texture")
      .section_if_present()
      .choice("source", &T::source, "where the roughness PSD comes from", TextureSource::self_affine, kTextureSources)
      .path("table", &T::table_path,
            "PSD table CSV: header wavenumber_rad_per_m or spatial_frequency_cycles_per_m, then psd_m3 or psd_um2_m",
            "none")
      .choice("table_extension", &T::table_extension, "PSD outside the table or measured band",
              texture::Extension::error, kTableExtensions)
      .text("profiles", &T::profile_paths,
            "measured scans, each used whole: comma-separated CSV files (position_m,height_m or height_um)", "",
            study_relative_files)
      .boolean("median_filter", &T::median_filter, "3-point median filter on measured profiles", "false")
      .real("hurst", &T::hurst, "-", "Hurst exponent H of the self-affine PSD", "0.8", {0.0, 1.0, false, true})
      .real("long_wavelength", &T::long_wavelength, "m", "long-wavelength cut-off (0: none)", "0", at_least(0.0))
      .real("rolloff_wavelength", &T::rolloff_wavelength, "m", "roll-off wavelength (plateau above it)", "1e-3",
            above(0.0))
      .real("short_wavelength", &T::short_wavelength, "m",
            "short-wavelength cut-off (with source = profiles: cuts the measured PSD, only where set)", "1e-5",
            above(0.0))
      .choice("rms_kind", &T::rms_kind, "what `rms` sets for the self-affine PSD", texture::RmsTarget::height,
              kRmsKinds)
      .real("rms", &T::rms, "m (height) or - (slope)", "rms height or rms slope of the self-affine PSD", "1e-6",
            above(0.0))
      .choice("road_class", &T::road_class, "ISO 8608 road class", 'A', kRoadClasses)
      .choice("amplitudes", &T::amplitudes, "harmonic amplitudes", spectral::Amplitudes::rayleigh, kAmplitudes);
}
template struct DeclaredSection<TextureSection>;

void TextureSection::finish() {
  present = !key_values().empty();
  has_table = present && value_text(table_path) != "none";
}

}  // namespace rollspec::study
