#include "src/study/sections/texture_section.hpp"

#include <filesystem>
#include <limits>

#include "src/study/key_reader.hpp"
#include "src/study/sections/choice_read.hpp"

namespace rollspec::study {

std::vector<KeySpec> TextureSection::keys() {
  const double inf = std::numeric_limits<double>::infinity();
  return {
      choice_key("texture", "source", "where the roughness PSD comes from", TextureSource::self_affine,
                 kTextureSources),
      path_key("texture", "table",
               "PSD table CSV: header wavenumber_rad_per_m or spatial_frequency_cycles_per_m, then psd_m3 or psd_um2_m",
               std::string("none")),
      choice_key("texture", "table_extension", "PSD outside the table or measured band", texture::Extension::error,
                 kTableExtensions),
      text_key("texture", "profiles",
               "measured scans, each used whole: comma-separated CSV files (position_m,height_m or height_um)",
               std::string("")),
      bool_key("texture", "median_filter", "3-point median filter on measured profiles", std::string("false")),
      real_key("texture", "hurst", "-", "Hurst exponent H of the self-affine PSD", std::string("0.8"), 0.0, 1.0, false,
               true),
      real_key("texture", "long_wavelength", "m", "long-wavelength cut-off (0: none)", std::string("0"), 0.0, inf),
      real_key("texture", "rolloff_wavelength", "m", "roll-off wavelength (plateau above it)", std::string("1e-3"), 0.0,
               inf, false),
      real_key("texture", "short_wavelength", "m",
               "short-wavelength cut-off (with source = profiles: cuts the measured PSD, only where set)",
               std::string("1e-5"), 0.0, inf, false),
      choice_key("texture", "rms_kind", "what `rms` sets for the self-affine PSD", texture::RmsTarget::height,
                 kRmsKinds),
      real_key("texture", "rms", "m (height) or - (slope)", "rms height or rms slope of the self-affine PSD",
               std::string("1e-6"), 0.0, inf, false),
      choice_key("texture", "road_class", "ISO 8608 road class", 'A', kRoadClasses),
      choice_key("texture", "amplitudes", "harmonic amplitudes", spectral::Amplitudes::rayleigh, kAmplitudes),
  };
}

TextureSection TextureSection::parse(const KeyReader& s) {
  TextureSection t;
  if (!s.has("texture.source")) return t;
  t.present = true;
  t.source = read_choice(s, "texture.source", kTextureSources);
  t.table = s.text("texture.table");
  t.has_table = t.table != "none";
  t.table_path = s.path("texture.table");
  t.table_extension = read_choice(s, "texture.table_extension", kTableExtensions);
  // Profiles are relative to the study file (not to a --set's directory).
  for (const auto& f : s.list("texture.profiles")) {
    namespace fs = std::filesystem;
    t.profile_paths.push_back(fs::path(f).is_absolute() ? f : (fs::path(s.file()).parent_path() / f).string());
  }
  t.median_filter = s.boolean("texture.median_filter");
  t.hurst = s.real("texture.hurst");
  t.long_wavelength = s.real("texture.long_wavelength");
  t.rolloff_wavelength = s.real("texture.rolloff_wavelength");
  t.short_wavelength = s.real("texture.short_wavelength");
  t.rms_kind = read_choice(s, "texture.rms_kind", kRmsKinds);
  t.rms = s.real("texture.rms");
  t.road_class = read_choice(s, "texture.road_class", kRoadClasses);
  t.amplitudes = read_choice(s, "texture.amplitudes", kAmplitudes);
  t.source_origin = {s.where("texture.source")};
  t.table_extension_origin = {s.where("texture.table_extension")};
  t.profiles_origin = {s.where("texture.profiles")};
  t.long_wavelength_origin = {s.where("texture.long_wavelength")};
  t.short_wavelength_origin = {s.where("texture.short_wavelength")};
  t.rms_origin = {s.where("texture.rms")};
  for (const auto& k : keys()) {
    t.texts.emplace_back(k.key, s.text(k.full_name()));
    if (s.is_set(k.full_name())) t.set_keys.emplace_back(k.key, KeyOrigin{s.where(k.full_name())});
  }
  return t;
}

bool TextureSection::is_set(const std::string& key) const {
  for (const auto& [k, origin] : set_keys)
    if (k == key) return true;
  return false;
}

}  // namespace rollspec::study
