#include "src/scenes/ball_on_beam.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/dopri5_reference.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/linear_reference.hpp"
#include "kernels/beam/modal_beam.hpp"
#include "kernels/beam/path_contact_table.hpp"
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
#include "src/scenes/ball_on_beam_settings.hpp"
#include "src/scenes/ball_on_beam_writer.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/study/key_reader.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/stiffness/strip_equivalent_roughness.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;

namespace {

struct Workspace {
  std::vector<double> texture, u_phase, u_amp, f0_phase, f0_amp;
  std::unique_ptr<spectral::SynthesisScratch> line_scratch, f0_scratch;  // made on the thread's first realisation
  beam::BallOnBeamResult result;
  spectral::WelchWorkspace welch;
  Workspace(std::size_t n_texture, std::size_t harmonics, std::size_t segment)
      : texture(n_texture), u_phase(harmonics), u_amp(harmonics), welch(segment) {}
};

class BallOnBeam final : public EnsembleScene {
 public:
  explicit BallOnBeam(const KeyReader& s) : b_(read_ball_on_beam_settings(s)) {
    lines_ = texture_io::line_generator(b_.line_keys, b_.line_psd, b_.spacing, b_.line_samples);
    welch_ = std::make_unique<spectral::WelchPlan>(b_.welch);
    std::vector<std::string> names;
    for (std::size_t k = 0; k < b_.model.sensors.size(); ++k) names.push_back("sensor_" + std::to_string(k + 1));
    rows_ = std::make_unique<PsdRows>(names, b_.sensor_mean, welch_->frequencies(), b_.band_min, b_.band_max,
                                      2 * welch_->n_freq() + 1);
    for (int t = 0; t < ensemble::ensemble_threads(); ++t)
      workspaces_.push_back(std::make_unique<Workspace>(b_.line_samples, lines_->harmonics(), b_.welch.segment));
    add_pipeline_stages(s);
  }

