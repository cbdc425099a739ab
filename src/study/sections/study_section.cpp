#include "src/study/sections/study_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

StudySection StudySection::parse(const KeyReader& s) {
  StudySection t;
  t.scene = s.scene();
  t.description = s.text("study.description");
  t.realisations = s.integer("study.realisations");
  t.seed = static_cast<std::uint64_t>(s.integer("study.seed"));
  t.seed_text = s.text("study.seed");
  t.scene_origin = {s.where("study.scene")};
  return t;
}

}  // namespace rollspec::study
