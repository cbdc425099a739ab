#include "src/scenes/ball_on_beam.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/scenes/study_welch.hpp"

#include "kernels/beam/quadratic_hold_step.hpp"
#include "kernels/integrators/exact_oscillator_step.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <mutex>
#include <sstream>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/dopri5_reference.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/linear_reference.hpp"
#include "kernels/beam/modal_beam.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/psd_units.hpp"
#include "kernels/texture/time_signal.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/psd_result.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/ensemble/progress.hpp"
#include "src/study/study.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/stiffness_keys.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

namespace {

std::string g4(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::vector<double> sensor_positions(const Study& s) {
  auto v = s.numbers("sensors.positions");
  if (v.empty()) s.refuse("sensors.positions", "lists no position; allowed: comma-separated positions in m");
  return v;
}

namespace {

struct Workspace {
  std::vector<double> texture, u_phase, u_amp;
  beam::BallOnBeamResult result;
  spectral::WelchWorkspace welch;
  Workspace(std::size_t n_texture, std::size_t harmonics, std::size_t segment)
      : texture(n_texture), u_phase(harmonics), u_amp(harmonics), welch(segment) {}
};

class BallOnBeam final : public Scene {
 public:
  explicit BallOnBeam(const Study& s)
      : seed_(static_cast<std::uint64_t>(s.integer("study.seed"))),
        model_{study_modal_beam(s), {}, {}, {}, s.real("signal.sample_rate"), sensor_positions(s)},
        psd_(texture_io::study_psd(s)),
        average_(s.boolean("sensors.average")),
        dopri_(s.text("signal.integrator") == "dopri5"),
        rtol_(s.real("signal.rtol")),
        confidence_(s.real("spectrum.confidence")),
        band_min_(s.real("spectrum.band_min")),
        band_max_(s.real("spectrum.band_max")),
        time_histories_(static_cast<std::size_t>(s.integer("output.time_histories"))) {
    const double l = s.real("beam.length");
    for (double x : model_.sensors)
      if (x < 0.0 || x > l) s.refuse("sensors.positions", "position " + std::to_string(x) + " m lies outside the span [0, length]");
    // Ball.
    const double radius = s.real("ball.radius");
    model_.ball.mass = 4.0 / 3.0 * M_PI * radius * radius * radius * s.real("ball.density");
    model_.ball.gravity = s.real("ball.gravity");
    model_.traverse.x_start = s.real("ball.start");
    model_.traverse.x_end = s.real("ball.end");
    model_.traverse.speed = s.real("ball.speed");
    if (!(model_.traverse.x_end > model_.traverse.x_start)) s.refuse("ball.end", "must exceed [ball] start");
    if (model_.traverse.x_end > l) s.refuse("ball.end", "lies beyond the span [0, length]");
    // Contact.
    beam::ContactLaw& law = model_.contact;
    law_name_ = s.text("contact.law");
    contact_model_ = law_name_ == "table"     ? ContactModel::table
                     : law_name_ == "literal" ? ContactModel::literal
                     : law_name_ == "hertz"   ? ContactModel::hertz
                     : s.text("contact.blocked_force") == "solver" ? ContactModel::linearised_solver
                                                                   : ContactModel::linearised_spring;
    if (blocked_solver() || uses_table()) study_ = &s;
    law.kind = linearised() ? beam::ContactLawKind::linearised
               : contact_model_ == ContactModel::table   ? beam::ContactLawKind::table
               : contact_model_ == ContactModel::literal ? beam::ContactLawKind::literal_stiffness
                                                         : beam::ContactLawKind::hertz;
    law.effective_modulus = contact::effective_modulus(s.real("ball.youngs_modulus"), s.real("ball.poisson"),
                                                       s.real("beam.youngs_modulus"), s.real("beam.poisson"));
    law.radius = radius;
    law.k0 = s.real("contact.k0");
    law.damping = s.real("contact.damping");
    law.loss = s.text("contact.loss") == "zero" ? beam::LossOfContact::zero_force : beam::LossOfContact::damping_only;
    const double weight = model_.ball.mass * model_.ball.gravity;
    static_compression_ = linearised() ? weight / law.k0 : std::pow(3.0 * weight / (4.0 * law.effective_modulus * std::sqrt(radius)), 2.0 / 3.0);
    patch_half_width_ = s.boolean("contact.patch_filter") ? beam::hertz_half_width(radius, linearised() ? std::pow(3.0 * weight / (4.0 * law.effective_modulus * std::sqrt(radius)), 2.0 / 3.0) : static_compression_) : 0.0;
    // Roughness line over the whole span, so the patch filter and the traverse never run off it.
    // One roughness sample per integration step by default: the interpolation between samples then
    // low-passes the excitation only near the step's own Nyquist frequency.
    dx_ = s.real("roughness.spacing") > 0.0
              ? s.real("roughness.spacing")
              : model_.traverse.speed / (model_.sample_rate * static_cast<double>(s.integer("signal.substeps")));
    const std::size_t line_samples = static_cast<std::size_t>(std::floor(l / dx_)) + 1;
    if (line_samples > (1u << 26)) s.refuse("roughness.spacing", "gives more than 2^26 samples over the span");
    lines_ = texture_io::study_line_generator(s, psd_, dx_, line_samples, "roughness.spacing");
    if (!uses_table() && !blocked_solver())
      check_contact_resolution(s, linearised() ? law.k0 : 2.0 * law.effective_modulus * std::sqrt(radius * static_compression_));
    // Integrator options (the integrator itself is built in prepare(), once the contact law is complete).
    step_options_.substeps = static_cast<int>(s.integer("signal.substeps"));
    step_options_.hold = s.text("signal.hold") == "quadratic" ? beam::ForceHold::quadratic : beam::ForceHold::linear;
    check_step_coefficients(s);
    samples_ = beam::output_samples(model_);
    skip_ = static_cast<std::size_t>(std::ceil(s.real("spectrum.skip_start") * model_.sample_rate));
    if (skip_ >= samples_) s.refuse("spectrum.skip_start", "leaves nothing of the record (" + std::to_string(samples_) + " samples)");
    const auto segment = static_cast<std::size_t>(s.integer("spectrum.segment"));
    if (segment > samples_ - skip_)
      s.refuse("spectrum.segment", "is longer than the analysed record (" + std::to_string(samples_ - skip_) +
                                       " samples = ((end - start) / speed - skip_start) x sample_rate)");
    welch_ = std::make_unique<spectral::WelchPlan>(study_welch_config(s, model_.sample_rate));
    std::vector<std::string> names;
    for (std::size_t k = 0; k < model_.sensors.size(); ++k) names.push_back("sensor_" + std::to_string(k + 1));
    rows_ = std::make_unique<PsdRows>(names, average_, welch_->frequencies(), band_min_, band_max_, 2 * welch_->n_freq() + 1);
    for (int t = 0; t < ensemble::ensemble_threads(); ++t)
      workspaces_.push_back(std::make_unique<Workspace>(line_samples, lines_->harmonics(), segment));
    add_pipeline_stages(s);
  }

  // texture, surface, stiffness_table, blocked_force, dynamics, spectra: the tables are stage
  // objects whose inspection `plan` prints and whose resolution prepare() runs.
  void add_pipeline_stages(const Study& s) {
    add_stages({{"texture", StageStatus::run, "beam line texture per realisation from [texture] (" + psd_.description + ")"}});
    std::unique_ptr<TableStage> table;
    if (uses_table()) {
      const double radius = model_.contact.radius, e_star = model_.contact.effective_modulus;
      table = std::make_unique<TableStage>(
          "stiffness_table", stiffness::stiffness_cached_table(s, radius, e_star),
          [] { return std::make_unique<stiffness::StiffnessTable>(); },
          [&s, radius, e_star](stiffness::TableData& out, bool quiet) {
            static_cast<stiffness::StiffnessTable&>(out) = stiffness::build_table(s, radius, e_star, quiet);
          },
          [this](const stiffness::TableData& t, const std::string& status, bool quiet) {
            use_stiffness_table(static_cast<const stiffness::StiffnessTable&>(t), status, quiet);
          });
    }
    const TableStage* t = table.get();
    add_stage(std::make_unique<DerivedStage>([t] {
      const bool valid = t && t->state() == stiffness::TableState::valid;
      return StagePlan{"surface", t && !valid ? StageStatus::run : StageStatus::skipped,
                       !t      ? "the point-contact laws need no isotropic surface"
                       : valid ? "inside the cached stiffness table"
                               : "isotropic surfaces for the stiffness table"};
    }));
    if (table) add_stage(std::move(table));
    else
      add_stages({{"stiffness_table", StageStatus::skipped,
                   linearised() ? "linearised law: k0 from [contact]" : "hertz law: analytic, needs no table"}});
    if (blocked_solver()) {
      const double radius = model_.contact.radius, e_star = model_.contact.effective_modulus;
      const double weight = model_.ball.mass * model_.ball.gravity;
      // The strip's grid: the study's keys where set, else derived from the contact radius and the
      // texture; the path step at most v / f_s so F0 reaches the output's Nyquist frequency.
      const stiffness::BlockedForceGeometry grid =
          stiffness::blocked_force_geometry(s, radius, e_star, weight, model_.traverse.speed / model_.sample_rate);
      add_stage(std::make_unique<TableStage>(
          "blocked_force", stiffness::blocked_force_cached_table(s, grid, radius, e_star, weight),
          [] { return std::make_unique<stiffness::BlockedForceTable>(); },
          [&s, grid, radius, e_star, weight](stiffness::TableData& out, bool quiet) {
            static_cast<stiffness::BlockedForceTable&>(out) = stiffness::build_blocked_force(s, grid, radius, e_star, weight, quiet);
          },
          [this](const stiffness::TableData& b, const std::string& status, bool quiet) {
            use_blocked_force(static_cast<const stiffness::BlockedForceTable&>(b), status, quiet);
          },
          grid.describe()));
    } else {
      add_stages({{"blocked_force", linearised() ? StageStatus::run : StageStatus::skipped,
                   linearised() ? "F0(t) = W + k0 h_patch(v t) per realisation (linear contact spring)"
                               : "only the linearised law uses F0"}});
    }
    add_stages({{"dynamics", StageStatus::run, dopri_ ? "Dormand-Prince 5(4) reference" : "exact modal step per mode, implicit contact force"},
                {"spectra", StageStatus::run, "Welch PSDs of sensors, contact force and ball; ensemble mean"}});
  }

  // The exact modal step of very high modes (omega h in the thousands) overflows double precision:
  // every realisation would be non-finite. Refused here, before any work, with the largest mode
  // count whose step is finite.
  void check_step_coefficients(const Study& s) const {
    if (dopri_) return;
    const double h = 1.0 / (model_.sample_rate * static_cast<double>(step_options_.substeps));
    const beam::ModalBeam& b = model_.beam;
    for (int i = 0; i < b.modes(); ++i) {
      const auto f = integrators::ExactOscillatorStep::make(b.omega(i), b.zeta(i), h);
      bool ok = std::isfinite(f.a00) && std::isfinite(f.a01) && std::isfinite(f.a10) && std::isfinite(f.a11) &&
                std::isfinite(f.b0) && std::isfinite(f.b1) && std::isfinite(f.c0) && std::isfinite(f.c1);
      if (ok && step_options_.hold == beam::ForceHold::quadratic) {
        const auto q = beam::QuadraticHoldStep::make(b.omega(i), b.zeta(i), h);
        for (double v : {q.a00, q.a01, q.a10, q.a11, q.bm, q.b0, q.b1, q.cm, q.c0, q.c1}) ok = ok && std::isfinite(v);
      }
      if (ok) continue;
      char buf[200];
      std::snprintf(buf, sizeof buf, "keeps %d modes, but the exact step of mode %d (%.4g Hz, omega h = %.4g) overflows double precision",
                    b.modes(), i + 1, b.frequency(i), b.omega(i) * h);
      s.refuse(s.integer("beam.modes") > 0 ? "beam.modes" : "beam.max_frequency",
               std::string(buf) + "; allowed: at most " + std::to_string(i) + " modes at this step (or signal.integrator = dopri5)");
    }
  }

  void prepare(bool quiet, bool rebuild) override {
    quiet_ = quiet;
    resolve_stages(quiet, rebuild);  // the tables' use_* complete the contact law
    integrator_ = std::make_unique<beam::ExactStepIntegrator>(model_, step_options_);
  }

  void use_stiffness_table(const stiffness::StiffnessTable& t, const std::string& status, bool quiet) {
    if (!quiet) std::fprintf(stderr, "stiffness table: %s\n", status.c_str());
    model_.contact.compression = t.approach;
    if (model_.contact.kind == beam::ContactLawKind::table) {
      model_.contact.values = t.force_mean;
    } else {  // seed 001 Eq. 7 literally: k_c(delta) from the table's stiffness, F = k_c(delta) delta
      model_.contact.values = t.stiffness_mean;
      model_.contact.values[0] = t.stiffness_mean[1];
    }
    static_compression_ = t.approach_at(model_.ball.mass * model_.ball.gravity);
    if (!(static_compression_ > 0.0))
      study_->refuse("stiffness.approach_max", "the table's largest force " + std::to_string(t.force_mean.back()) +
                                                   " N does not reach the ball's weight; raise approach_max");
    check_contact_resolution(*study_, t.stiffness_at(model_.ball.mass * model_.ball.gravity));
  }

  // The contact solver's blocked force (seed 002 §4.2): k0 from the table, F0(t) synthesised per
  // realisation from the table's PSD along the path, G_t(f) = 2 pi G_k(2 pi f / v) / v (D-2),
  // sampled at the integration step.
  void use_blocked_force(const stiffness::BlockedForceTable& table, const std::string& status, bool quiet) {
    blocked_ = table;
    if (!quiet) std::fprintf(stderr, "blocked force table: %s (k0 = %.4g N/m, d0 = %.4g m)\n", status.c_str(), blocked_.k0,
                             blocked_.approach);
    const double weight = model_.ball.mass * model_.ball.gravity;
    model_.contact.k0 = blocked_.k0;
    static_compression_ = weight / blocked_.k0;
    check_contact_resolution(*study_, blocked_.k0);
    f0_step_ = 1.0 / (model_.sample_rate * static_cast<double>(step_options_.substeps));
    auto n = static_cast<std::size_t>(std::ceil(beam::traverse_duration(model_.traverse) / f0_step_)) + 4;
    n = texture::fast_even_length(n);
    f0_synth_ = std::make_unique<spectral::HarmonicSynthesiser>(n);
    const double df = 1.0 / (static_cast<double>(n) * f0_step_), v = model_.traverse.speed;
    f0_psd_.assign(f0_synth_->harmonics(), 0.0);
    for (std::size_t j = 1; j < f0_psd_.size(); ++j) {
      const double f = df * static_cast<double>(j);
      f0_psd_[j] = 2.0 * M_PI * blocked_.psd_at(2.0 * M_PI * f / v) / v;
    }
    f0_df_ = df;
  }

  double blocked_force_time_psd(double f) const {
    const double v = model_.traverse.speed;
    return 2.0 * M_PI * blocked_.psd_at(2.0 * M_PI * f / v) / v;
  }

  // The step must resolve the ball's bounce on the contact spring: h <= T_c / 20 with
  // T_c = 2 pi sqrt(m_ball / k_contact) at the static load (kernels/README.md D-23). Coarser steps stay finite
  // but misstate loss of contact and the high-frequency levels, so they are refused.
  void check_contact_resolution(const Study& s, double k_contact) const {
    const double tc = 2.0 * M_PI * std::sqrt(model_.ball.mass / k_contact);
    const double h = 1.0 / (model_.sample_rate * static_cast<double>(s.integer("signal.substeps")));
    if (h > tc / 20.0) {
      const auto need = static_cast<long long>(std::ceil(20.0 / (tc * model_.sample_rate)));
      s.refuse("signal.substeps", "the integration step 1 / (sample_rate x substeps) = " + g4(h) +
                                      " s exceeds the contact resolution limit dt <= T_c / 20 = " + g4(tc / 20.0) +
                                      " s (T_c = 2 pi sqrt(m_ball / k_contact), k_contact = " + g4(k_contact) +
                                      " N/m at the ball's weight); allowed: substeps >= " + std::to_string(need) +
                                      " at this sample rate");
    }
  }

  std::size_t rows() const { return rows_->rows(); }
  // PsdRows layout, then the extras: contact-force PSD, ball-acceleration PSD, loss-of-contact share.
  std::size_t values_per_realisation() const override { return rows_->size(); }

  // Simulates realisation `id` into ws.result (shared by the ensemble and the time-history output).
  void simulate(std::uint64_t id, Workspace& ws) const {
    const std::size_t nh = lines_->harmonics();
    if (!blocked_solver()) {
    rng::PhiloxStream(seed_, id, rng::Stream::roughness_phase).uniform_open(ws.u_phase.data(), nh);
    rng::PhiloxStream(seed_, id, rng::Stream::roughness_amplitude).uniform_open(ws.u_amp.data(), nh);
    lines_->generate(ws.u_phase.data(), ws.u_amp.data(), ws.texture.data());
    }
    beam::UniformSamples h{0.0, dx_, blocked_solver() ? std::vector<double>() : ws.texture};
    if (patch_half_width_ > 0.0 && !blocked_solver()) h = beam::contact_patch_average(h, patch_half_width_);
    beam::Realisation r;
    if (blocked_solver()) {
      const std::size_t nh_f0 = f0_synth_->harmonics(), n = f0_synth_->samples();
      std::vector<double> up(nh_f0), ua(nh_f0);
      rng::PhiloxStream(seed_, id, rng::Stream::blocked_force_phase).uniform_open(up.data(), nh_f0);
      rng::PhiloxStream(seed_, id, rng::Stream::blocked_force_amplitude).uniform_open(ua.data(), nh_f0);
      r.blocked_force.origin = 0.0;
      r.blocked_force.step = f0_step_;
      r.blocked_force.values.resize(n);
      f0_synth_->synthesise(f0_psd_.data(), f0_df_, spectral::Amplitudes::rayleigh, up.data(), ua.data(),
                            r.blocked_force.values.data());
      for (double& f : r.blocked_force.values) f += model_.ball.mass * model_.ball.gravity;
    } else if (linearised()) {
      // Blocked force of a linear contact spring: F0(t) = W + k0 h(x_start + v t) (D-11).
      const double v = model_.traverse.speed, x0 = model_.traverse.x_start, dt = dx_ / v;
      const auto first = static_cast<std::size_t>(std::floor(x0 / dx_));
      r.blocked_force.origin = (static_cast<double>(first) * dx_ - x0) / v;
      r.blocked_force.step = dt;
      const double weight = model_.ball.mass * model_.ball.gravity;
      for (std::size_t i = first; i < h.values.size(); ++i) r.blocked_force.values.push_back(weight + model_.contact.k0 * h.values[i]);
    } else {
      r.roughness = std::move(h);
    }
    if (dopri_) {
      beam::ReferenceTolerances tol;
      tol.rtol = rtol_;
      ws.result = beam::simulate_dopri5(model_, r, tol);
    } else {
      integrator_->run(r, ws.result);
    }
  }

  void run_realisation(std::uint64_t id, int thread, double* values) const override {
    Workspace& ws = *workspaces_[static_cast<std::size_t>(thread)];
    simulate(id, ws);
    const std::size_t nf = welch_->n_freq(), ns = model_.sensors.size(), n = ws.result.samples() - skip_;
    for (std::size_t s = 0; s < ns; ++s)
      welch_->psd(ws.result.sensor_acceleration[s].data() + skip_, n, rows_->row(values, s), ws.welch);
    rows_->finish(values);
    double* x = rows_->extras(values);
    welch_->psd(ws.result.contact_force.data() + skip_, n, x, ws.welch);
    welch_->psd(ws.result.ball_acceleration.data() + skip_, n, x + nf, ws.welch);
    x[2 * nf] = ws.result.loss_of_contact_share;
  }

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override {
    const std::size_t nf = welch_->n_freq();
    const double K = static_cast<double>(sums.count);
    auto mean_of = [&](std::size_t i) { return sums.mean(i); };
    auto std_of = [&](std::size_t i) { return sums.std_dev(i); };
    io::PsdEnsemble e = rows_->ensemble(sums);
    e.welch_dof = K * welch_->equivalent_dof(samples_ - skip_);  // stationary D-16 value, for information
    e.window_enbw_bins = spectral::equivalent_noise_bandwidth_bins(welch_->window());
    e.confidence = confidence_;
    io::write_psd_result(w, e);

    std::vector<double> force(nf), ball(nf);
    for (std::size_t k = 0; k < nf; ++k) {
      force[k] = mean_of(rows_->extra_index(k));
      ball[k] = mean_of(rows_->extra_index(nf + k));
    }
    w.write("/contact/force_psd", {nf}, force.data(), "N^2/Hz", "ensemble mean PSD of the contact force");
    w.write("/ball/acceleration_psd", {nf}, ball.data(), "(m/s^2)^2/Hz", "ensemble mean PSD of the ball acceleration");
    io::write_frequency_scale(w, "/contact", e.frequency);
    io::write_frequency_scale(w, "/ball", e.frequency);
    w.attach_scale("/contact/force_psd", "/contact/frequency", 0);
    w.attach_scale("/ball/acceleration_psd", "/ball/frequency", 0);
    const double share = mean_of(rows_->extra_index(2 * nf)), share_std = std_of(rows_->extra_index(2 * nf));
    w.write("/contact/loss_of_contact_share", {1}, &share, "1", "mean share of the time in loss of contact");
    w.write("/contact/loss_of_contact_share_std", {1}, &share_std, "1", "its standard deviation over realisations");
    w.attribute("/contact", "law", law_name_);
    w.attribute("/contact", "static_compression", static_compression_);
    w.attribute("/contact", "patch_half_width", patch_half_width_);
    w.attribute("/contact", "effective_modulus", model_.contact.effective_modulus);
    if (linearised()) w.attribute("/contact", "k0", model_.contact.k0);
    if (blocked_solver()) {
      w.attribute("/contact", "blocked_force_approach", blocked_.approach);
      w.attribute("/contact", "blocked_force_input_hash", blocked_.input_hash);
    }

    const auto& b = model_.beam;
    std::vector<double> fm(static_cast<std::size_t>(b.modes()));
    for (int i = 0; i < b.modes(); ++i) fm[static_cast<std::size_t>(i)] = b.frequency(i);
    w.write("/beam/modal_frequency", {fm.size()}, fm.data(), "Hz", "undamped modal frequencies");
    const auto& p = b.properties();
    w.attribute("/beam", "length", p.length);
    w.attribute("/beam", "effective_length", b.effective_length());
    w.attribute("/beam", "width", p.width);
    w.attribute("/beam", "thickness", p.thickness);
    w.attribute("/beam", "youngs_modulus", p.youngs_modulus);
    w.attribute("/beam", "density", p.density);
    w.attribute("/beam", "static_correction", static_cast<std::int64_t>(b.static_correction()));
    w.write("/sensors/position", {model_.sensors.size()}, model_.sensors.data(), "m", "sensor positions along the span");
    w.attribute("/ball", "mass", model_.ball.mass);
    w.attribute("/ball", "speed", model_.traverse.speed);

    if (linearised()) write_linear_reference(w, e.frequency, e.sensors, K);
    if (time_histories_) write_time_histories(w, sums.only);
  }

 private:
  // Frequency-domain solution of the linearised model made exact for what the Monte-Carlo
  // simulates (kernels/beam/linear_reference.hpp; README B34, B34a-c, B35a; D-20).
  void write_linear_reference(io::Hdf5Writer& w, const std::vector<double>& f, const std::vector<std::string>& sensors,
                              double realisations) const {
    beam::LinearReferenceInput in;
    in.beam = &model_.beam;
    in.ball_mass = model_.ball.mass;
    in.damping = model_.contact.damping;
    in.sensors = model_.sensors;
    in.sensor_mean = rows() > model_.sensors.size();
    in.welch = welch_.get();
    in.sample_rate = model_.sample_rate;
    beam::ReferenceExcitation& ex = in.excitation;
    if (blocked_solver()) {
      ex.time_psd = [this](double fi) { return blocked_force_time_psd(fi); };
    } else {
      ex.time_psd = texture::time_psd(psd_, model_.traverse.speed);
    }
    ex.blocked_force = blocked_solver();
    ex.k0 = model_.contact.k0;
    ex.speed = model_.traverse.speed;
    ex.spacing = dx_;
    ex.patch_half_width = patch_half_width_;
    ex.x_start = model_.traverse.x_start;
    ex.step = 1.0 / (model_.sample_rate * static_cast<double>(step_options_.substeps));
    in.positions = beam::welch_position_blocks(*welch_, samples_ - skip_, skip_, model_.traverse.x_start,
                                               model_.traverse.speed, model_.sample_rate);
    in.realisations = realisations;
    in.confidence = confidence_;
    // The reference runs after the ensemble and can take longer than it: shown when over a second.
    ensemble::Progress progress("linearised reference", beam::linear_reference_steps(in), quiet_);
    progress.show_after(1.0);
    const beam::LinearReference ref = beam::linear_reference(in, [&progress] { progress.advance(); });
    progress.finish();
    w.write("/reference/psd", {rows(), f.size()}, ref.psd.data(), "(m/s^2)^2/Hz",
            "expected Welch estimate of the linearised model's frequency-domain PSD, averaged over ball positions");
    w.write("/reference/psd_raw", {rows(), f.size()}, ref.raw.data(), "(m/s^2)^2/Hz",
            "the frequency-domain PSD itself at the bin frequencies (not window-smoothed)");
    w.write("/reference/degrees_of_freedom", {rows(), f.size()}, ref.dof.data(), "1",
            "chi-square dof of the ensemble mean per bin for the non-stationary record, from the Welch window "
            "and the ball's positions (/psd/degrees_of_freedom comes from the realisations' scatter)");
    w.write("/reference/mean_lower", {rows(), f.size()}, ref.mean_lower.data(), "(m/s^2)^2/Hz",
            "lower end of the range that holds the ensemble mean with the study's confidence if /reference/psd is right");
    w.write("/reference/mean_upper", {rows(), f.size()}, ref.mean_upper.data(), "(m/s^2)^2/Hz",
            "upper end of that range");
    w.attribute("/reference/psd", "label",
                std::string("linear, quasi-stationary (no moving-weight response, no loss of contact)"));
    io::write_frequency_scale(w, "/reference", f);
    io::write_sensor_scale(w, "/reference", sensors);
    for (const char* d : {"/reference/psd", "/reference/psd_raw", "/reference/degrees_of_freedom", "/reference/mean_lower",
                          "/reference/mean_upper"}) {
      w.attach_scale(d, "/reference/sensor", 0);
      w.attach_scale(d, "/reference/frequency", 1);
    }
  }

  // Realisations 0..n-1 again (deterministic: same Philox keys), so histories survive --resume;
  // with --only, the history of that one realisation.
  void write_time_histories(io::Hdf5Writer& w, std::int64_t only) const {
    Workspace& ws = *workspaces_[0];
    const std::size_t n = samples_, ns = model_.sensors.size(), nh = only >= 0 ? 1 : time_histories_;
    std::vector<double> t(n), acc(nh * ns * n), force(nh * n), ball(nh * n), delta(nh * n);
    for (std::size_t j = 0; j < n; ++j) t[j] = static_cast<double>(j) / model_.sample_rate;
    for (std::size_t r = 0; r < nh; ++r) {
      simulate(only >= 0 ? static_cast<std::uint64_t>(only) : r, ws);
      for (std::size_t s = 0; s < ns; ++s)
        std::copy(ws.result.sensor_acceleration[s].begin(), ws.result.sensor_acceleration[s].end(), acc.begin() + static_cast<std::ptrdiff_t>((r * ns + s) * n));
      std::copy(ws.result.contact_force.begin(), ws.result.contact_force.end(), force.begin() + static_cast<std::ptrdiff_t>(r * n));
      std::copy(ws.result.ball_acceleration.begin(), ws.result.ball_acceleration.end(), ball.begin() + static_cast<std::ptrdiff_t>(r * n));
      std::copy(ws.result.compression.begin(), ws.result.compression.end(), delta.begin() + static_cast<std::ptrdiff_t>(r * n));
    }
    w.write("/time_history/time", {n}, t.data(), "s", "time from the start of the record");
    w.write("/time_history/sensor_acceleration", {nh, ns, n}, acc.data(), "m/s^2", "realisation x sensor x time");
    w.write("/time_history/contact_force", {nh, n}, force.data(), "N", "realisation x time");
    w.write("/time_history/ball_acceleration", {nh, n}, ball.data(), "m/s^2", "realisation x time");
    w.write("/time_history/compression", {nh, n}, delta.data(), "m", "contact compression delta = w_beam + h - w_ball (> 0: contact)");
    w.make_scale("/time_history/time", "time");
    w.attach_scale("/time_history/sensor_acceleration", "/time_history/time", 2);
    for (const char* d : {"/time_history/contact_force", "/time_history/ball_acceleration", "/time_history/compression"})
      w.attach_scale(d, "/time_history/time", 1);
    w.attribute("/time_history", "realisations",
                only >= 0 ? std::to_string(only) : "0.." + std::to_string(time_histories_ - 1));
  }

  std::uint64_t seed_;
  beam::BallOnBeamModel model_;
  texture::Psd psd_;
  bool average_, dopri_;
  double rtol_, confidence_, band_min_, band_max_;
  std::size_t time_histories_;
  // One value for the contact law and the blocked force's source ([contact] law, blocked_force).
  enum class ContactModel { hertz, table, literal, linearised_spring, linearised_solver };
  ContactModel contact_model_ = ContactModel::hertz;
  bool linearised() const {
    return contact_model_ == ContactModel::linearised_spring || contact_model_ == ContactModel::linearised_solver;
  }
  bool uses_table() const { return contact_model_ == ContactModel::table || contact_model_ == ContactModel::literal; }
  bool blocked_solver() const { return contact_model_ == ContactModel::linearised_solver; }
  bool quiet_ = false;
  stiffness::BlockedForceTable blocked_;
  std::unique_ptr<spectral::HarmonicSynthesiser> f0_synth_;
  std::vector<double> f0_psd_;
  double f0_step_ = 0.0, f0_df_ = 0.0;
  std::string law_name_;
  beam::ExactStepOptions step_options_;
  const Study* study_ = nullptr;  // for the table stage in prepare(); the study outlives the scene
  double static_compression_ = 0.0, patch_half_width_ = 0.0, dx_ = 0.0;
  std::unique_ptr<texture::LineTextureGenerator> lines_;
  std::unique_ptr<beam::ExactStepIntegrator> integrator_;
  std::size_t samples_ = 0, skip_ = 0;
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace

std::unique_ptr<Scene> make_ball_on_beam(const Study& s) { return std::make_unique<BallOnBeam>(s); }

}  // namespace rollspec::scenes
