#include "src/scenes/rolling_beam/rolling_beam.hpp"
#include "src/scenes/rolling_beam/rolling_beam_settings.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "kernels/rolling/examples.hpp"
#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::scenes {

using namespace study;
using Eigen::Vector3d;

namespace {

class RollingBeam final : public SingleRunScene {
 public:
  explicit RollingBeam(const KeyReader& s) : r_(read_rolling_beam_settings(s)) {
    add_stages(fixed_stages());  // after the members the descriptions name
  }

  std::vector<StagePlan> fixed_stages() const {
    return {
        {"texture", StageStatus::skipped, "flat rigid plane"},
        {"stiffness_table", StageStatus::skipped, "penalty contact"},
        {"dynamics", StageStatus::run,
         std::string(r_.solver.analysis == rolling::Analysis::Dynamic ? "Newmark dynamics"
                                                                      : "quasi-static load steps") +
             ", " + std::to_string(static_cast<long long>(std::llround(r_.run.t_end / r_.run.dt))) + " steps, " +
             io::counted(r_.model.contacts.size(), "rolling contact node")},
        {"spectra", StageStatus::skipped, "a single deterministic run has no ensemble spectra"},
    };
  }

  void run(bool quiet) override {
    history_ = rolling::run(r_.model, r_.solver, r_.run);
    if (!history_.completed)
      throw data_error(
          r_.step_where + ": Newton did not converge at t = " + std::to_string(history_.failed_at) + " s even after " +
          std::to_string(r_.solver.max_cuts) +
          " step halvings; reduce the step, raise [analysis] max_iterations or max_cuts, or soften the penalties");
    if (!quiet)
      std::fprintf(stderr, "rolling-beam: %d steps, %d Newton iterations, %d step cuts\n", history_.steps,
                   history_.newton_iterations, history_.cuts);
  }

