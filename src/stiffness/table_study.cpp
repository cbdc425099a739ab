#include "src/stiffness/table_study.hpp"

#include <algorithm>

#include "src/io/content_hash.hpp"
#include "src/stiffness/table_text.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::stiffness {

namespace {
bool has_section(const study::KeyReader& s, const std::string& section) {
  return std::any_of(s.keys().begin(), s.keys().end(), [&](const study::KeySpec& k) { return k.section == section; });
}
}  // namespace

TableSections TableSections::parse(const study::KeyReader& s) {
  TableSections t;
  t.stiffness = study::StiffnessSection::parse(s);
  t.texture = study::TextureSection::parse(s);
  t.surface = study::SurfaceSection::parse(s);
  t.strips = has_section(s, "blocked_force");
  if (t.strips) {
    t.blocked_force = study::BlockedForceSection::parse(s);
    t.equivalent_roughness = study::EquivalentRoughnessSection::parse(s);
  }
  return t;
}

TableStudy TableStudy::of(const TableSections& sections, const texture::Psd& psd, const study::KeyReader& s) {
  TableStudy t;
  t.stiffness = sections.stiffness;
  t.surface = study::StripSurfaceSection::of(sections.surface, sections.texture);
  t.blocked_force = sections.blocked_force;
  t.equivalent_roughness = sections.equivalent_roughness;
  t.store.study_file = s.file();
  t.store.study_text = s.canonical_text();
  t.store.seed = t.stiffness.table_seed;
  t.store.table_dir = t.stiffness.table_dir;
  t.store.table_origin = t.stiffness.origin(t.stiffness.table);
  t.store.table_dir_origin = t.stiffness.origin(t.stiffness.table_dir);
  t.store.inputs = s.input_files();
  for (const auto& p : texture_io::profile_files(sections.texture)) t.store.inputs.push_back(p);
  // A smooth stiffness study needs no texture (its PSD keys are never resolved).
  t.textured = sections.textured();
  if (t.textured) {
    t.psd = psd;
    t.amplitudes = texture_io::study_amplitudes(sections.texture);
    t.psd_fingerprint = io::hex16(io::fnv1a64(texture_io::psd_input_fingerprint(sections.texture)));
    t.profile_derived_keys = texture_io::profile_derived_surface_keys(sections.texture, sections.surface);
  }
  if (t.stiffness.rough && sections.stiffness_table)
    t.surfaces = std::make_shared<const texture_io::SurfaceGenerator>(texture_io::surface_generator(
        sections.texture, texture_io::with_profile_values(sections.texture, sections.surface), psd));
  return t;
}

TableStudy TableStudy::parse(const study::KeyReader& s) {
  const TableSections sections = TableSections::parse(s);
  return of(sections, sections.textured() ? texture_io::study_psd(sections.texture) : texture::Psd{}, s);
}

}  // namespace rollspec::stiffness
