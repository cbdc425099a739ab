#include "src/study/sections/pipe_roughness_section.hpp"

#include "src/study/key_reader.hpp"

namespace rollspec::study {

PipeRoughnessSection PipeRoughnessSection::parse(const KeyReader& s) {
  PipeRoughnessSection r;
  r.line = s.text("roughness.kind") == "line";
  return r;
}

}  // namespace rollspec::study