  void write_results(io::Hdf5Writer& w) const override {
    const auto& h = history_;
    const std::size_t nt = h.time.size(), nn = r_.record.size(), nc = r_.model.contacts.size();
    auto block = [&](const std::vector<std::vector<Vector3d>>& v) {
      std::vector<double> out(nt * nn * 3);
      for (std::size_t t = 0; t < nt; ++t)
        for (std::size_t n = 0; n < nn; ++n)
          for (int k = 0; k < 3; ++k) out[(t * nn + n) * 3 + static_cast<std::size_t>(k)] = v[t][n](k);
      return out;
    };
    w.write("/time_history/time", {nt}, h.time.data(), "s", "time of each recorded state");
    w.make_scale("/time_history/time", "time");
    const struct {
      const char* name;
      const std::vector<std::vector<Vector3d>>* data;
      const char* units;
      const char* what;
    } fields[] = {{"position", &h.position, "m", "node positions"},
                  {"velocity", &h.velocity, "m/s", "node velocities"},
                  {"acceleration", &h.acceleration, "m/s^2", "node accelerations"},
                  {"angular_velocity", &h.angular_velocity, "rad/s", "node angular velocities (spatial)"}};
    for (const auto& f : fields) {
      const auto v = block(*f.data);
      w.write(std::string("/time_history/") + f.name, {nt, nn, 3}, v.data(), f.units, f.what);
      w.attach_scale(std::string("/time_history/") + f.name, "/time_history/time", 0);
    }
    std::vector<double> rot(nt * nn * 9);
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t n = 0; n < nn; ++n)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            rot[((t * nn + n) * 3 + static_cast<std::size_t>(i)) * 3 + static_cast<std::size_t>(j)] =
                h.rotation[t][n](i, j);
    w.write("/time_history/rotation", {nt, nn, 3, 3}, rot.data(), "1",
            "node rotation matrices Q (columns: the node's frame vectors e1, e2, e3 in space)");
    w.attach_scale("/time_history/rotation", "/time_history/time", 0);
    std::vector<double> nodes(r_.record.begin(), r_.record.end());
    w.write("/time_history/node", {nn}, nodes.data(), "1", "model node index of each recorded node");
    // Energies (seed 000 §4; kernels/rolling README R-43).
    const struct {
      const char* name;
      double rolling::Energies::*member;
      const char* what;
    } energies[] = {{"kinetic", &rolling::Energies::kinetic, "kinetic energy, translation and rotation"},
                    {"strain", &rolling::Energies::strain, "beam strain energy"},
                    {"penalty", &rolling::Energies::penalty, "normal penalty energy eps_n g_n^2 / 2"},
                    {"tangential_elastic", &rolling::Energies::tangential_elastic, "energy in the stick springs"},
                    {"external_work", &rolling::Energies::external_work, "work of gravity and nodal loads"},
                    {"imposed_work", &rolling::Energies::imposed_work, "work of the reactions at imposed DOFs"},
                    {"friction_work", &rolling::Energies::friction_work, "mechanical energy removed by friction"},
                    {"friction_dissipation", &rolling::Energies::friction_dissipation,
                     "return-mapping dissipation sum f_max |slip increment|"}};
    for (const auto& e : energies) {
      std::vector<double> v(nt);
      for (std::size_t t = 0; t < nt; ++t) v[t] = h.energy[t].*e.member;
      w.write(std::string("/time_history/energy/") + e.name, {nt}, v.data(), "J", e.what);
    }
    std::vector<double> balance(nt);
    for (std::size_t t = 0; t < nt; ++t) balance[t] = h.energy[t].balance() - h.energy[0].balance();
    w.write("/time_history/energy/balance_error", {nt}, balance.data(), "J",
            "kinetic + strain + penalty - external work - imposed work + friction work, minus its initial value");
    // Contacts.
    std::vector<double> force(nt * nc * 3), moment(nt * nc * 3), slip(nt * nc), active(nt * nc), gap(nt * nc);
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t c = 0; c < nc; ++c) {
        const auto& o = h.contact[t][c];
        for (int k = 0; k < 3; ++k) {
          force[(t * nc + c) * 3 + static_cast<std::size_t>(k)] = o.force(k);
          moment[(t * nc + c) * 3 + static_cast<std::size_t>(k)] = o.moment(k);
        }
        slip[t * nc + c] = o.slip ? 1.0 : 0.0;
        active[t * nc + c] = o.active ? 1.0 : 0.0;
        gap[t * nc + c] = o.g_n;
      }
    w.write("/time_history/contact/force", {nt, nc, 3}, force.data(), "N",
            "contact force on the node (normal + friction)");
    w.write("/time_history/contact/moment", {nt, nc, 3}, moment.data(), "N m",
            "friction moment (C - x_o) x f on the node");
    w.write("/time_history/contact/slip", {nt, nc}, slip.data(), "1", "1 while the contact slips, 0 while it sticks");
    w.write("/time_history/contact/active", {nt, nc}, active.data(), "1", "1 while in contact");
    w.write("/time_history/contact/normal_gap", {nt, nc}, gap.data(), "m", "normal gap g_n (negative: penetration)");
    std::vector<double> cnode, cplane;
    for (const auto& c : r_.model.contacts) cnode.push_back(c.node), cplane.push_back(c.plane);
    w.write("/time_history/contact/node", {nc}, cnode.data(), "1", "model node index of each contact");
    w.write("/time_history/contact/plane", {nc}, cplane.data(), "1",
            "plane index of each contact (order of [plane] point)");
    if (!r_.model.imposed.empty()) {
      const std::size_t ni = r_.model.imposed.size();
      std::vector<double> r(nt * ni);
      for (std::size_t t = 0; t < nt; ++t)
        for (std::size_t i = 0; i < ni; ++i) r[t * ni + i] = h.reactions[t][i];
      w.write("/time_history/reaction", {nt, ni}, r.data(), "N", "reactions at the imposed DOFs (support order)");
    }
    w.attribute("/time_history", "steps", static_cast<std::int64_t>(h.steps));
    w.attribute("/time_history", "newton_iterations", static_cast<std::int64_t>(h.newton_iterations));
    w.attribute("/time_history", "step_cuts", static_cast<std::int64_t>(h.cuts));
    w.attribute("/time_history", "substeps", static_cast<std::int64_t>(h.substeps));
    w.attribute("/time_history", "limited_steps", static_cast<std::int64_t>(h.limited_steps));
    w.attribute("/time_history", "penetration_cuts", static_cast<std::int64_t>(h.penetration_cuts));
  }

 private:
  RollingBeamSettings r_;
  rolling::History history_;
};

}  // namespace

std::unique_ptr<Scene> make_rolling_beam(const KeyReader& s) { return std::make_unique<RollingBeam>(s); }

}  // namespace rollspec::scenes
