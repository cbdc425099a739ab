#include "src/scenes/stiffness/stiffness_scene.hpp"

#include <cmath>

#include "kernels/contact/geometry.hpp"
#include "src/error.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/flat_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/texture/texture_keys.hpp"
#include "src/study/sections/surface_section.hpp"
#include "src/study/sections/texture_section.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> stiffness_scene_keys() {
  return joined_keys({BallSection::solid_keys(), FlatSection::keys(), StiffnessSection::keys(),
                      texture_io::surface_keys(), texture_io::psd_keys()});
}

BallContact ball_contact_pair(const KeyReader& s, double other_modulus, double other_poisson) {
  const BallSection ball = BallSection::parse(s);
  BallContact p{};
  p.radius = ball.radius;
  p.effective_modulus = ball.effective_modulus(other_modulus, other_poisson);
  p.weight = 4.0 / 3.0 * M_PI * std::pow(p.radius, 3) * ball.density * ball.gravity;
  return p;
}

BallContact stiffness_contact_pair(const KeyReader& s) {
  const FlatSection flat = FlatSection::parse(s);
  return ball_contact_pair(s, flat.youngs_modulus, flat.poisson);
}

namespace {
class StiffnessScene final : public Scene {
 public:
  explicit StiffnessScene(const KeyReader& s)
      : pair_(stiffness_contact_pair(s)), tables_(stiffness::TableStudy::parse(s)) {
    const bool rough = tables_.stiffness.rough;  // a rough flat's PSD source is validated by the parse
    // `rollspec stiffness` builds and prints the table through stiffness::resolve_table, the same
    // CachedTable, so this stage and that command agree.
    const BallContact pair = pair_;
    auto table = std::make_unique<TableStage>(
        "stiffness_table", stiffness::stiffness_cached_table(tables_, pair.radius, pair.effective_modulus),
        [] { return std::make_unique<stiffness::StiffnessTable>(); },
        [this, pair](stiffness::TableData& out, bool quiet) {
          static_cast<stiffness::StiffnessTable&>(out) =
              stiffness::build_table(tables_, pair.radius, pair.effective_modulus, quiet);
        },
        [](const stiffness::TableData&, const std::string&, bool) {});
    const TableStage* t = table.get();
    add_stage(std::make_unique<DerivedStage>([t, rough] {
      const bool valid = t->state() == stiffness::TableState::valid;
      return StagePlan{"surface", valid || !rough ? StageStatus::skipped : StageStatus::run,
                       !rough  ? "smooth flat ([stiffness] surface = smooth)"
                       : valid ? "inside the cached table"
                               : "isotropic surfaces ([surface], [texture]) per table realisation"};
    }));
    add_stage(std::move(table));
    add_stages({{"dynamics", StageStatus::skipped, "the scene has no dynamics"},
                {"spectra", StageStatus::skipped, "the scene has no sensors"}});
  }

 private:
  BallContact pair_;
  stiffness::TableStudy tables_;
};
}  // namespace

std::unique_ptr<Scene> make_stiffness_scene(const KeyReader& s) { return std::make_unique<StiffnessScene>(s); }

std::vector<FirstKey> stiffness_first_keys() {
  return {first_key(&BallSection::radius),
          first_key(&BallSection::density),
          first_key(&BallSection::youngs_modulus),
          first_key(&FlatSection::youngs_modulus),
          first_key(&TextureSection::rms),
          first_key(&TextureSection::hurst),
          first_key(&StiffnessSection::approach_max),
          first_key(&StiffnessSection::realisations),
          first_key(&SurfaceSection::nx),
          first_key(&SurfaceSection::spacing)};
}

}  // namespace rollspec::scenes
