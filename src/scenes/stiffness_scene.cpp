#include "src/scenes/stiffness_scene.hpp"

#include <cmath>
#include <limits>

#include "kernels/contact/geometry.hpp"
#include "src/error.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/study/key_reader.hpp"
#include "src/study/sections/ball_section.hpp"
#include "src/study/sections/flat_section.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

std::vector<KeySpec> stiffness_scene_keys() {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<KeySpec> k = {
      real_key("ball", "radius", "m", "ball radius R", std::string("0.02"), 0.0, inf, false),
      real_key("ball", "density", "kg/m^3", "ball density (weight = 4/3 pi R^3 rho g)", std::string("7850"), 0.0, inf,
               false),
      real_key("ball", "youngs_modulus", "Pa", "ball Young's modulus", std::string("210e9"), 0.0, inf, false),
      real_key("ball", "poisson", "-", "ball Poisson's ratio", std::string("0.3"), -1.0, 0.5, false, false),
      real_key("ball", "gravity", "m/s^2", "gravitational acceleration (for the ball's weight)", std::string("9.81"),
               0.0, inf),
      real_key("flat", "youngs_modulus", "Pa", "flat's Young's modulus", std::string("210e9"), 0.0, inf, false),
      real_key("flat", "poisson", "-", "flat's Poisson's ratio", std::string("0.3"), -1.0, 0.5, false, false),
  };
  for (auto& t : study::StiffnessSection::keys()) k.push_back(t);
  for (auto& t : texture_io::surface_keys()) k.push_back(t);
  for (auto& t : texture_io::psd_keys()) k.push_back(t);
  return k;
}

BallContact ball_contact_pair(const KeyReader& s, double other_modulus, double other_poisson) {
  const BallSection ball = BallSection::parse_solid(s);
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
  return {{"ball.radius", {}}, {"ball.density", {}},   {"ball.youngs_modulus", {}},    {"flat.youngs_modulus", {}},
          {"texture.rms", {}}, {"texture.hurst", {}},  {"stiffness.approach_max", {}}, {"stiffness.realisations", {}},
          {"surface.nx", {}},  {"surface.spacing", {}}};
}

}  // namespace rollspec::scenes
