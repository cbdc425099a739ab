#include "src/scenes/rolling_pipe.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/scenes/study_welch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/line_texture.hpp"
#include "src/error.hpp"
#include "src/io/hdf5_file.hpp"
#include "src/io/psd_result.hpp"
#include "src/rng/philox_stream.hpp"
#include "src/study/study.hpp"
#include "src/texture/texture_keys.hpp"

namespace rollspec::scenes {

using namespace study;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {
const double inf = std::numeric_limits<double>::infinity();
const double kPi = 3.141592653589793;

// Free-free Euler-Bernoulli bending: beta_n L = 4.7300, 7.8532, 10.9956, (2n+1) pi/2 beyond.
double free_free_frequency(int n, double length, double ei, double rho_a) {
  const double bl[] = {4.730040744862704, 7.853204624095838, 10.995607838001671};
  const double b = (n < 3 ? bl[n] : (2.0 * n + 3.0) * kPi / 2.0) / length;
  return b * b * std::sqrt(ei / rho_a) / (2.0 * kPi);
}

// Extra values stored after the spectra of one realisation.
enum Extra : std::size_t { curvature_ratio, invalid_contact, open_share, newton_per_step, speed_ratio, extras };
}  // namespace

std::vector<KeySpec> rolling_pipe_keys() {
  std::vector<KeySpec> k = {
      real_key("pipe", "length", "m", "tube length (its axis lies across the rolling direction)", std::string("1"), 0.0, inf, false),
      real_key("pipe", "diameter", "m", "outer diameter (the contact spheres' diameter)", std::string("0.06"), 0.0, inf, false),
      real_key("pipe", "inner_diameter", "m", "inner diameter (0: solid bar)", std::string("0.052"), 0.0, inf),
      real_key("pipe", "youngs_modulus", "Pa", "Young's modulus", std::string("210e9"), 0.0, inf, false),
      real_key("pipe", "poisson", "-", "Poisson's ratio", std::string("0.3"), -1.0, 0.5, false, false),
      real_key("pipe", "density", "kg/m^3", "density", std::string("7850"), 0.0, inf, false),
      integer_key("pipe", "elements", "quadratic 3-node beam elements along the tube (2n + 1 contact nodes)", std::string("4"), 1, 1000),
      real_key("roll", "speed", "m/s", "initial rolling speed v (spin v/r: rolling without slip)", std::string("0.5"), 0.0, inf, false),
      real_key("roll", "distance", "m", "distance rolled during the record (record length distance/speed)", std::string("0.3"), 0.0, inf, false),
      choice_key("roughness", "kind",
                 "line: a line texture along the rolling direction, the same under every node; isotropic: an isotropic "
                 "surface realisation from [surface] (spectral or seed method), different under every node",
                 std::string("line"), {"line", "isotropic"}),
      real_key("roughness", "spacing", "m", "sample spacing of the line texture", std::string("1e-3"), 0.0, inf, false),
      real_key("contact", "friction", "-", "Coulomb coefficient mu (0: frictionless, the tube slides)", std::string("0.3"), 0.0, inf),
      real_key("contact", "penalty_normal", "N/m", "normal penalty eps_n per contact node", std::string("2e7"), 0.0, inf, false),
      real_key("contact", "penalty_tangential", "N/m", "tangential penalty eps_t per contact node", std::string("2e6"), 0.0, inf, false),
      real_key("contact", "damping_ratio", "-",
               "normal contact damper per node as a ratio of critical on the node's lumped mass: c = 2 zeta sqrt(eps_n m_node)",
               std::string("0.1"), 0.0, 10.0),
      bool_key("contact", "rolling", "rolling correction of the tangential gap (false: seed 000's 'no rolling')", std::string("true")),
      real_key("gravity", "acceleration", "m/s^2", "gravity, normal to the mean surface", std::string("9.81"), 0.0, inf, false),
      real_key("analysis", "dt", "s", "time step (also the sampling interval of the spectra)", std::string("1e-4"), 0.0, inf, false),
      real_key("analysis", "tolerance", "-", "Newton convergence: residual 2-norm relative to the tube's weight",
               std::string("1e-8"), 0.0, 1.0, false),
      text_key("sensors", "positions", "sensor positions along the tube as fractions of its length (nearest node), comma-separated",
               std::string("0,0.5,1")),
      bool_key("sensors", "average", "add the mean PSD over sensors", std::string("true")),
      real_key("spectrum", "skip_start", "s", "start of the record left out of the spectra (settling on the surface)",
               std::string("0.02"), 0.0, inf),
  };
  for (auto& key : texture_io::psd_keys()) k.push_back(key);
  for (auto& key : texture_io::surface_keys()) k.push_back(key);
  return k;
}

namespace {

class RollingPipe final : public Scene {
 public:
  explicit RollingPipe(const Study& s)
      : seed_(static_cast<std::uint64_t>(s.integer("study.seed"))),
        psd_(texture_io::study_psd(s)),
        line_(s.text("roughness.kind") == "line"),
        average_(s.boolean("sensors.average")),
        confidence_(s.real("spectrum.confidence")),
        band_min_(s.real("spectrum.band_min")),
        band_max_(s.real("spectrum.band_max")) {
    using namespace rolling;
    const double d = s.real("pipe.diameter"), di = s.real("pipe.inner_diameter");
    if (di >= d) s.refuse("pipe.inner_diameter", "must be smaller than [pipe] diameter");
    radius_ = 0.5 * d;
    length_ = s.real("pipe.length");
    section_ = circular_section(s.real("pipe.youngs_modulus"), s.real("pipe.poisson"), s.real("pipe.density"), d, di);
    elements_ = static_cast<int>(s.integer("pipe.elements"));
    speed_ = s.real("roll.speed");
    distance_ = s.real("roll.distance");
    dt_ = s.real("analysis.dt");
    g_ = s.real("gravity.acceleration");
    steps_ = static_cast<std::size_t>(std::llround(distance_ / speed_ / dt_));
    if (steps_ < 16) s.refuse("roll.distance", "gives fewer than 16 time steps at [analysis] dt");
    if (steps_ > 50'000'000) s.refuse("analysis.dt", "gives more than 5e7 steps per realisation");
    const int nodes = 2 * elements_ + 1;
    // Lumped node mass of the quadratic elements: m_e (1/6, 2/3, 1/6), so an interior end node
    // carries m_e/3 and a mid node 2 m_e/3; the stiffest contact oscillation is at the lightest.
    const double m_e = section_.rhoA * length_ / elements_;
    const double m_light = m_e / 6.0, m_mid = 2.0 * m_e / 3.0;
    law_.radius = radius_;
    law_.eps_n = s.real("contact.penalty_normal");
    law_.eps_t = s.real("contact.penalty_tangential");
    law_.mu = s.real("contact.friction");
    law_.rolling = s.boolean("contact.rolling");
    zeta_ = s.real("contact.damping_ratio");
    // The damper of each node follows its lumped mass: c = 2 zeta sqrt(eps_n m_node).
    for (int i = 0; i < nodes; ++i) {
      const double mn = i % 2 == 1 ? m_mid : (i == 0 || i == nodes - 1 ? m_light : 2.0 * m_light);
      damping_.push_back(2.0 * zeta_ * std::sqrt(law_.eps_n * mn));
    }
    // The step must resolve the contact oscillation of the lightest node: dt <= T_c / 20 (kernels/README.md D-23).
    const double tc = 2.0 * kPi * std::sqrt(m_light / law_.eps_n);
    if (dt_ > tc / 20.0) {
      std::ostringstream m;
      m << "= " << dt_ << " s does not resolve the contact oscillation of the lightest node (T_c = 2 pi sqrt(m/eps_n) = " << tc
        << " s); allowed: dt <= T_c/20 = " << tc / 20.0 << " s";
      s.refuse("analysis.dt", m.str());
    }
    // Sensors: nearest nodes.
    for (double f : s.numbers("sensors.positions")) {
      if (!(f >= 0.0 && f <= 1.0)) s.refuse("sensors.positions", "fraction " + std::to_string(f) + " lies outside [0, 1]");
      sensors_.push_back(static_cast<int>(std::lround(f * (nodes - 1))));
      sensor_fractions_.push_back(f);
    }
    if (sensors_.empty()) s.refuse("sensors.positions", "lists no sensor; allowed: fractions in [0, 1]");
    // The rolled strip: x from -margin to distance + margin (the spheres' footprint and a cell).
    x_lo_ = -(radius_ + 0.02 * distance_ + 0.01);
    x_hi_ = distance_ + radius_ + 0.02 * distance_ + 0.01;
    if (line_) {
      dx_ = s.real("roughness.spacing");
      const std::size_t samples = static_cast<std::size_t>(std::ceil((x_hi_ - x_lo_) / dx_)) + 1;
      if (samples > (1u << 24)) s.refuse("roughness.spacing", "gives more than 2^24 samples over the rolled strip");
      lines_ = texture_io::study_line_generator(s, psd_, dx_, samples, "roughness.spacing");
    } else {
      surfaces_ = std::make_unique<texture_io::SurfaceGenerator>(texture_io::study_surface_generator(s, psd_));
      dx_ = s.real("surface.spacing");
      const double nx = static_cast<double>(s.integer("surface.nx")), ny = static_cast<double>(s.integer("surface.ny"));
      const double need_x = x_hi_ - x_lo_, need_y = length_ + 2.0 * radius_ + 2.0 * dx_;
      if ((nx - 1.0) * dx_ < need_x || (ny - 1.0) * dx_ < need_y) {
        std::ostringstream m;
        m << "the surface grid covers " << (nx - 1.0) * dx_ << " m x " << (ny - 1.0) * dx_ << " m; allowed: at least "
          << need_x << " m along the rolling direction (nx) and " << need_y << " m along the tube (ny)";
        s.refuse("surface.nx", m.str());
      }
    }
    // A priori single-point check with the PSD's rms curvature sqrt(m4) over the sampled
    // band: a sphere sharper than the typical valley would touch at two points almost everywhere.
    const double k_hi = std::min(psd_.support_max, kPi / dx_);
    const double k_lo = std::max(psd_.support_min, 1e-6 * k_hi);  // k^4 G: nothing lost below
    const double m4 = k_hi > k_lo ? texture::integrate_psd(psd_, k_lo, k_hi, 4.0) : 0.0;
    rms_curvature_ = std::sqrt(m4);
    if (radius_ * rms_curvature_ > 0.5) {
      std::ostringstream m;
      m << "rms curvature of the roughness sqrt(m4) = " << rms_curvature_ << " 1/m times the contact radius " << radius_
        << " m is " << radius_ * rms_curvature_
        << ": the node spheres would touch at two points in most valleys; allowed: r sqrt(m4) <= 0.5 (raise the "
           "short wavelength cut-off or the roughness spacing)";
      s.refuse(line_ ? "roughness.spacing" : "surface.spacing", m.str());
    }
    samples_ = steps_ + 1;
    skip_ = static_cast<std::size_t>(std::ceil(s.real("spectrum.skip_start") / dt_));
    if (skip_ >= samples_) s.refuse("spectrum.skip_start", "leaves nothing of the record (" + std::to_string(samples_) + " samples)");
    const auto segment = static_cast<std::size_t>(s.integer("spectrum.segment"));
    if (segment > samples_ - skip_)
      s.refuse("spectrum.segment", "is longer than the analysed record (" + std::to_string(samples_ - skip_) +
                                       " samples = (distance / speed - skip_start) / dt)");
    welch_ = std::make_unique<spectral::WelchPlan>(study_welch_config(s, 1.0 / dt_));
    std::vector<std::string> names;
    for (std::size_t j = 0; j < sensors_.size(); ++j) names.push_back("sensor_" + std::to_string(j + 1));
    rows_ = std::make_unique<PsdRows>(names, average_, welch_->frequencies(), band_min_, band_max_, extras);
    for (int t = 0; t < ensemble::ensemble_threads(); ++t) workspaces_.push_back(std::make_unique<Workspace>(segment));
    options_.analysis = Analysis::Dynamic;
    options_.max_iterations = 30;
    options_.max_cuts = 12;
    options_.max_line_search = 8;
    options_.disp_tol = 1e-14;
    options_.force_tol = s.real("analysis.tolerance") * section_.rhoA * length_ * g_;
    add_stages(fixed_stages());  // after the members the descriptions name
  }

