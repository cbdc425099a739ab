#include "src/scenes/ball_on_beam.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/scenes/study_welch.hpp"

#include "kernels/beam/quadratic_hold_step.hpp"
#include "kernels/integrators/exact_oscillator_step.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <complex>
#include <limits>
#include <mutex>
#include <sstream>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/dopri5_reference.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/linear_response.hpp"
#include "kernels/beam/modal_beam.hpp"
#include "kernels/contact/geometry.hpp"
#include "kernels/spectral/confidence.hpp"
#include "kernels/spectral/harmonic_synthesis.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/spectral/welch_expectation.hpp"
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
const double inf = std::numeric_limits<double>::infinity();

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

std::vector<KeySpec> ball_on_beam_keys() {
  std::vector<KeySpec> k = {
      choice_key("beam", "support", "boundary conditions", std::string("clamped-clamped"),
                 {"clamped-clamped", "simply-supported"}),
      real_key("beam", "length", "m", "physical span l between the supports", std::string("0.4"), 0.0, inf, false),
      real_key("beam", "effective_length", "m", "modal length l_eff >= l (clamp rotation, seed 002: l + 30 mm); 0: l",
               std::string("0"), 0.0, inf),
      real_key("beam", "width", "m", "section width", std::string("0.05"), 0.0, inf, false),
      real_key("beam", "thickness", "m", "section thickness (bending direction)", std::string("0.0068"), 0.0, inf, false),
      real_key("beam", "youngs_modulus", "Pa", "Young's modulus E", std::string("210e9"), 0.0, inf, false),
      real_key("beam", "poisson", "-", "Poisson's ratio (contact modulus)", std::string("0.3"), -1.0, 0.5, false, false),
      real_key("beam", "density", "kg/m^3", "density rho", std::string("7850"), 0.0, inf, false),
      integer_key("beam", "modes", "number of modes (0: all up to max_frequency)", std::string("0"), 0, 5000),
      real_key("beam", "max_frequency", "Hz", "highest modal frequency kept when modes = 0", std::string("20000"), 0.0, inf),
      real_key("beam", "loss_factor", "-", "modal loss factor eta (zeta = eta/2)", std::string("0.01"), 0.0, 2.0),
      bool_key("beam", "static_correction", "residual flexibility of the truncated modes", std::string("true")),
      real_key("ball", "radius", "m", "ball radius R", std::string("0.02"), 0.0, inf, false),
      real_key("ball", "density", "kg/m^3", "ball density (mass = 4/3 pi R^3 rho)", std::string("7850"), 0.0, inf, false),
      real_key("ball", "youngs_modulus", "Pa", "ball Young's modulus", std::string("210e9"), 0.0, inf, false),
      real_key("ball", "poisson", "-", "ball Poisson's ratio", std::string("0.3"), -1.0, 0.5, false, false),
      real_key("ball", "speed", "m/s", "rolling speed v", std::string("1"), 0.0, inf, false),
      real_key("ball", "start", "m", "ball position where the record starts", std::string("0.05"), 0.0, inf),
      real_key("ball", "end", "m", "ball position where the record ends", std::string("0.35"), 0.0, inf),
      real_key("ball", "gravity", "m/s^2", "gravitational acceleration", std::string("9.81"), 0.0, inf),
      choice_key("contact", "law",
                 "contact law: hertz (D-10), table (rough-surface P(delta) from the stiffness stage, D-10), literal "
                 "(seed 001 Eq. 7: k_c(delta) delta from the same table) or linearised blocked force (D-11)",
                 std::string("hertz"), {"hertz", "table", "literal", "linearised"}),
      real_key("contact", "damping", "N s/m", "contact damping c_c (c0 for the linearised law)", std::string("100"), 0.0, inf),
      choice_key("contact", "loss", "force during loss of contact: damping_only (seed 001 Eq. 8) or zero",
                 std::string("damping_only"), {"damping_only", "zero"}),
      real_key("contact", "k0", "N/m", "linearised contact stiffness k0", std::string("6.8e6"), 0.0, inf, false),
      choice_key("contact", "blocked_force",
                 "linearised law's F0(t): spring (W + k0 h_patch(v t), k0 from [contact]) or solver (the contact "
                 "solver's blocked force along a rough strip, seed 002 §4.2: k0, d0 and the F0 PSD from a cached table)",
                 std::string("spring"), {"spring", "solver"}),
      bool_key("contact", "patch_filter", "average the roughness over the Hertz contact width at the static load",
               std::string("true")),
      real_key("roughness", "spacing", "m",
               "sample spacing of the beam's line texture (harmonics above pi/dx dropped); 0: one sample per integration "
               "step, v / (sample_rate x substeps)",
               std::string("0"), 0.0, inf),
      real_key("signal", "sample_rate", "Hz", "output sample rate of accelerations and forces", std::string("25600"), 0.0,
               inf, false),
      integer_key("signal", "substeps", "integration steps per output sample (exact-step integrator)", std::string("4"), 1,
                  1000),
      choice_key("signal", "hold",
                 "modal force over a step: quadratic (order 3, default) or linear (order 2) (kernels/beam B23, B36)",
                 std::string("quadratic"), {"quadratic", "linear"}),
      choice_key("signal", "integrator", "exact (exact modal step, implicit contact) or dopri5 (reference)",
                 std::string("exact"), {"exact", "dopri5"}),
      real_key("signal", "rtol", "-", "relative tolerance of the dopri5 reference", std::string("1e-8"), 1e-14, 1e-2),
      text_key("sensors", "positions", "accelerometer positions along the beam, m, comma-separated", std::string("0.2")),
      bool_key("sensors", "average", "add the mean PSD over sensors (seed 002 averages 5 sensors x 25 rolls)",
               std::string("true")),
      real_key("spectrum", "skip_start", "s",
               "time at the start of each record left out of the PSDs (start-up of the random response)", std::string("0"),
               0.0, inf),
      integer_key("output", "time_histories", "store time histories of realisations 0..n-1", std::string("0"), 0, 1000),
  };
  for (auto& t : texture_io::psd_keys()) k.push_back(t);
  for (auto& t : texture_io::surface_keys()) k.push_back(t);
  for (auto& t : stiffness::stiffness_keys()) k.push_back(t);
  for (auto& t : stiffness::blocked_force_keys()) k.push_back(t);
  return k;
}

