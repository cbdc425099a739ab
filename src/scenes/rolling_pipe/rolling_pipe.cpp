#include "src/scenes/rolling_pipe/rolling_pipe.hpp"
#include "src/scenes/rolling_pipe/rolling_pipe_settings.hpp"
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
#include "src/study/key_reader.hpp"
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

namespace {

class RollingPipe final : public EnsembleScene {
 public:
  explicit RollingPipe(const KeyReader& s) : p_(read_rolling_pipe_settings(s)) {
    if (p_.line) {
      lines_ = texture_io::line_generator(p_.line_keys, p_.psd, p_.spacing, p_.line_samples);
    } else {
      surfaces_ =
          std::make_unique<texture_io::SurfaceGenerator>(texture_io::surface_generator(p_.texture, p_.surface, p_.psd));
    }
    welch_ = std::make_unique<spectral::WelchPlan>(p_.welch);
    rows_ = std::make_unique<PsdRows>(numbered_sensors(p_.sensor_nodes.size()), p_.sensor_mean, welch_->frequencies(),
                                      p_.band_min, p_.band_max, extras);
    for (int t = 0; t < ensemble::ensemble_threads(); ++t)
      workspaces_.push_back(std::make_unique<Workspace>(p_.welch.segment));
    add_stages(fixed_stages());  // after the members the descriptions name
  }