  std::vector<StagePlan> fixed_stages() const {
    return {
        {"texture", line_ ? StageStatus::run : StageStatus::skipped,
         line_ ? "line texture along the rolling direction per realisation (" + psd_.description + ")" : "isotropic surface instead"},
        {"surface", line_ ? StageStatus::skipped : StageStatus::run,
         line_ ? "a line texture is used" : "isotropic surface per realisation from [surface] (" + psd_.description + ")"},
        {"stiffness_table", StageStatus::skipped, "penalty node-sphere contact"},
        {"dynamics", StageStatus::run,
         "Newmark, " + std::to_string(steps_) + " steps, " + std::to_string(2 * elements_ + 1) +
             " rolling contact nodes with friction on the height field"},
        {"spectra", StageStatus::run, "Welch PSDs of the vertical acceleration at the sensor nodes; ensemble mean"},
    };
  }

  std::size_t values_per_realisation() const override { return rows_->size(); }

  void run_realisation(std::uint64_t id, int thread, double* values) const override {
    using namespace rolling;
    Workspace& ws = *workspaces_[static_cast<std::size_t>(thread)];
    Model m;
    m.surfaces.push_back(surface(id, ws));
    const HeightField& field = m.surfaces[0];
    const ContactValidity validity = footprint_validity(field);
    m.sections.push_back(section_);
    // Straight tube resting on the highest point under its nodes, lowered by the mean static
    // penetration; it settles within skip_start.
    const int nn = 2 * elements_ + 1;
    double top = -inf;
    for (int i = 0; i < nn; ++i) {
      const double y = -0.5 * length_ + length_ * i / (nn - 1);
      top = std::max(top, sample_height(field, Vector2d(0.0, y)).h);
    }
    const double z0 = top + radius_ - section_.rhoA * length_ * g_ / (nn * law_.eps_n);
    const auto ids = add_straight_beam(m, Vector3d(0.0, -0.5 * length_, z0), Vector3d(0.0, 0.5 * length_, z0), elements_, 0,
                                       Vector3d::UnitX());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      SurfaceContactLaw law = law_;
      law.damping = damping_[i];
      m.surface_contacts.push_back(SurfaceContactPair{ids[i], 0, law});
    }
    m.v0.assign(m.X.size(), Vector3d(speed_, 0.0, 0.0));
    m.w0.assign(m.X.size(), Vector3d(0.0, speed_ / radius_, 0.0));  // v + w x (-r e_z) = 0
    m.gravity = Vector3d(0.0, 0.0, -g_);
    RunOptions ro;
    ro.dt = dt_;
    ro.t_end = static_cast<double>(steps_) * dt_;
    for (int sn : sensors_) ro.record_nodes.push_back(ids[static_cast<std::size_t>(sn)]);
    ro.record_energies = false;  // spectra need accelerations only
    const History h = run(m, options_, ro);
    if (!h.completed) {
      std::ostringstream e;
      e << "realisation " << id << " (seed " << seed_ << "): Newton did not converge at t = " << h.failed_at
        << " s even after " << options_.max_cuts
        << " step halvings; reduce [analysis] dt, soften the penalties or smooth the roughness; rerun it alone with --only " << id;
      throw data_error(e.str());
    }
    const std::size_t ns = sensors_.size(), n = h.time.size() - skip_;
    std::vector<double>& a = ws.signal;
    a.resize(h.time.size());
    for (std::size_t j = 0; j < ns; ++j) {
      for (std::size_t k = 0; k < h.time.size(); ++k) a[k] = h.acceleration[k][j].z();
      welch_->psd(a.data() + skip_, n, rows_->row(values, j), ws.welch);
    }
    rows_->finish(values);
    double* x = rows_->extras(values);
    x[curvature_ratio] = radius_ * validity.max_concave_curvature;
    x[invalid_contact] = validity.valid ? 0.0 : 1.0;
    std::size_t open = 0, pairs = 0;
    for (std::size_t k = skip_; k < h.time.size(); ++k)
      for (const auto& c : h.surface_contact[k]) {
        open += c.active ? 0 : 1;
        ++pairs;
      }
    x[open_share] = static_cast<double>(open) / static_cast<double>(pairs);
    x[newton_per_step] = static_cast<double>(h.newton_iterations) / static_cast<double>(std::max(1, h.steps));
    const std::size_t mid = ns / 2;
    x[speed_ratio] = h.velocity.back()[mid].x() / speed_;
  }

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override {
    const double K = static_cast<double>(sums.count);
    auto mean_of = [&](std::size_t i) { return sums.mean(i); };
    auto std_of = [&](std::size_t i) { return sums.std_dev(i); };
    io::PsdEnsemble e = rows_->ensemble(sums);
    // Realisations differ by which nodes touch the floor (intermittent contact), far more than
    // Welch noise; the intervals come from their scatter (D-21), the Welch value is information.
    e.welch_dof = K * welch_->equivalent_dof(samples_ - skip_);
    e.window_enbw_bins = spectral::equivalent_noise_bandwidth_bins(welch_->window());
    e.confidence = confidence_;
    io::write_psd_result(w, e);

    const std::size_t x0 = rows_->extra_index(0);
    const double invalid = mean_of(x0 + invalid_contact) * K;
    const struct {
      const char* name;
      std::size_t index;
      const char* units;
      const char* what;
    } extras_out[] = {
        {"/contact/curvature_ratio", curvature_ratio, "1", "r kappa_max of the realisation's surface (< 1: single-point contact)"},
        {"/contact/open_share", open_share, "1", "share of node-time in loss of contact over the analysed record"},
        {"/contact/newton_per_step", newton_per_step, "1", "Newton iterations per time step"},
        {"/roll/speed_ratio", speed_ratio, "1", "rolling speed at the end of the record over the initial speed"},
    };
    for (const auto& o : extras_out) {
      const double v[2] = {mean_of(x0 + o.index), std_of(x0 + o.index)};
      w.write(o.name, {2}, v, o.units, std::string(o.what) + " (ensemble mean, standard deviation)");
    }
    w.write("/contact/two_point_realisations", {1}, &invalid, "1",
            "realisations whose surface has valleys sharper than the node sphere somewhere (r kappa_max >= 1)");
    if (invalid > 0.0)
      std::fprintf(stderr,
                   "rolling-pipe: warning: %.0f of %llu realisations have valleys sharper than the node spheres somewhere "
                   "(r kappa_max >= 1): contact there is a closest-point approximation\n",
                   invalid, static_cast<unsigned long long>(sums.count));
    w.attribute("/contact", "friction", law_.mu);
    w.attribute("/contact", "penalty_normal", law_.eps_n);
    w.attribute("/contact", "penalty_tangential", law_.eps_t);
    w.attribute("/contact", "damping_ratio", zeta_);
    w.attribute("/contact", "radius", radius_);
    w.attribute("/contact", "rms_curvature_ratio", radius_ * rms_curvature_);
    std::vector<double> sensor_nodes(sensors_.begin(), sensors_.end());
    w.write("/sensors/node", {sensor_nodes.size()}, sensor_nodes.data(), "1", "beam node of each sensor (0 at y = -length/2)");
    w.write("/sensors/position", {sensor_fractions_.size()}, sensor_fractions_.data(), "1", "sensor position as a fraction of the length");
    std::vector<double> ff;
    const double ei = section_.EI2;
    for (int i = 0; i < 6; ++i) ff.push_back(free_free_frequency(i, length_, ei, section_.rhoA));
    w.write("/pipe/free_free_frequency", {ff.size()}, ff.data(), "Hz",
            "Euler-Bernoulli free-free bending frequencies of the tube (orientation, no contact)");
    w.attribute("/pipe", "length", length_);
    w.attribute("/pipe", "outer_radius", radius_);
    w.attribute("/pipe", "mass", section_.rhoA * length_);
    w.attribute("/pipe", "elements", static_cast<std::int64_t>(elements_));
    w.attribute("/roll", "speed", speed_);
    w.attribute("/roll", "distance", distance_);
    w.attribute("/roll", "dt", dt_);
  }

