#include "src/study/sections/study_seed_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

StudySeedSection StudySeedSection::parse(const KeyReader& s) {
  return {static_cast<std::uint64_t>(s.integer("study.seed"))};
}

}  // namespace rollspec::study
