#include "src/scenes/ball_on_beam/ball_on_beam_excitation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/spectral/harmonic_synthesis.hpp"
#include "src/rng/philox_stream.hpp"

namespace rollspec::scenes {

namespace {

// The line texture of realisation id over the whole span, patch-averaged where the filter is patch.
class LineDraw {
 public:
  LineDraw(const BallOnBeamSettings& b, std::shared_ptr<const texture::LineTextureGenerator> lines, int threads)
      : seed_(b.seed), spacing_(b.spacing), patch_half_width_(b.patch_half_width), lines_(std::move(lines)) {
    for (int t = 0; t < threads; ++t) ws_.push_back(std::make_unique<Workspace>(b.line_samples, lines_->harmonics()));
  }

  beam::UniformSamples draw(std::uint64_t id, int thread) const {
    Workspace& ws = *ws_[static_cast<std::size_t>(thread)];
    const std::size_t nh = lines_->harmonics();
    rng::PhiloxStream(seed_, id, rng::Stream::roughness_phase).uniform_open(ws.u_phase.data(), nh);
    rng::PhiloxStream(seed_, id, rng::Stream::roughness_amplitude).uniform_open(ws.u_amp.data(), nh);
    if (!ws.scratch) ws.scratch = std::make_unique<spectral::SynthesisScratch>(lines_->period());
    lines_->generate(ws.u_phase.data(), ws.u_amp.data(), ws.texture.data(), *ws.scratch);
    beam::UniformSamples h{0.0, spacing_, ws.texture};
    if (patch_half_width_ > 0.0) h = beam::contact_patch_average(h, patch_half_width_);
    return h;
  }

 private:
  struct Workspace {
    std::vector<double> texture, u_phase, u_amp;
    std::unique_ptr<spectral::SynthesisScratch> scratch;  // made on the thread's first realisation
    Workspace(std::size_t n_texture, std::size_t harmonics)
        : texture(n_texture), u_phase(harmonics), u_amp(harmonics) {}
  };
  std::uint64_t seed_;
  double spacing_, patch_half_width_;
  std::shared_ptr<const texture::LineTextureGenerator> lines_;
  std::vector<std::unique_ptr<Workspace>> ws_;
};

// The point laws on a synthesised line (filter none, patch, iso2d, or solver's h_eq PSD).
class SynthesisedLine final : public BallOnBeamExcitation {
 public:
  SynthesisedLine(const BallOnBeamSettings& b, std::shared_ptr<const texture::LineTextureGenerator> lines, int threads)
      : line_(b, std::move(lines), threads) {}
  void fill(std::uint64_t id, int thread, beam::Realisation& r) const override { r.roughness = line_.draw(id, thread); }

 private:
  LineDraw line_;
};

// Blocked force of a linear contact spring: F0(t) = W + k0 h(x_start + v t) (D-11).
class LinearSpringForce final : public BallOnBeamExcitation {
 public:
  LinearSpringForce(const BallOnBeamSettings& b, const ResolvedContact& c,
                    std::shared_ptr<const texture::LineTextureGenerator> lines, int threads)
      : line_(b, std::move(lines), threads),
        spacing_(b.spacing),
        speed_(b.model.traverse.speed),
        x_start_(b.model.traverse.x_start),
        weight_(b.weight()),
        k0_(c.law.k0) {}

  void fill(std::uint64_t id, int thread, beam::Realisation& r) const override {
    const beam::UniformSamples h = line_.draw(id, thread);
    const double v = speed_, x0 = x_start_, dt = spacing_ / v;
    const auto first = static_cast<std::size_t>(std::floor(x0 / spacing_));
    r.blocked_force.origin = (static_cast<double>(first) * spacing_ - x0) / v;
    r.blocked_force.step = dt;
    r.blocked_force.values.reserve(h.values.size() - std::min(first, h.values.size()));
    for (std::size_t i = first; i < h.values.size(); ++i) r.blocked_force.values.push_back(weight_ + k0_ * h.values[i]);
  }