 private:
  struct Workspace {
    std::vector<double> u_phase, u_amp, texture, signal;
    texture::Surface grid;
    spectral::WelchWorkspace welch;
    explicit Workspace(std::size_t segment) : welch(segment) {}
  };

  // R-62 over the strips the node spheres roll over (|y - y_node| <= r + one cell); a grid
  // surface elsewhere is never touched.
  rolling::ContactValidity footprint_validity(const rolling::HeightField& f) const {
    if (f.n2 == 1) return rolling::check_single_point_contact(f, radius_);
    rolling::ContactValidity worst;
    const int nn = 2 * elements_ + 1;
    for (int i = 0; i < nn; ++i) {
      const double y = -0.5 * length_ + length_ * i / (nn - 1);
      const int j0 = std::max(0, static_cast<int>(std::floor((y - radius_ - f.s2_0) / f.ds2)) - 1);
      const int j1 = std::min(f.n2 - 1, static_cast<int>(std::ceil((y + radius_ - f.s2_0) / f.ds2)) + 1);
      rolling::HeightField strip = f;
      strip.n2 = j1 - j0 + 1;
      strip.s2_0 = f.s2_0 + j0 * f.ds2;
      strip.h.assign(f.h.begin() + static_cast<std::ptrdiff_t>(j0) * f.n1, f.h.begin() + static_cast<std::ptrdiff_t>(j1 + 1) * f.n1);
      const auto v = rolling::check_single_point_contact(strip, radius_);
      if (v.max_concave_curvature > worst.max_concave_curvature) worst = v;
    }
    return worst;
  }

