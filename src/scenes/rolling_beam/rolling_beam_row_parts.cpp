// What scene `rolling-beam`'s registry row (scene_registry.cpp) names besides its class and keys: its memory
// model and the references a run cites.
#include <cmath>

#include "kernels/rolling/solver.hpp"
#include "src/scenes/dimension_plausibility.hpp"
#include "src/scenes/memory_terms.hpp"
#include "src/scenes/rolling_beam/rolling_beam.hpp"
#include "src/scenes/rolling_beam/rolling_beam_settings.hpp"
#include "src/study/key_reader.hpp"

namespace rollspec::scenes {

namespace {

using Item = MemoryItem;

// rolling-beam keeps every recorded state (positions, velocities, accelerations, angular
// velocities and accelerations, rotations; contacts; energies) and copies one field at the write;
// the Newton system is a band matrix of 6 dofs per node.
std::vector<Item> rolling_beam(const RollingBeamSettings& r) {
  const double nodes = static_cast<double>(r.model.X.size()), nn = static_cast<double>(r.record.size());
  const double nc = static_cast<double>(r.model.contacts.size());
  const double records = std::floor(r.run.t_end / r.run.dt / std::max(r.run.record_every, 1)) + 2.0;
  // Nine per-record vectors, each a 24-byte header and a heap block (about 24 bytes of overhead).
  const double per_record = nn * (5.0 * 24.0 + 72.0) + 9.0 * 48.0 +
                            nc * static_cast<double>(sizeof(rolling::ContactOutput)) +
                            static_cast<double>(sizeof(rolling::Energies)) + 8.0;
  const double write_copy = records * (nn * 72.0 + nc * 9.0 * 8.0);
  std::vector<std::string> elements;
  if (r.elements > 0) elements.push_back(key_text("beam", "elements", static_cast<double>(r.elements)));
  std::vector<std::string> history = {key_text("analysis", "dt", r.run.dt), key_text("analysis", "t_end", r.run.t_end),
                                      key_text("analysis", "record_every", static_cast<double>(r.run.record_every)),
                                      "[output] nodes (" + std::to_string(r.record.size()) + " recorded)"};
  for (const auto& e : elements) history.push_back(e);
  return {{records * per_record + write_copy, history,
           "time history, " + std::to_string(static_cast<long long>(records)) + " recorded states of " +
               std::to_string(static_cast<long long>(nn)) + " nodes"},
          {nodes * 6.0 * 8.0 * 400.0, elements,
           "beam model and its band Newton system, " + std::to_string(static_cast<long long>(nodes)) + " nodes"}};
}

}  // namespace

std::vector<MemoryItem> rolling_beam_memory(const study::KeyReader& s, int /*threads*/) {
  return rolling_beam(read_rolling_beam_settings(s));
}

std::vector<std::string> rolling_beam_references(const study::KeyReader&) { return {"seed 000", "D-12..D-14"}; }

}  // namespace rollspec::scenes
