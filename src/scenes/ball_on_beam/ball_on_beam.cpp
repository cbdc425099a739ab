#include "src/scenes/ball_on_beam/ball_on_beam_scene.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "kernels/beam/dopri5_reference.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/run_warning.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_writer.hpp"
#include "src/study/key_reader.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

BallOnBeam::BallOnBeam(const BallOnBeamSections& s)
    : b_(read_ball_on_beam_settings(s)), contact_(contact_from_settings(b_)) {
  for (const auto& w : b_.warnings) io::warn(w);
  lines_ = texture_io::line_generator(b_.line_keys, b_.line_psd, b_.spacing, b_.line_samples);
  welch_ = std::make_unique<spectral::WelchPlan>(b_.welch);
  rows_ = std::make_unique<PsdRows>(numbered_sensors(b_.model.sensors.size()), b_.sensor_mean, welch_->frequencies(),
                                    b_.band_min, b_.band_max, 2 * welch_->n_freq() + 1);
  for (int t = 0; t < ensemble::ensemble_threads(); ++t)
    workspaces_.push_back(std::make_unique<BallOnBeamWorkspace>(b_.welch.segment));
  add_pipeline_stages(s.tables);
  table_error_.table = random_tables();
  if (b_.stiffness.table_jackknife) check_table_jackknife();
  check_blocked_force_leave_out();
  if (blocked_solver())
    if (const std::string w = blocked_force_resolution_warning(b_, blocked_force_grid()); !w.empty()) io::warn(w);
  if (jackknifes_stiffness_table()) tables_ = s.tables;
  if (solver_filter() && !b_.strip_line) filter_tables_ = s.tables;
}

// Simulates realisation `id` into ws.result (shared by the ensemble and the time-history output).
void BallOnBeam::simulate(std::uint64_t id, int thread, BallOnBeamWorkspace& ws) const {
  beam::Realisation r;
  excitation_->fill(id, thread, r);
  if (b_.dopri) {
    beam::ReferenceTolerances tol;
    tol.rtol = b_.rtol;
    ws.result = beam::simulate_dopri5(*model_, r, tol);
  } else {
    integrator_->run(r, ws.result);
  }
}

void BallOnBeam::run_realisation(std::uint64_t id, int thread, double* values) const {
  BallOnBeamWorkspace& ws = *workspaces_[static_cast<std::size_t>(thread)];
  simulate(id, thread, ws);
  const std::size_t nf = welch_->n_freq(), ns = b_.model.sensors.size(), n = ws.result.samples() - b_.skip;
  for (std::size_t s = 0; s < ns; ++s)
    welch_->psd(ws.result.sensor_acceleration[s].data() + b_.skip, n, rows_->row(values, s), ws.welch);
  rows_->finish(values);
  double* x = rows_->extras(values);
  welch_->psd(ws.result.contact_force.data() + b_.skip, n, x, ws.welch);
  welch_->psd(ws.result.ball_acceleration.data() + b_.skip, n, x + nf, ws.welch);
  x[2 * nf] = ws.result.loss_of_contact_share;
}

void BallOnBeam::write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const {
  BallOnBeamWriter(b_, contact_, *welch_, *rows_, lines_->fundamental(), quiet_)
      .write(w, sums, table_error_, spectra_only_, loss_effect_);
  if (b_.time_histories && !spectra_only_) write_time_histories(w, sums.only);  // re-simulates: not for a fit
}

io::PsdEnsemble BallOnBeam::spectra(const ensemble::EnsembleSums& sums) const {
  return BallOnBeamWriter(b_, contact_, *welch_, *rows_, lines_->fundamental(), quiet_).spectra(sums);
}

TableJackknifePlan BallOnBeam::table_jackknife() const {
  if (jackknifes_stiffness_table())
    return {static_cast<std::size_t>(b_.stiffness.realisations), "stiffness table", "surfaces",
            &study::StiffnessSection::leave_out_sets};
  if (blocked_solver()) {  // D-30d: over the overlapping Welch segments of F0 along the path
    const stiffness::SegmentJackknife j = stiffness::f0_segments(blocked_force_grid());
    TableJackknifePlan plan{j.segments, "blocked-force table", "Welch segments of F0", [](long long i) {
                              return std::vector<std::string>{
                                  study::BlockedForceSection::leave_out_setting(i),
                                  study::StiffnessSection::table_error_setting(study::TableError::none)};
                            }};
    plan.variance_factor = j.variance_factor;
    plan.dof = j.dof;
    plan.independent_bands = true;
    return plan;
  }
  TableJackknifePlan plan{static_cast<std::size_t>(b_.equivalent_roughness_strips), "equivalent-roughness table",
                          "strips", [](long long i) {
                            return std::vector<std::string>{
                                study::EquivalentRoughnessSection::leave_out_setting(i),
                                study::StiffnessSection::table_error_setting(study::TableError::none)};
                          }};
  plan.independent_bands = true;
  return plan;
}

