#pragma once
// What the contact table stages (stiffness, blocked force, equivalent roughness, path table) take
// from a study, read once: their sections, where their files go (TableStore) and the texture they
// cut strips and surfaces from. Their random surfaces and strips draw from the tables' own streams
// keyed by ([stiffness] table_seed, index), never the study seed. The builders and the input texts (the tables' hashes)
// read this value only, never the study's keys.
#include <memory>
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

// The sections a table stage reads, parsed once (by the scene's sections or by TableStudy::parse).
struct TableSections {
  study::StiffnessSection stiffness;
  study::TextureSection texture;
  study::SurfaceSection surface;
  bool strips = false;          // the scene has the strip stages' sections (ball-on-beam)
  bool stiffness_table = true;  // a stiffness table is built (ball-on-beam: [contact] law = table or literal)
  study::BlockedForceSection blocked_force;
  study::EquivalentRoughnessSection equivalent_roughness;

  static TableSections parse(const study::KeyReader& s);
  // Whether a table reads the texture: a rough stiffness table or any strip stage.
  bool textured() const { return stiffness.rough || strips; }
};

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
  // A rough stiffness table's surface generator ([texture], and [surface] with the measured
  // profiles' values), made once here where a stiffness table is built; shared by the copies the
  // table stages keep.
  std::shared_ptr<const texture_io::SurfaceGenerator> surfaces;

  // From parsed sections and the PSD they describe (texture_io::study_psd; unused unless
  // sections.textured()); `s` gives the study's file, canonical text and input files only.
  static TableStudy of(const TableSections& sections, const texture::Psd& psd, const study::KeyReader& s);
  static TableStudy parse(const study::KeyReader& s);
};

}  // namespace rollspec::stiffness
