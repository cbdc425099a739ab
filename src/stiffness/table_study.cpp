#include "src/stiffness/table_study.hpp"

#include <algorithm>

#include "src/ensemble/checkpoint.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::stiffness {

namespace {
bool has_section(const study::KeyReader& s, const std::string& section) {
  return std::any_of(s.keys().begin(), s.keys().end(), [&](const study::KeySpec& k) { return k.section == section; });
}
}  // namespace

TableStudy TableStudy::parse(const study::KeyReader& s) {
  TableStudy t;
  t.stiffness = study::StiffnessSection::parse(s);
  t.surface = study::StripSurfaceSection::parse(s);
  const bool strips = has_section(s, "blocked_force");
  if (strips) {
    t.blocked_force = study::BlockedForceSection::parse(s);
    t.equivalent_roughness = study::EquivalentRoughnessSection::parse(s);
  }
  t.store.study_file = s.file();
  t.store.study_text = s.canonical_text();
  t.store.seed = t.stiffness.table_seed;
  t.store.table_dir = t.stiffness.text("table_dir");
  t.store.table_origin = t.stiffness.table_origin;
  t.store.table_dir_origin = t.stiffness.table_dir_origin;
  t.store.inputs = s.input_files();
  for (const auto& p : texture_io::profile_files(s)) t.store.inputs.push_back(p);
  // A smooth stiffness study needs no texture (its PSD keys are never resolved).
  t.textured = t.stiffness.rough || strips;
  if (t.textured) {
    t.psd = texture_io::study_psd(s);
    t.amplitudes = texture_io::study_amplitudes(s);
    t.psd_fingerprint = hex16(ensemble::fnv1a64(texture_io::psd_input_fingerprint(s)));
    t.profile_derived_keys = texture_io::profile_derived_surface_keys(s);
  }
  if (t.stiffness.rough) {
    t.texture = study::TextureSection::parse(s);
    t.surface_generator = texture_io::with_profile_values(t.texture, study::SurfaceSection::parse(s));
  }
  return t;
}

}  // namespace rollspec::stiffness