beam::ModalBeam study_modal_beam(const Study& s) {
  beam::BeamProperties p;
  p.support = s.text("beam.support") == "clamped-clamped" ? beam::Support::clamped_clamped : beam::Support::simply_supported;
  p.youngs_modulus = s.real("beam.youngs_modulus");
  p.density = s.real("beam.density");
  p.width = s.real("beam.width");
  p.thickness = s.real("beam.thickness");
  p.length = s.real("beam.length");
  p.effective_length = s.real("beam.effective_length");
  if (p.effective_length > 0.0 && p.effective_length < p.length)
    s.refuse("beam.effective_length", "is shorter than [beam] length; allowed: 0 or >= length");
  beam::ModeSelection sel;
  sel.count = static_cast<int>(s.integer("beam.modes"));
  sel.max_frequency = s.real("beam.max_frequency");
  if (sel.count == 0 && sel.max_frequency <= 0.0) s.refuse("beam.max_frequency", "must be > 0 when [beam] modes = 0");
  beam::ModalDamping d;
  d.loss_factor = s.real("beam.loss_factor");
  try {
    return beam::ModalBeam(p, sel, d, s.boolean("beam.static_correction"));
  } catch (const std::exception& e) {
    throw config_error(s.where("beam.modes") + ": " + e.what());
  }
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
    const std::string law_name = s.text("contact.law");
    law_name_ = law_name;
    blocked_solver_ = law_name == "linearised" && s.text("contact.blocked_force") == "solver";
    if (blocked_solver_) study_ = &s;
    linearised_ = law_name == "linearised";
    uses_table_ = law_name == "table" || law_name == "literal";
    law.kind = linearised_ ? beam::ContactLawKind::linearised
               : law_name == "table" ? beam::ContactLawKind::table
               : law_name == "literal" ? beam::ContactLawKind::literal_stiffness
                                       : beam::ContactLawKind::hertz;
    law.effective_modulus = contact::effective_modulus(s.real("ball.youngs_modulus"), s.real("ball.poisson"),
                                                       s.real("beam.youngs_modulus"), s.real("beam.poisson"));
    law.radius = radius;
    law.k0 = s.real("contact.k0");
    law.damping = s.real("contact.damping");
    law.loss = s.text("contact.loss") == "zero" ? beam::LossOfContact::zero_force : beam::LossOfContact::damping_only;
    const double weight = model_.ball.mass * model_.ball.gravity;
    static_compression_ = linearised_ ? weight / law.k0 : std::pow(3.0 * weight / (4.0 * law.effective_modulus * std::sqrt(radius)), 2.0 / 3.0);
    patch_half_width_ = s.boolean("contact.patch_filter") ? beam::hertz_half_width(radius, linearised_ ? std::pow(3.0 * weight / (4.0 * law.effective_modulus * std::sqrt(radius)), 2.0 / 3.0) : static_compression_) : 0.0;
    // Roughness line over the whole span, so the patch filter and the traverse never run off it.
    // One roughness sample per integration step by default: the interpolation between samples then
    // low-passes the excitation only near the step's own Nyquist frequency.
    dx_ = s.real("roughness.spacing") > 0.0
              ? s.real("roughness.spacing")
              : model_.traverse.speed / (model_.sample_rate * static_cast<double>(s.integer("signal.substeps")));
    texture::LineTextureSpec ls;
    ls.spacing = dx_;
    ls.samples = static_cast<std::size_t>(std::floor(l / dx_)) + 1;
    if (ls.samples > (1u << 26)) s.refuse("roughness.spacing", "gives more than 2^26 samples over the span");
    ls.amplitudes = texture_io::study_amplitudes(s);
    ls.allow_truncation = true;
    try {
      lines_ = std::make_unique<texture::LineTextureGenerator>(psd_, ls);
    } catch (const std::exception& e) {
      throw config_error(s.where("roughness.spacing") + ": " + e.what());
    }
    if (!uses_table_ && !blocked_solver_)
      check_contact_resolution(s, linearised_ ? law.k0 : 2.0 * law.effective_modulus * std::sqrt(radius * static_compression_));
    // Integrator options (the integrator itself is built in prepare(), once the contact law is complete).
    step_options_.substeps = static_cast<int>(s.integer("signal.substeps"));
    step_options_.hold = s.text("signal.hold") == "quadratic" ? beam::ForceHold::quadratic : beam::ForceHold::linear;
    check_step_coefficients(s);
    if (uses_table_) study_ = &s;
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
      workspaces_.push_back(std::make_unique<Workspace>(ls.samples, lines_->harmonics(), segment));
    add_pipeline_stages(s);
  }

  // texture, surface, stiffness_table, blocked_force, dynamics, spectra: the tables are stage
  // objects whose inspection `plan` prints and whose resolution prepare() runs.
  void add_pipeline_stages(const Study& s) {
    add_stages({{"texture", StageStatus::run, "beam line texture per realisation from [texture] (" + psd_.description + ")"}});
    std::unique_ptr<TableStage> table;
    if (uses_table_) {
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
                   linearised_ ? "linearised law: k0 from [contact]" : "hertz law: analytic, needs no table"}});
    if (blocked_solver_) {
      const double radius = model_.contact.radius, e_star = model_.contact.effective_modulus;
      const double weight = model_.ball.mass * model_.ball.gravity;
      add_stage(std::make_unique<TableStage>(
          "blocked_force", stiffness::blocked_force_cached_table(s, radius, e_star, weight),
          [] { return std::make_unique<stiffness::BlockedForceTable>(); },
          [&s, radius, e_star, weight](stiffness::TableData& out, bool quiet) {
            static_cast<stiffness::BlockedForceTable&>(out) = stiffness::build_blocked_force(s, radius, e_star, weight, quiet);
          },
          [this](const stiffness::TableData& b, const std::string& status, bool quiet) {
            use_blocked_force(static_cast<const stiffness::BlockedForceTable&>(b), status, quiet);
          }));
    } else {
      add_stages({{"blocked_force", linearised_ ? StageStatus::run : StageStatus::skipped,
                   linearised_ ? "F0(t) = W + k0 h_patch(v t) per realisation (linear contact spring)"
                               : "only the linearised law uses F0"}});
    }
    add_stages({{"dynamics", StageStatus::run, dopri_ ? "Dormand-Prince 5(4) reference" : "exact modal step, implicit contact (D-9, D-10)"},
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
  // T_c = 2 pi sqrt(m_ball / k_contact) at the static load (theory D-21). Coarser steps stay finite
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
    if (!blocked_solver_) {
    rng::PhiloxStream(seed_, id, rng::Stream::roughness_phase).uniform_open(ws.u_phase.data(), nh);
    rng::PhiloxStream(seed_, id, rng::Stream::roughness_amplitude).uniform_open(ws.u_amp.data(), nh);
    lines_->generate(ws.u_phase.data(), ws.u_amp.data(), ws.texture.data());
    }
    beam::UniformSamples h{0.0, dx_, blocked_solver_ ? std::vector<double>() : ws.texture};
    if (patch_half_width_ > 0.0 && !blocked_solver_) h = beam::contact_patch_average(h, patch_half_width_);
    beam::Realisation r;
    if (blocked_solver_) {
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
    } else if (linearised_) {
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
    if (linearised_) w.attribute("/contact", "k0", model_.contact.k0);
    if (blocked_solver_) {
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

    if (linearised_) write_linear_reference(w, e.frequency, e.sensors, K);
    if (time_histories_) write_time_histories(w, sums.only);
  }

 private:
  // Frequency-domain solution of the linearised model (seed 002 check), made exact for what the
  // Monte-Carlo simulates (kernels/beam README B34, B34a-c, B35a; D-20):
  //  - excitation: the blocked-force samples the integrator sees, W + k0 (patch-averaged samples of
  //    the synthesised roughness): k0^2 G_t(f) T(k)^2 with T the patch filter acting on samples
  //    (B35a: sin(ka)/(ka) times the linear interpolant's sinc^2(k dx/2)), no harmonic above pi/dx,
  //    times |C|^2 of the Catmull-Rom interpolation (B13) at the steps' offset from the samples;
  //  - receptances averaged over ball positions with the Welch estimate's own time weights (B34a:
  //    sum over segments of the squared window), not uniformly;
  //  - the PSD continues to the integration step's Nyquist frequency and aliases into [0, f_s/2]
  //    when the outputs are sampled (B34c: the D-20 integral taken beyond f_s/2);
  //  - then the expected Welch estimate (D-20): the window resolves no resonance narrower than a bin.
  //  - the chi-square dof of the ensemble mean per bin for this non-stationary record (B34b).
  // Left out: the moving load (quasi-stationary in the ball position). Its bias grows with the
  // distance the ball travels while the modes respond (v / (zeta_1 omega_1) against the analysed
  // length), not only with the seeds' Tf/tau (fundamental period over traverse time): measured
  // in tests/cli/test_ball_on_beam.py.
  void write_linear_reference(io::Hdf5Writer& w, const std::vector<double>& f, const std::vector<std::string>& sensors,
                              double realisations) const {
    const std::size_t refine = 8, half = refine * (f.size() - 1);
    const double fs = model_.sample_rate, step = 1.0 / (fs * static_cast<double>(step_options_.substeps));
    const auto aliases = static_cast<std::size_t>(std::ceil(0.5 / step / (0.5 * fs) - 1e-9));
    const std::size_t nfine = half * aliases + 1;
    const double v = model_.traverse.speed, k0 = model_.contact.k0, a = patch_half_width_;
    const auto gt = texture::time_psd(psd_, v);
    const double k_nyq = M_PI / dx_, dfine = welch_->frequency_step() / static_cast<double>(refine);
    // Catmull-Rom weights of y_{i-1}, y_i, y_{i+1}, y_{i+2} at fraction tau between samples (B13).
    auto catmull_rom_gain = [](double tau, double theta) {
      const double t2 = tau * tau, t3 = t2 * tau;
      const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + tau, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
      const double c[4] = {-0.5 * h10, h00 - 0.5 * h11, h01 + 0.5 * h10, 0.5 * h11};
      std::complex<double> g = 0.0;
      for (int n = 0; n < 4; ++n) g += c[n] * std::polar(1.0, static_cast<double>(n - 1) * theta);
      return std::norm(g);
    };
    // Offset of the integration steps from the F0 samples (the same at every step when the samples
    // are one per step, the default); otherwise F0 is read at every fraction: mean gain over tau.
    const double dt_f0 = dx_ / v;
    const bool one_per_step = std::abs(dt_f0 / step - 1.0) < 1e-9;
    double tau = 0.0;
    if (one_per_step) {
      const double x0 = model_.traverse.x_start, first = std::floor(x0 / dx_);
      tau = (x0 - first * dx_) / dx_;
      tau -= std::floor(tau);
    }
    std::vector<double> fine(nfine), exc(nfine, 0.0);
    for (std::size_t i = 0; i < nfine; ++i) {
      fine[i] = dfine * static_cast<double>(i);
      const double k = 2.0 * M_PI * fine[i] / v;
      if (i == 0) continue;
      if (blocked_solver_) {
        exc[i] = blocked_force_time_psd(fine[i]);  // synthesised at the step, up to its Nyquist frequency
        continue;
      }
      if (k > k_nyq) continue;  // harmonics above pi/dx are not synthesised
      const double patch = beam::contact_patch_transfer(k, a, dx_);  // (B35a)
      const double theta = 2.0 * M_PI * fine[i] * dt_f0;
      double hold = 0.0;
      if (one_per_step) {
        hold = catmull_rom_gain(tau, theta);
      } else {
        for (int j = 0; j < 16; ++j) hold += catmull_rom_gain((j + 0.5) / 16.0, theta) / 16.0;
      }
      exc[i] = k0 * k0 * gt(fine[i]) * patch * patch * hold;
    }
    // Ball positions with the Welch time weights of the analysed record (B34a): sample i of the
    // analysed part weighs sum_segments w^2(i - segment start); the samples after the last segment
    // weigh nothing. Blocks of consecutive samples, at their weighted mean position.
    const std::size_t n = samples_ - skip_;
    const auto tw = spectral::welch_time_weights(*welch_, n);
    const std::size_t blocks = std::min<std::size_t>(n, 256), per = (n + blocks - 1) / blocks;
    std::vector<std::size_t> edges;
    std::vector<double> xi, xw;
    for (std::size_t b0 = 0; b0 < n; b0 += per) {
      const std::size_t b1 = std::min(n, b0 + per);
      double sw = 0.0, sx = 0.0;
      for (std::size_t i = b0; i < b1; ++i) {
        const double x = model_.traverse.x_start + v * static_cast<double>(skip_ + i) / fs;
        sw += tw[i];
        sx += tw[i] * x;
      }
      edges.push_back(b0);
      xi.push_back(sw > 0.0 ? sx / sw : model_.traverse.x_start + v * static_cast<double>(skip_ + (b0 + b1) / 2) / fs);
      xw.push_back(sw);
    }
    edges.push_back(n);
    // The reference runs after the ensemble and can take longer than it: shown when over a second.
    const std::size_t n_rows = model_.sensors.size() + (rows() > model_.sensors.size() ? 1 : 0);
    ensemble::Progress progress("linearised reference", 1 + n_rows + (edges.size() - 1), quiet_);
    progress.show_after(1.0);
    const auto lr = beam::linear_response_psd(model_.beam, model_.ball.mass, k0, model_.contact.damping, xi,
                                              model_.sensors, fine, exc, beam::Excitation::blocked_force, xw);
    progress.advance();
    std::vector<std::vector<double>> rows_fine = lr.sensor_psd;
    if (rows() > model_.sensors.size()) {
      std::vector<double> m(nfine, 0.0);
      for (const auto& row : lr.sensor_psd)
        for (std::size_t k = 0; k < nfine; ++k) m[k] += row[k] / static_cast<double>(lr.sensor_psd.size());
      rows_fine.push_back(m);
    }
    std::vector<double> expected, raw;
    for (const auto& row : rows_fine) {
      const auto e = spectral::welch_expectation(*welch_, row, refine);
      expected.insert(expected.end(), e.begin(), e.end());
      progress.advance();
      for (std::size_t k = 0; k < f.size(); ++k) raw.push_back(row[k * refine]);
    }
    // Degrees of freedom of the ensemble mean per bin (B34b): the record is not stationary (the
    // response at a bin rises and falls with the ball's position, e.g. with phi_n(xi)^2 at a
    // resonance), so a Welch estimate holds fewer dof than the stationary D-16 value; the sensors
    // of one roll are correlated, so their mean holds fewer than n_sensors times one sensor's.
    // Cross-spectra per position block, smoothed by the Welch kernel truncated at +-4 bins.
    const std::size_t nf = f.size(), ns = model_.sensors.size(), pairs = ns * (ns + 1) / 2, reach = 4 * refine;
    const auto kern = spectral::welch_kernel(*welch_, refine);
    const std::size_t nk = kern.size();
    const std::vector<double> band(fine.begin(), fine.begin() + static_cast<std::ptrdiff_t>(half + 1));
    std::vector<std::complex<double>> cross((edges.size() - 1) * pairs * nf, 0.0);
    for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
      progress.advance();
      if (xw[p] == 0.0) continue;  // no segment sees this block
      const auto H = beam::linear_response_transfer(model_.beam, model_.ball.mass, k0, model_.contact.damping, xi[p],
                                                    model_.sensors, band, beam::Excitation::blocked_force);
      for (std::size_t k = 0; k < nf; ++k) {
        const std::size_t c = k * refine, j0 = c > reach ? c - reach : 0, j1 = std::min(half, c + reach);
        double norm = 0.0;
        for (std::size_t j = j0; j <= j1; ++j) norm += kern[(c + nk - j) % nk];
        std::size_t q = 0;
        for (std::size_t s1 = 0; s1 < ns; ++s1)
          for (std::size_t s2 = s1; s2 < ns; ++s2, ++q) {
            std::complex<double> acc = 0.0;
            for (std::size_t j = j0; j <= j1; ++j) acc += kern[(c + nk - j) % nk] * exc[j] * H[s1][j] * std::conj(H[s2][j]);
            cross[(p * pairs + q) * nf + k] = acc / norm;
          }
      }
    }
    progress.finish();
    std::vector<double> dof;
    for (std::size_t s = 0; s < ns; ++s) {
      std::vector<std::complex<double>> own((edges.size() - 1) * nf);
      const std::size_t q = s * ns - s * (s - 1) / 2;  // the (s, s) pair
      for (std::size_t p = 0; p + 1 < edges.size(); ++p)
        for (std::size_t k = 0; k < nf; ++k) own[p * nf + k] = cross[(p * pairs + q) * nf + k];
      const auto d = spectral::welch_block_dof(*welch_, n, edges, 1, nf, own);
      for (double v1 : d) dof.push_back(realisations * v1);
    }
    if (rows() > ns) {
      const auto d = spectral::welch_block_dof(*welch_, n, edges, ns, nf, cross);
      for (double v1 : d) dof.push_back(realisations * v1);
    }
    // Where the ensemble mean of K realisations falls with probability `confidence` if the
    // reference is right: nu P / S ~ chi2(nu) (D-16) with this dof.
    std::vector<double> lower(expected.size()), upper(expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const auto fi = spectral::chi_square_interval(std::max(dof[i], 1.0), confidence_);
      lower[i] = expected[i] / fi.upper;
      upper[i] = expected[i] / fi.lower;
    }
    w.write("/reference/psd", {rows(), f.size()}, expected.data(), "(m/s^2)^2/Hz",
            "expected Welch estimate (D-20) of the linearised model's frequency-domain PSD, averaged over ball positions");
    w.write("/reference/psd_raw", {rows(), f.size()}, raw.data(), "(m/s^2)^2/Hz",
            "the frequency-domain PSD itself at the bin frequencies (not window-smoothed)");
    w.write("/reference/degrees_of_freedom", {rows(), f.size()}, dof.data(), "1",
            "chi-square dof of the ensemble mean per bin for the non-stationary record (kernels/beam B34b; "
            "/psd/degrees_of_freedom is the stationary value)");
    w.write("/reference/mean_lower", {rows(), f.size()}, lower.data(), "(m/s^2)^2/Hz",
            "lower end of the range that holds the ensemble mean with the study's confidence if /reference/psd is right");
    w.write("/reference/mean_upper", {rows(), f.size()}, upper.data(), "(m/s^2)^2/Hz",
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
    w.write("/time_history/compression", {nh, n}, delta.data(), "m", "contact compression delta (D-1)");
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
  bool linearised_ = false, uses_table_ = false, blocked_solver_ = false, quiet_ = false;
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