  std::vector<StagePlan> fixed_stages() const {
    return {
        {"texture", p_.line ? StageStatus::run : StageStatus::skipped,
         p_.line ? "line texture along the rolling direction per realisation (" + p_.psd.description + ")"
                 : "isotropic surface instead"},
        {"surface", p_.line ? StageStatus::skipped : StageStatus::run,
         p_.line ? "a line texture is used"
                 : "isotropic surface per realisation from [surface] (" + p_.psd.description + ")"},
        {"stiffness_table", StageStatus::skipped, "penalty node-sphere contact"},
        {"dynamics", StageStatus::run,
         "Newmark, " + std::to_string(p_.steps) + " steps, " + std::to_string(2 * p_.elements + 1) +
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
    m.sections.push_back(p_.section);
    // Straight tube resting on the highest point under its nodes, lowered by the mean static
    // penetration; it settles within skip_start.
    const int nn = 2 * p_.elements + 1;
    double top = -inf;
    for (int i = 0; i < nn; ++i) {
      const double y = -0.5 * p_.length + p_.length * i / (nn - 1);
      top = std::max(top, sample_height(field, Vector2d(0.0, y)).h);
    }
    const double z0 = top + p_.radius - p_.section.rhoA * p_.length * p_.gravity / (nn * p_.law.eps_n);
    const auto ids = add_straight_beam(m, Vector3d(0.0, -0.5 * p_.length, z0), Vector3d(0.0, 0.5 * p_.length, z0),
                                       p_.elements, 0, Vector3d::UnitX());
    for (std::size_t i = 0; i < ids.size(); ++i) {
      SurfaceContactLaw law = p_.law;
      law.damping = p_.node_damping[i];
      m.surface_contacts.push_back(SurfaceContactPair{ids[i], 0, law});
    }
    m.v0.assign(m.X.size(), Vector3d(p_.speed, 0.0, 0.0));
    m.w0.assign(m.X.size(), Vector3d(0.0, p_.speed / p_.radius, 0.0));  // v + w x (-r e_z) = 0
    m.gravity = Vector3d(0.0, 0.0, -p_.gravity);
    RunOptions ro;
    ro.dt = p_.dt;
    ro.t_end = static_cast<double>(p_.steps) * p_.dt;
    for (int sn : p_.sensor_nodes) ro.record_nodes.push_back(ids[static_cast<std::size_t>(sn)]);
    ro.record_energies = false;  // spectra need accelerations only
    const History h = run(m, p_.solver, ro);
    if (!h.completed) {
      std::ostringstream e;
      e << "realisation " << id << " (seed " << p_.seed << "): Newton did not converge at t = " << h.failed_at
        << " s even after " << p_.solver.max_cuts
        << " step halvings; reduce [analysis] dt, soften the penalties or smooth the roughness; rerun it alone with "
           "--only "
        << id;
      throw data_error(e.str());
    }
    const std::size_t ns = p_.sensor_nodes.size(), n = h.time.size() - p_.skip;
    std::vector<double>& a = ws.signal;
    a.resize(h.time.size());
    for (std::size_t j = 0; j < ns; ++j) {
      for (std::size_t k = 0; k < h.time.size(); ++k) a[k] = h.acceleration[k][j].z();
      welch_->psd(a.data() + p_.skip, n, rows_->row(values, j), ws.welch);
    }
    rows_->finish(values);
    double* x = rows_->extras(values);
    x[curvature_ratio] = p_.radius * validity.max_concave_curvature;
    x[invalid_contact] = validity.valid ? 0.0 : 1.0;
    std::size_t open = 0, pairs = 0;
    for (std::size_t k = p_.skip; k < h.time.size(); ++k)
      for (const auto& c : h.surface_contact[k]) {
        open += c.active ? 0 : 1;
        ++pairs;
      }
    x[open_share] = static_cast<double>(open) / static_cast<double>(pairs);
    x[newton_per_step] = static_cast<double>(h.newton_iterations) / static_cast<double>(std::max(1, h.steps));
    const std::size_t mid = ns / 2;
    x[speed_ratio] = h.velocity.back()[mid].x() / p_.speed;
  }

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override {
    const double K = static_cast<double>(sums.count);
    auto mean_of = [&](std::size_t i) { return sums.mean(i); };
    auto std_of = [&](std::size_t i) { return sums.std_dev(i); };
    // Realisations differ by which nodes touch the floor (intermittent contact), far more than
    // Welch noise; the intervals come from their scatter (D-21), the Welch value is information.
    io::PsdEnsemble e = rows_->welch_ensemble(sums, *welch_, p_.samples - p_.skip, p_.confidence);
    // A sensor records its nearest node: its place along the tube, from the end at y = -length/2.
    for (const int n : p_.sensor_nodes) e.sensor_position.push_back(n * p_.length / (p_.nodes() - 1));
    e.position_meaning = "position along the tube of the sensor's node, from its end at y = -length/2";
    io::write_psd_result(w, e);

    const std::size_t x0 = rows_->extra_index(0);
    const double invalid = mean_of(x0 + invalid_contact) * K;
    const struct {
      const char* name;
      std::size_t index;
      const char* units;
      const char* what;
    } extras_out[] = {
        {"/contact/curvature_ratio", curvature_ratio, "1",
         "r kappa_max of the realisation's surface (< 1: single-point contact)"},
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
      std::fprintf(
          stderr,
          "rolling-pipe: warning: %.0f of %llu realisations have valleys sharper than the node spheres somewhere "
          "(r kappa_max >= 1): contact there is a closest-point approximation\n",
          invalid, static_cast<unsigned long long>(sums.count));
    w.attribute("/contact", "friction", p_.law.mu);
    w.attribute("/contact", "penalty_normal", p_.law.eps_n);
    w.attribute("/contact", "penalty_tangential", p_.law.eps_t);
    w.attribute("/contact", "damping_ratio", p_.damping_ratio);
    w.attribute("/contact", "radius", p_.radius);
    w.attribute("/contact", "rms_curvature_ratio", p_.radius * p_.rms_curvature);
    std::vector<double> sensor_nodes(p_.sensor_nodes.begin(), p_.sensor_nodes.end());
    w.write("/sensors/node", {sensor_nodes.size()}, sensor_nodes.data(), "1",
            "beam node of each sensor (0 at y = -length/2)");
    w.write("/sensors/position", {p_.sensor_fractions.size()}, p_.sensor_fractions.data(), "1",
            "sensor position as a fraction of the length");
    std::vector<double> ff;
    const double ei = p_.section.EI2;
    for (int i = 0; i < 6; ++i) ff.push_back(free_free_frequency(i, p_.length, ei, p_.section.rhoA));
    w.write("/pipe/free_free_frequency", {ff.size()}, ff.data(), "Hz",
            "Euler-Bernoulli free-free bending frequencies of the tube (orientation, no contact)");
    w.attribute("/pipe", "length", p_.length);
    w.attribute("/pipe", "outer_radius", p_.radius);
    w.attribute("/pipe", "mass", p_.section.rhoA * p_.length);
    w.attribute("/pipe", "elements", static_cast<std::int64_t>(p_.elements));
    w.attribute("/roll", "speed", p_.speed);
    w.attribute("/roll", "distance", p_.distance);
    w.attribute("/roll", "dt", p_.dt);
  }

 private:
  struct Workspace {
    std::vector<double> u_phase, u_amp, texture, signal;
    std::unique_ptr<spectral::SynthesisScratch> line_scratch;  // made on the thread's first line
    texture::Surface grid;
    spectral::WelchWorkspace welch;
    explicit Workspace(std::size_t segment) : welch(segment) {}
  };

  // R-62 over the strips the node spheres roll over (|y - y_node| <= r + one cell); a grid
  // surface elsewhere is never touched.
  rolling::ContactValidity footprint_validity(const rolling::HeightField& f) const {
    if (f.n2 == 1) return rolling::check_single_point_contact(f, p_.radius);
    rolling::ContactValidity worst;
    const int nn = 2 * p_.elements + 1;
    for (int i = 0; i < nn; ++i) {
      const double y = -0.5 * p_.length + p_.length * i / (nn - 1);
      const int j0 = std::max(0, static_cast<int>(std::floor((y - p_.radius - f.s2_0) / f.ds2)) - 1);
      const int j1 = std::min(f.n2 - 1, static_cast<int>(std::ceil((y + p_.radius - f.s2_0) / f.ds2)) + 1);
      rolling::HeightField strip = f;
      strip.n2 = j1 - j0 + 1;
      strip.s2_0 = f.s2_0 + j0 * f.ds2;
      strip.h.assign(f.h.begin() + static_cast<std::ptrdiff_t>(j0) * f.n1,
                     f.h.begin() + static_cast<std::ptrdiff_t>(j1 + 1) * f.n1);
      const auto v = rolling::check_single_point_contact(strip, p_.radius);
      if (v.max_concave_curvature > worst.max_concave_curvature) worst = v;
    }
    return worst;
  }

  // The realisation's surface from its Philox streams (roughness_* for lines, surface_* grids).
  rolling::HeightField surface(std::uint64_t id, Workspace& ws) const {
    rolling::HeightField f;
    f.base = rolling::make_plane(Vector3d::Zero(), Vector3d::UnitZ());  // t1 = x (rolling), t2 = y (tube axis)
    f.s1_0 = p_.x_lo;
    f.ds1 = p_.spacing;
    if (p_.line) {
      const std::size_t nh = lines_->harmonics();
      ws.u_phase.resize(nh);
      ws.u_amp.resize(nh);
      ws.texture.resize(lines_->spec().samples);
      rng::PhiloxStream(p_.seed, id, rng::Stream::roughness_phase).uniform_open(ws.u_phase.data(), nh);
      rng::PhiloxStream(p_.seed, id, rng::Stream::roughness_amplitude).uniform_open(ws.u_amp.data(), nh);
      if (!ws.line_scratch) ws.line_scratch = std::make_unique<spectral::SynthesisScratch>(lines_->period());
      lines_->generate(ws.u_phase.data(), ws.u_amp.data(), ws.texture.data(), *ws.line_scratch);
      f.n1 = static_cast<int>(ws.texture.size());
      f.n2 = 1;
      f.h = ws.texture;
    } else {
      surfaces_->generate(p_.seed, id, ws.grid);
      f.n1 = static_cast<int>(ws.grid.nx);
      f.n2 = static_cast<int>(ws.grid.ny);
      f.ds2 = ws.grid.dy;
      f.s2_0 = -0.5 * static_cast<double>(ws.grid.ny - 1) * ws.grid.dy;
      f.h = ws.grid.heights;
    }
    return f;
  }

  RollingPipeSettings p_;
  std::unique_ptr<texture::LineTextureGenerator> lines_;
  std::unique_ptr<texture_io::SurfaceGenerator> surfaces_;
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
};

}  // namespace

std::unique_ptr<Scene> make_rolling_pipe(const KeyReader& s) { return std::make_unique<RollingPipe>(s); }

ResultShape rolling_pipe_result_shape(const KeyReader& s) {
  const RollingPipeSettings p = read_rolling_pipe_settings(s);
  return psd_result_shape(numbered_sensors(p.sensor_nodes.size()), p.sensor_mean, p.welch, p.band_min, p.band_max);
}

}  // namespace rollspec::scenes
