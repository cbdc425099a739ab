#pragma once
// What the contact table stages (stiffness, blocked force, equivalent roughness, path table) take
// from a study, read once: their sections, where their files go (TableStore) and the texture they
// cut strips and surfaces from. Their random surfaces and strips draw from the tables' own streams
// keyed by ([stiffness] table_seed, index), never the study seed. The builders and the input texts (the tables' hashes)
// read this value only, never the study's keys.
#include <string>
#include <vector>

#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/texture/psd.hpp"
#include "src/stiffness/cached_table.hpp"
#include "src/study/sections/blocked_force_section.hpp"
#include "src/study/sections/equivalent_roughness_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/study/sections/strip_surface_section.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::stiffness {

struct TableStudy {
  TableStore store;
  study::StiffnessSection stiffness;
  study::StripSurfaceSection surface;
  // The strip stages' sections (scene ball-on-beam; defaults elsewhere).
  study::BlockedForceSection blocked_force;
  study::EquivalentRoughnessSection equivalent_roughness;
  // The texture, resolved where a table uses it (rough stiffness tables, every strip stage).
  bool textured = false;
  texture::Psd psd;
  spectral::Amplitudes amplitudes = spectral::Amplitudes::rayleigh;
  std::string psd_fingerprint;                    // 16 hex digits over the PSD's input files
  std::vector<std::string> profile_derived_keys;  // texture_io::profile_derived_surface_keys
  // The [texture] and [surface] sections of a rough stiffness table's surface generator.
  study::TextureSection texture;
  study::SurfaceSection surface_generator;

  static TableStudy parse(const study::KeyReader& s);
};

}  // namespace rollspec::stiffness