  // The realisation's surface from its Philox streams (roughness_* for lines, surface_* grids).
  rolling::HeightField surface(std::uint64_t id, Workspace& ws) const {
    rolling::HeightField f;
    f.base = rolling::make_plane(Vector3d::Zero(), Vector3d::UnitZ());  // t1 = x (rolling), t2 = y (tube axis)
    f.s1_0 = x_lo_;
    f.ds1 = dx_;
    if (line_) {
      const std::size_t nh = lines_->harmonics();
      ws.u_phase.resize(nh);
      ws.u_amp.resize(nh);
      ws.texture.resize(lines_->spec().samples);
      rng::PhiloxStream(seed_, id, rng::Stream::roughness_phase).uniform_open(ws.u_phase.data(), nh);
      rng::PhiloxStream(seed_, id, rng::Stream::roughness_amplitude).uniform_open(ws.u_amp.data(), nh);
      lines_->generate(ws.u_phase.data(), ws.u_amp.data(), ws.texture.data());
      f.n1 = static_cast<int>(ws.texture.size());
      f.n2 = 1;
      f.h = ws.texture;
    } else {
      surfaces_->generate(seed_, id, ws.grid);
      f.n1 = static_cast<int>(ws.grid.nx);
      f.n2 = static_cast<int>(ws.grid.ny);
      f.ds2 = ws.grid.dy;
      f.s2_0 = -0.5 * static_cast<double>(ws.grid.ny - 1) * ws.grid.dy;
      f.h = ws.grid.heights;
    }
    return f;
  }

  std::uint64_t seed_;
  texture::Psd psd_;
  bool line_, average_;
  double confidence_, band_min_, band_max_;
  double radius_ = 0.0, length_ = 0.0, speed_ = 0.0, distance_ = 0.0, dt_ = 0.0, g_ = 0.0, dx_ = 0.0;
  double x_lo_ = 0.0, x_hi_ = 0.0, zeta_ = 0.0, rms_curvature_ = 0.0;
  std::vector<double> damping_;  // per node, N s/m
  int elements_ = 1;
  std::size_t steps_ = 0, samples_ = 0, skip_ = 0;
  rolling::BeamSection section_;
  rolling::SurfaceContactLaw law_;
  rolling::SolverOptions options_;
  std::vector<int> sensors_;
  std::vector<double> sensor_fractions_;
  std::unique_ptr<texture::LineTextureGenerator> lines_;
  std::unique_ptr<texture_io::SurfaceGenerator> surfaces_;
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace

std::unique_ptr<Scene> make_rolling_pipe(const Study& s) { return std::make_unique<RollingPipe>(s); }

}  // namespace rollspec::scenes
