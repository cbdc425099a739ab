#pragma once
// [texture]: where the roughness PSD comes from (self-affine, table, measured profiles, ISO 8608,
// ISO 3095), its amplitudes and the extension beyond a table's band, read once. Scenes without
// [texture] parse to present = false.
#include <string>
#include <utility>
#include <vector>

#include "src/study/key_spec.hpp"
#include "src/study/sections/key_origin.hpp"

namespace rollspec::study {

class KeyReader;

struct TextureSection {
  bool present = false;                    // the scene has [texture]
  std::string source;                      // self-affine, table, profiles, iso8608, iso3095
  std::string table;                       // as written ("none": not set)
  std::string table_path;                  // usable from the current directory
  std::string table_extension;             // error, constant, power_law, zero
  std::vector<std::string> profile_paths;  // [texture] profiles, relative to the study file
  bool median_filter = false;
  double hurst = 0.8, long_wavelength = 0.0, rolloff_wavelength = 1e-3, short_wavelength = 1e-5, rms = 1e-6;
  std::string rms_kind, road_class, amplitudes;
  KeyOrigin source_origin, table_extension_origin, profiles_origin, long_wavelength_origin, short_wavelength_origin,
      rms_origin;
  // The keys() in table order with their canonical value texts, for the cached tables' input texts.
  std::vector<std::pair<std::string, std::string>> texts;
  // The keys the study file or a --set gave a value (not their documented default), with where:
  // source = profiles refuses those that cannot act on measured profiles and cuts at short_wavelength
  // only when it is set.
  std::vector<std::pair<std::string, KeyOrigin>> set_keys;
  bool is_set(const std::string& key) const;

  static std::vector<KeySpec> keys();
  static TextureSection parse(const KeyReader& s);
};

}  // namespace rollspec::study