// D-35: the linearised law assumes a closed contact; where the run lost it, the same realisations run
// again with one that never opens size what that moved.
std::vector<std::string> BallOnBeam::closed_contact_sets(const ensemble::EnsembleSums& sums) const {
  if (!b_.linearised() || b_.contact_section.loss == study::ContactLoss::closed || spectra_only_) return {};
  if (!(sums.mean(rows_->extra_index(2 * welch_->n_freq())) > 0.0)) return {};
  return {study::ContactSection::loss_setting(study::ContactLoss::closed),
          study::StiffnessSection::table_error_setting(study::TableError::none)};
}

// Realisations 0..n-1 again (deterministic: same Philox keys), so histories survive --resume;
// with --only, the history of that one realisation.
void BallOnBeam::write_time_histories(io::Hdf5Writer& w, std::int64_t only) const {
  BallOnBeamWorkspace& ws = *workspaces_[0];
  const std::size_t n = b_.samples, ns = b_.model.sensors.size(), nh = only >= 0 ? 1 : b_.time_histories;
  std::vector<double> t(n), acc(nh * ns * n), force(nh * n), ball(nh * n), delta(nh * n);
  for (std::size_t j = 0; j < n; ++j) t[j] = static_cast<double>(j) / b_.model.sample_rate;
  for (std::size_t r = 0; r < nh; ++r) {
    simulate(only >= 0 ? static_cast<std::uint64_t>(only) : r, 0, ws);
    for (std::size_t s = 0; s < ns; ++s)
      std::copy(ws.result.sensor_acceleration[s].begin(), ws.result.sensor_acceleration[s].end(),
                acc.begin() + static_cast<std::ptrdiff_t>((r * ns + s) * n));
    std::copy(ws.result.contact_force.begin(), ws.result.contact_force.end(),
              force.begin() + static_cast<std::ptrdiff_t>(r * n));
    std::copy(ws.result.ball_acceleration.begin(), ws.result.ball_acceleration.end(),
              ball.begin() + static_cast<std::ptrdiff_t>(r * n));
    std::copy(ws.result.compression.begin(), ws.result.compression.end(),
              delta.begin() + static_cast<std::ptrdiff_t>(r * n));
  }
  w.write("/time_history/time", {n}, t.data(), "s", "time from the start of the record");
  w.write("/time_history/sensor_acceleration", {nh, ns, n}, acc.data(), "m/s^2", "realisation x sensor x time");
  w.write("/time_history/contact_force", {nh, n}, force.data(), "N", "realisation x time");
  w.write("/time_history/ball_acceleration", {nh, n}, ball.data(), "m/s^2", "realisation x time");
  w.write("/time_history/compression", {nh, n}, delta.data(), "m",
          "contact compression delta = w_beam + h - w_ball (> 0: contact)");
  w.make_scale("/time_history/time", "time");
  w.attach_scale("/time_history/sensor_acceleration", "/time_history/time", 2);
  for (const char* d : {"/time_history/contact_force", "/time_history/ball_acceleration", "/time_history/compression"})
    w.attach_scale(d, "/time_history/time", 1);
  w.attribute("/time_history", "realisations",
              only >= 0 ? std::to_string(only) : "0.." + std::to_string(b_.time_histories - 1));
}

std::unique_ptr<Scene> make_ball_on_beam(const KeyReader& s) {
  return std::make_unique<BallOnBeam>(BallOnBeamSections::parse(s));
}

ResultShape ball_on_beam_result_shape(const KeyReader& s) {
  const BallOnBeamSettings b = read_ball_on_beam_settings(BallOnBeamSections::parse(s));
  return psd_result_shape(numbered_sensors(b.model.sensors.size()), b.sensor_mean, b.welch, b.band_min, b.band_max);
}

}  // namespace rollspec::scenes