 private:
  LineDraw line_;
  double spacing_, speed_, x_start_, weight_, k0_;
};

// The contact solver's blocked force (seed 002 §4.2): F0(t) synthesised per realisation from the
// table's PSD along the path, G_t(f) = 2 pi G_k(2 pi f / v) / v (D-2), sampled at the integration step.
class SynthesisedBlockedForce final : public BallOnBeamExcitation {
 public:
  SynthesisedBlockedForce(const BallOnBeamSettings& b, const ResolvedContact& c, int threads)
      : seed_(b.seed), weight_(b.weight()), step_(b.integration_step()) {
    auto n = static_cast<std::size_t>(std::ceil(beam::traverse_duration(b.model.traverse) / step_)) + 4;
    n = texture::fast_even_length(n);
    synth_ = std::make_unique<spectral::HarmonicSynthesiser>(n);
    const double df = 1.0 / (static_cast<double>(n) * step_);
    std::vector<double> psd(synth_->harmonics(), 0.0);
    for (std::size_t j = 1; j < psd.size(); ++j)
      psd[j] = blocked_force_time_psd(b, c.blocked, df * static_cast<double>(j));
    half_amplitudes_ = spectral::synthesis_half_amplitudes(psd.data(), psd.size(), df);
    for (int t = 0; t < threads; ++t) ws_.push_back(std::make_unique<Workspace>());
  }

  void fill(std::uint64_t id, int thread, beam::Realisation& r) const override {
    Workspace& ws = *ws_[static_cast<std::size_t>(thread)];
    const std::size_t nh = synth_->harmonics(), n = synth_->samples();
    ws.phase.resize(nh);
    ws.amp.resize(nh);
    if (!ws.scratch) ws.scratch = std::make_unique<spectral::SynthesisScratch>(n);
    rng::PhiloxStream(seed_, id, rng::Stream::blocked_force_phase).uniform_open(ws.phase.data(), nh);
    rng::PhiloxStream(seed_, id, rng::Stream::blocked_force_amplitude).uniform_open(ws.amp.data(), nh);
    r.blocked_force.origin = 0.0;
    r.blocked_force.step = step_;
    r.blocked_force.values.resize(n);
    synth_->synthesise(half_amplitudes_.data(), spectral::Amplitudes::rayleigh, ws.phase.data(), ws.amp.data(),
                       r.blocked_force.values.data(), *ws.scratch);
    for (double& f : r.blocked_force.values) f += weight_;
  }

 private:
  struct Workspace {
    std::vector<double> phase, amp;
    std::unique_ptr<spectral::SynthesisScratch> scratch;  // made on the thread's first realisation
  };
  std::uint64_t seed_;
  double weight_, step_;
  std::unique_ptr<spectral::HarmonicSynthesiser> synth_;
  std::vector<double> half_amplitudes_;
  std::vector<std::unique_ptr<Workspace>> ws_;
};

// [equivalent_roughness] line = strip: h_eq of strip 0 along the path, the same every realisation.
class StripLine final : public BallOnBeamExcitation {
 public:
  explicit StripLine(const ResolvedContact& c) : line_(c.strip_line) {}
  void fill(std::uint64_t, int, beam::Realisation& r) const override { r.roughness = line_; }

 private:
  beam::UniformSamples line_;
};

// law = path: the path table's strip is the roughness, already in the law; nothing else is random.
class PathStrip final : public BallOnBeamExcitation {
 public:
  void fill(std::uint64_t, int, beam::Realisation&) const override {}
};

}  // namespace

std::unique_ptr<BallOnBeamExcitation> make_ball_on_beam_excitation(
    const BallOnBeamSettings& b, const ResolvedContact& c, std::shared_ptr<const texture::LineTextureGenerator> lines,
    int threads) {
  if (b.blocked_solver()) return std::make_unique<SynthesisedBlockedForce>(b, c, threads);
  if (b.path_law()) return std::make_unique<PathStrip>();
  if (b.strip_line) return std::make_unique<StripLine>(c);
  if (b.linearised()) return std::make_unique<LinearSpringForce>(b, c, std::move(lines), threads);
  return std::make_unique<SynthesisedLine>(b, std::move(lines), threads);
}

}  // namespace rollspec::scenes
