// libFuzzer harness over study-file validation: rollspec::study::Study::load with the scene
// schemas (scenes::schema_for), as `rollspec run/plan/texture` call it.
//
// Input: leading lines "@section.key=value" are --set overrides; the rest is the study file,
// written to a temporary file (Study::load reads a path). Refusing an input with a UserError
// (exit 64/65/66/78 in the command) is the expected outcome; any other exception, a crash or a
// sanitizer report is a finding. A study that loads is read back through every typed accessor
// and the canonical text, as the scenes and the result provenance do.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "src/error.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"
#include "fuzz_temp_file.hpp"

namespace {

void read_back(const rollspec::study::Study& s) {
  using rollspec::study::KeyType;
  for (const auto& k : s.keys()) {
    const std::string name = k.full_name();
    switch (k.type) {
      case KeyType::real:
        (void)s.real(name);
        break;
      case KeyType::integer:
        (void)s.integer(name);
        break;
      case KeyType::boolean:
        (void)s.boolean(name);
        break;
      case KeyType::path:
        (void)s.path(name);
        break;
      case KeyType::choice:
      case KeyType::text:
        (void)s.text(name);
        break;
    }
    (void)s.where(name);
  }
  (void)s.canonical_text();
  (void)s.canonical_text_without({"study.realisations"});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  while (text.size() > 1 && text[0] == '@') {
    const auto nl = text.find('\n');
    overrides.push_back(text.substr(1, nl == std::string::npos ? std::string::npos : nl - 1));
    text = nl == std::string::npos ? std::string() : text.substr(nl + 1);
  }
  static const rollspec::fuzz::TempFile file("study", ".ini");
  file.write(text.data(), text.size());
  try {
    const auto s = rollspec::study::Study::load(file.path, overrides, rollspec::scenes::schema_for);
    read_back(s);
  } catch (const rollspec::UserError&) {
    // Refused with a message and a sysexits code: the expected outcome for bad input.
  }
  return 0;
}