  // texture, surface, stiffness_table, blocked_force, dynamics, spectra: the tables are stage
  // objects whose inspection `plan` prints and whose resolution prepare() runs.
  void add_pipeline_stages(const KeyReader& s) {
    if (b_.path_law())
      add_stages(
          {{"texture", StageStatus::skipped, "law = path: the path table's strip is the roughness (no line texture)"}});
    else if (b_.strip_line)
      add_stages({{"texture", StageStatus::skipped,
                   "equivalent_roughness.line = strip: h_eq of strip 0 along the path is the line (no synthesis)"}});
    else
      add_stages({{"texture", StageStatus::run,
                   "beam line texture per realisation from [texture] (" + b_.psd.description + "); " +
                       contact_filter_description(b_)}});
    const stiffness::TableStudy tables = stiffness::TableStudy::parse(s);
    std::unique_ptr<TableStage> table;
    if (uses_table()) {
      const double radius = b_.model.contact.radius, e_star = b_.model.contact.effective_modulus;
      table = std::make_unique<TableStage>(
          "stiffness_table", stiffness::stiffness_cached_table(tables, radius, e_star),
          [] { return std::make_unique<stiffness::StiffnessTable>(); },
          [tables, radius, e_star](stiffness::TableData& out, bool quiet) {
            static_cast<stiffness::StiffnessTable&>(out) = stiffness::build_table(tables, radius, e_star, quiet);
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
    if (table)
      add_stage(std::move(table));
    else
      add_stages({{"stiffness_table", StageStatus::skipped,
                   linearised()    ? "linearised law: k0 from [contact]"
                   : b_.path_law() ? "path law: P(delta, xi) from the path table"
                                   : "hertz law: analytic, needs no table"}});
    if (blocked_solver()) {
      // The strip's grid: the study's keys where set, else derived from the contact radius and the
      // texture; the path step at most v / f_s so F0 reaches the output's Nyquist frequency.
      const stiffness::BlockedForceGeometry grid = blocked_force_grid();
      add_contact_table_stage("blocked_force", tables, grid, &stiffness::blocked_force_cached_table,
                              &stiffness::build_blocked_force, &BallOnBeam::use_blocked_force, grid.describe());
    } else {
      add_stages({{"blocked_force", linearised() ? StageStatus::run : StageStatus::skipped,
                   linearised() ? "F0(t) = W + k0 h_patch(v t) per realisation (linear contact spring)"
                                : "only the linearised law uses F0"}});
    }
    if (solver_filter() && b_.strip_line) {
      // line = strip: h_eq of strip 0 on the path table's grid and positions (the strip law = path uses).
      const stiffness::PathTableGeometry grid = path_grid();
      add_contact_table_stage("equivalent_roughness", tables, grid, &stiffness::strip_equivalent_roughness_cached_table,
                              &stiffness::build_strip_equivalent_roughness, &BallOnBeam::use_strip_equivalent_roughness,
                              stiffness::strip_equivalent_roughness_describe(grid));
    } else if (solver_filter()) {
      // filter = solver (kernels/contact ER-1..ER-6): h_eq on the blocked-force grid, the path step
      // at most v / f_s so the h_eq PSD reaches the band limit (B40).
      const stiffness::BlockedForceGeometry grid = blocked_force_grid();
      add_contact_table_stage("equivalent_roughness", tables, grid, &stiffness::equivalent_roughness_cached_table,
                              &stiffness::build_equivalent_roughness, &BallOnBeam::use_equivalent_roughness,
                              stiffness::equivalent_roughness_describe(tables, grid));
    }
    if (b_.path_law()) {
      // law = path (kernels/beam B41-B46): P(delta, xi) of strip 0 along the ball's whole path.
      const stiffness::PathTableGeometry grid = path_grid();
      add_contact_table_stage("path_table", tables, grid, &stiffness::path_cached_table, &stiffness::build_path_table,
                              &BallOnBeam::use_path_table,
                              grid.describe() +
                                  "; every realisation rolls over this one strip (nothing else is random: K > 1 "
                                  "repeats the same run)");
    }
    add_stages({{"dynamics", StageStatus::run,
                 b_.dopri ? "Dormand-Prince 5(4) reference" : "exact modal step per mode, implicit contact force"},
                {"spectra", StageStatus::run, "Welch PSDs of sensors, contact force and ball; ensemble mean"},
                {"reference", writes_reference() ? StageStatus::run : StageStatus::skipped,
                 !linearised()  ? "only the linearised law has a frequency-domain reference"
                 : b_.reference ? "frequency-domain PSD of the linearised model, its expected Welch estimate and the "
                                  "range of the ensemble mean, once after the ensemble"
                                : "[output] reference = false"}});
  }

  // The path table's grid along the ball's whole path (law = path, and line = strip on its grid).
  stiffness::PathTableGeometry path_grid() const {
    return stiffness::path_table_geometry(b_.path_table, b_.blocked_force, b_.strip_surface, b_.texture_psd,
                                          b_.model.contact.radius, b_.model.contact.effective_modulus, b_.weight(),
                                          b_.model.traverse.x_end - b_.model.traverse.x_start);
  }

  // The strip's grid: the study's keys where set, else derived from the contact radius and the
  // texture; the path step at most v / f_s so F0 (and h_eq) reach the output's Nyquist frequency.
  stiffness::BlockedForceGeometry blocked_force_grid() const {
    return stiffness::blocked_force_geometry(b_.blocked_force, b_.strip_surface, b_.texture_psd,
                                             b_.model.contact.radius, b_.model.contact.effective_modulus, b_.weight(),
                                             b_.model.traverse.speed / b_.model.sample_rate);
  }

  // A cached table of strip 0 that the contact law takes: its file and hash from (study, grid, R, E*,
  // W), built from the same, completed by a use_* member.
  template <class Table, class Grid>
  void add_contact_table_stage(const char* name, const stiffness::TableStudy& s, const Grid& grid,
                               stiffness::CachedTable (*cached)(const stiffness::TableStudy&, const Grid&, double,
                                                                double, double),
                               Table (*build)(const stiffness::TableStudy&, const Grid&, double, double, double, bool),
                               void (BallOnBeam::*use)(const Table&, const std::string&, bool), std::string detail) {
    const double radius = b_.model.contact.radius, e_star = b_.model.contact.effective_modulus, weight = b_.weight();
    add_stage(std::make_unique<TableStage>(
        name, cached(s, grid, radius, e_star, weight), [] { return std::make_unique<Table>(); },
        [s, grid, radius, e_star, weight, build](stiffness::TableData& out, bool quiet) {
          static_cast<Table&>(out) = build(s, grid, radius, e_star, weight, quiet);
        },
        [this, use](const stiffness::TableData& t, const std::string& status, bool quiet) {
          (this->*use)(static_cast<const Table&>(t), status, quiet);
        },
        std::move(detail)));
  }

  void prepare(bool quiet, bool rebuild) override {
    quiet_ = quiet;
    resolve_stages(quiet, rebuild);  // the tables' use_* complete the contact law
    integrator_ = std::make_unique<beam::ExactStepIntegrator>(b_.model, b_.step);
  }

  void use_stiffness_table(const stiffness::StiffnessTable& t, const std::string& status, bool quiet) {
    if (!quiet) std::fprintf(stderr, "stiffness table: %s\n", status.c_str());
    b_.model.contact.compression = t.approach;
    if (b_.model.contact.kind == beam::ContactLawKind::table) {
      b_.model.contact.values = t.force_mean;
    } else {  // seed 001 Eq. 7 literally: k_c(delta) from the table's stiffness, F = k_c(delta) delta
      b_.model.contact.values = t.stiffness_mean;
      b_.model.contact.values[0] = t.stiffness_mean[1];
    }
    b_.static_compression = t.approach_at(b_.weight());
    if (!(b_.static_compression > 0.0))
      b_.stiffness.approach_max_origin.refuse("the table's largest force " + std::to_string(t.force_mean.back()) +
                                              " N does not reach the ball's weight; raise approach_max");
    check_contact_resolution(b_, t.stiffness_at(b_.weight()));
  }

  // law = path (B46): the table is the law; the line roughness is not used (the strip is the roughness).
  void use_path_table(const stiffness::PathTableData& t, const std::string& status, bool quiet) {
    beam::PathContactData d{t.position, t.approach, t.first_contact, t.force};
    b_.model.contact.path = std::make_shared<const beam::PathContactTable>(std::move(d));
    b_.model.contact.path_origin = b_.model.traverse.x_start;
    b_.static_compression = beam::path_table_static_approach(*b_.model.contact.path, b_.weight());
    if (!quiet)
      std::fprintf(stderr,
                   "path table: %s (%zu approaches x %zu positions; mean static approach %.4g m from the mean plane)\n",
                   status.c_str(), t.approach.size(), t.position.size(), b_.static_compression);
  }

  // line = strip: h_eq(xi_k) of strip 0 is the line, xi_0 at the traverse's start (as the path law's
  // path_origin, B46), linear between positions as P(delta, xi) is.
  void use_strip_equivalent_roughness(const stiffness::EquivalentRoughnessTable& t, const std::string& status,
                                      bool quiet) {
    if (!quiet)
      std::fprintf(stderr, "equivalent roughness table: %s (strip 0, %zu positions, delta_smooth = %.4g m)\n",
                   status.c_str(), t.position.size(), t.smooth_approach);
    strip_line_ = beam::UniformSamples{b_.model.traverse.x_start, t.position.at(1) - t.position.at(0), t.height};
    apply_equivalent_stiffness(t, quiet);
  }

  // ER-7 ([equivalent_roughness] stiffness = strip): the point law stretched along the approach,
  // F'(delta) = F(rho delta), carries the weight at delta_W / rho with the strips' mean contact
  // stiffness rho k(delta_W): a rough strip is softer than the smooth contact h_eq alone assumes.
  void apply_equivalent_stiffness(const stiffness::EquivalentRoughnessTable& t, bool quiet) {
    if (!b_.equivalent_stiffness) return;
    const double rho = t.stiffness_ratio();
    beam::ContactLaw& law = b_.model.contact;
    switch (law.kind) {
      case beam::ContactLawKind::hertz:
        law.effective_modulus *= std::pow(rho, 1.5);  // (4/3) E* sqrt(R) (rho delta)^(3/2)
        break;
      case beam::ContactLawKind::table:
        for (double& c : law.compression) c /= rho;
        break;
      case beam::ContactLawKind::literal_stiffness:  // k_c'(delta) delta = rho k_c(rho delta) delta
        for (double& c : law.compression) c /= rho;
        for (double& v : law.values) v *= rho;
        break;
      default:
        return;
    }
    b_.static_compression /= rho;
    if (!quiet)
      std::fprintf(stderr,
                   "equivalent stiffness: the strips' mean contact stiffness at the weight is %.4g of the smooth "
                   "strip's; the point law is stretched along the approach by 1/%.4g (ER-7)\n",
                   rho, rho);
  }

  // filter = solver: the line is synthesised from the strip-mean PSD of h_eq (ER-2), band-limited
  // (B40), no patch average and so no B40a compensation. Below the table's third bin k1 (bins 1 and
  // 2 of a Hann segment hold the leakage of waves longer than the segment, as for the blocked force)
  // the line takes the first-order theory's shape, G_eq of ER-5 (iso2d, Eq. 38), times an even factor
  // that is 1 at k = 0 and meets the table at k1: G_eq(k) (1 + (rho1 - 1) (k/k1)^2), rho1 =
  // G_table(k1) / G_eq(k1). At long waves h_eq is the flat-punch average of ER-3 exactly, which on an
  // isotropic surface also averages the roughness across the path (G_eq(0) < G(0) where the surface
  // has power at wavelengths below 2a). A PSD without an isotropic form falls back to the raw line
  // G_raw (h_eq -> h, as for corrugation uniform across the path).
  void use_equivalent_roughness(const stiffness::EquivalentRoughnessTable& t, const std::string& status, bool quiet) {
    if (!quiet)
      std::fprintf(stderr, "equivalent roughness table: %s (%g strips x %zu positions, delta_smooth = %.4g m)\n",
                   status.c_str(), t.strips, t.position.size(), t.smooth_approach);
    auto table = std::make_shared<const stiffness::EquivalentRoughnessTable>(t);
    texture::Psd low = b_.texture_psd;
    try {
      low = iso2d_line_psd(b_);
    } catch (const std::exception&) {  // no isotropic form: the raw line's shape
    }
    const std::size_t anchor = std::min<std::size_t>(3, t.psd_wavenumber.size() - 1);
    const double k1 = t.psd_wavenumber.size() > 1 ? t.psd_wavenumber[anchor] : 0.0;
    texture::Psd p;
    p.density = [table, low, k1](double k) {
      if (k >= k1 || !(k > 0.0)) return table->psd_at(k);
      const double g1 = low(k1);
      if (!(g1 > 0.0)) return table->psd_at(k);
      const double r = k / k1;
      return low(k) * (1.0 + (table->psd_at(k1) / g1 - 1.0) * r * r);
    };
    p.support_min = b_.texture_psd.support_min;
    p.support_max = t.psd_wavenumber.empty() ? 0.0 : t.psd_wavenumber.back();
    p.description = "PSD of the equivalent roughness h_eq on " + std::to_string(t.position.size()) + " positions x " +
                    std::to_string(static_cast<long long>(t.strips)) + " strips (kernels/contact ER-2)";
    for (std::size_t j = 1; j < t.psd_wavenumber.size(); ++j) p.breakpoints.push_back(t.psd_wavenumber[j]);
    b_.line_psd = std::isfinite(b_.band_limit_wavenumber)
                      ? texture::band_limited(std::move(p), b_.band_limit_wavenumber)
                      : std::move(p);
    apply_equivalent_stiffness(t, quiet);
    lines_ = texture_io::line_generator(b_.line_keys, b_.line_psd, b_.spacing, b_.line_samples);
    for (auto& ws : workspaces_) {
      ws->u_phase.resize(lines_->harmonics());
      ws->u_amp.resize(lines_->harmonics());
    }
  }

  // The contact solver's blocked force (seed 002 §4.2): k0 from the table, F0(t) synthesised per
  // realisation from the table's PSD along the path, G_t(f) = 2 pi G_k(2 pi f / v) / v (D-2),
  // sampled at the integration step.
  void use_blocked_force(const stiffness::BlockedForceTable& table, const std::string& status, bool quiet) {
    blocked_ = table;
    if (!quiet)
      std::fprintf(stderr, "blocked force table: %s (k0 = %.4g N/m, d0 = %.4g m)\n", status.c_str(), blocked_.k0,
                   blocked_.approach);
    const double weight = b_.weight();
    b_.model.contact.k0 = blocked_.k0;
    b_.static_compression = weight / blocked_.k0;
    check_contact_resolution(b_, blocked_.k0);
    f0_step_ = b_.integration_step();
    auto n = static_cast<std::size_t>(std::ceil(beam::traverse_duration(b_.model.traverse) / f0_step_)) + 4;
    n = texture::fast_even_length(n);
    f0_synth_ = std::make_unique<spectral::HarmonicSynthesiser>(n);
    const double df = 1.0 / (static_cast<double>(n) * f0_step_);
    f0_psd_.assign(f0_synth_->harmonics(), 0.0);
    for (std::size_t j = 1; j < f0_psd_.size(); ++j) {
      const double f = df * static_cast<double>(j);
      f0_psd_[j] = blocked_force_time_psd(f);
    }
    f0_df_ = df;
    f0_half_amplitudes_ = spectral::synthesis_half_amplitudes(f0_psd_.data(), f0_psd_.size(), df);
  }

  // F0 PSD along the path: the table's, and at long wavelengths, where the ball follows the
  // texture (F0 = W + k0 h), the texture's shape scaled to the table at its third bin: bins 1 and 2
  // of a Hann-windowed segment hold the leakage of waves longer than the segment (the strip is finite).
  double blocked_force_psd(double k) const {
    if (k > b_.band_limit_wavenumber) return 0.0;  // B40, as the texture
    const std::size_t anchor = std::min<std::size_t>(3, blocked_.psd_wavenumber.size() - 1);
    const double k1 = blocked_.psd_wavenumber.size() > 1 ? blocked_.psd_wavenumber[anchor] : 0.0;
    if (k >= k1 || !(k > 0.0)) return blocked_.psd_at(k);
    const double g1 = b_.psd(k1);
    return g1 > 0.0 ? blocked_.psd_at(k1) * b_.psd(k) / g1 : blocked_.psd_at(k);
  }

  double blocked_force_time_psd(double f) const {
    const double v = b_.model.traverse.speed;
    return 2.0 * M_PI * blocked_force_psd(2.0 * M_PI * f / v) / v;
  }

  std::size_t rows() const { return rows_->rows(); }
  // PsdRows layout, then the extras: contact-force PSD, ball-acceleration PSD, loss-of-contact share.
  std::size_t values_per_realisation() const override { return rows_->size(); }

  // Simulates realisation `id` into ws.result (shared by the ensemble and the time-history output).
  void simulate(std::uint64_t id, Workspace& ws) const {
    const std::size_t nh = lines_->harmonics();
    if (!blocked_solver() && !b_.path_law() && !b_.strip_line) {
      rng::PhiloxStream(b_.seed, id, rng::Stream::roughness_phase).uniform_open(ws.u_phase.data(), nh);
      rng::PhiloxStream(b_.seed, id, rng::Stream::roughness_amplitude).uniform_open(ws.u_amp.data(), nh);
      if (!ws.line_scratch) ws.line_scratch = std::make_unique<spectral::SynthesisScratch>(lines_->period());
      lines_->generate(ws.u_phase.data(), ws.u_amp.data(), ws.texture.data(), *ws.line_scratch);
    }
    const bool no_line = blocked_solver() || b_.path_law();  // their strip resolves the roughness
    beam::UniformSamples h{0.0, b_.spacing, no_line ? std::vector<double>() : ws.texture};
    if (b_.patch_half_width > 0.0 && !no_line) h = beam::contact_patch_average(h, b_.patch_half_width);
    beam::Realisation r;
    if (blocked_solver()) {
      const std::size_t nh_f0 = f0_synth_->harmonics(), n = f0_synth_->samples();
      ws.f0_phase.resize(nh_f0);
      ws.f0_amp.resize(nh_f0);
      if (!ws.f0_scratch) ws.f0_scratch = std::make_unique<spectral::SynthesisScratch>(n);
      rng::PhiloxStream(b_.seed, id, rng::Stream::blocked_force_phase).uniform_open(ws.f0_phase.data(), nh_f0);
      rng::PhiloxStream(b_.seed, id, rng::Stream::blocked_force_amplitude).uniform_open(ws.f0_amp.data(), nh_f0);
      r.blocked_force.origin = 0.0;
      r.blocked_force.step = f0_step_;
      r.blocked_force.values.resize(n);
      f0_synth_->synthesise(f0_half_amplitudes_.data(), spectral::Amplitudes::rayleigh, ws.f0_phase.data(),
                            ws.f0_amp.data(), r.blocked_force.values.data(), *ws.f0_scratch);
      for (double& f : r.blocked_force.values) f += b_.weight();
    } else if (linearised()) {
      // Blocked force of a linear contact spring: F0(t) = W + k0 h(x_start + v t) (D-11).
      const double v = b_.model.traverse.speed, x0 = b_.model.traverse.x_start, dt = b_.spacing / v;
      const auto first = static_cast<std::size_t>(std::floor(x0 / b_.spacing));
      r.blocked_force.origin = (static_cast<double>(first) * b_.spacing - x0) / v;
      r.blocked_force.step = dt;
      const double weight = b_.weight();
      r.blocked_force.values.reserve(h.values.size() - std::min(first, h.values.size()));
      for (std::size_t i = first; i < h.values.size(); ++i)
        r.blocked_force.values.push_back(weight + b_.model.contact.k0 * h.values[i]);
    } else if (b_.strip_line) {
      r.roughness = strip_line_;
    } else if (!b_.path_law()) {
      r.roughness = std::move(h);
    }
    if (b_.dopri) {
      beam::ReferenceTolerances tol;
      tol.rtol = b_.rtol;
      ws.result = beam::simulate_dopri5(b_.model, r, tol);
    } else {
      integrator_->run(r, ws.result);
    }
  }

  void run_realisation(std::uint64_t id, int thread, double* values) const override {
    Workspace& ws = *workspaces_[static_cast<std::size_t>(thread)];
    simulate(id, ws);
    const std::size_t nf = welch_->n_freq(), ns = b_.model.sensors.size(), n = ws.result.samples() - b_.skip;
    for (std::size_t s = 0; s < ns; ++s)
      welch_->psd(ws.result.sensor_acceleration[s].data() + b_.skip, n, rows_->row(values, s), ws.welch);
    rows_->finish(values);
    double* x = rows_->extras(values);
    welch_->psd(ws.result.contact_force.data() + b_.skip, n, x, ws.welch);
    welch_->psd(ws.result.ball_acceleration.data() + b_.skip, n, x + nf, ws.welch);
    x[2 * nf] = ws.result.loss_of_contact_share;
  }

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override {
    BallOnBeamWriter(
        b_, *welch_, *rows_, lines_->fundamental(), blocked_, [this](double f) { return blocked_force_time_psd(f); },
        quiet_)
        .write(w, sums);
    if (b_.time_histories) write_time_histories(w, sums.only);
  }

 private:
  // Realisations 0..n-1 again (deterministic: same Philox keys), so histories survive --resume;
  // with --only, the history of that one realisation.
  void write_time_histories(io::Hdf5Writer& w, std::int64_t only) const {
    Workspace& ws = *workspaces_[0];
    const std::size_t n = b_.samples, ns = b_.model.sensors.size(), nh = only >= 0 ? 1 : b_.time_histories;
    std::vector<double> t(n), acc(nh * ns * n), force(nh * n), ball(nh * n), delta(nh * n);
    for (std::size_t j = 0; j < n; ++j) t[j] = static_cast<double>(j) / b_.model.sample_rate;
    for (std::size_t r = 0; r < nh; ++r) {
      simulate(only >= 0 ? static_cast<std::uint64_t>(only) : r, ws);
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
    for (const char* d :
         {"/time_history/contact_force", "/time_history/ball_acceleration", "/time_history/compression"})
      w.attach_scale(d, "/time_history/time", 1);
    w.attribute("/time_history", "realisations",
                only >= 0 ? std::to_string(only) : "0.." + std::to_string(b_.time_histories - 1));
  }

  BallOnBeamSettings b_;
  bool linearised() const { return b_.linearised(); }
  bool uses_table() const { return b_.uses_table(); }
  bool blocked_solver() const { return b_.blocked_solver(); }
  bool solver_filter() const { return b_.filter == ContactFilter::solver; }
  bool writes_reference() const { return b_.linearised() && b_.reference; }
  bool quiet_ = false;
  stiffness::BlockedForceTable blocked_;
  std::unique_ptr<spectral::HarmonicSynthesiser> f0_synth_;
  std::vector<double> f0_psd_, f0_half_amplitudes_;
  double f0_step_ = 0.0, f0_df_ = 0.0;
  std::unique_ptr<texture::LineTextureGenerator> lines_;
  std::unique_ptr<beam::ExactStepIntegrator> integrator_;
  beam::UniformSamples strip_line_;  // [equivalent_roughness] line = strip: h_eq of strip 0 along the path
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace

std::unique_ptr<Scene> make_ball_on_beam(const KeyReader& s) { return std::make_unique<BallOnBeam>(s); }

}  // namespace rollspec::scenes
