#pragma once
// Scene `random-oscillator`: a linear single-degree-of-freedom oscillator (mass m, natural
// frequency f_n, damping ratio zeta) driven by a stationary Gaussian force synthesised from a
// force PSD (flat or table) by D-3, integrated exactly (D-18) from its periodic steady state, its
// acceleration PSD estimated per realisation (Welch, D-15) and averaged. The exact answer is
//   S_a(f) = |H_a(f)|^2 S_F(f),  H_a = 1 - s(f)^2 (k + i c w) / (k - w^2 + i c w) / m-normalised   (D-19)
// with s(f) = sinc(f / f_s) the first-order hold of the sampled force (s = 1 gives the textbook
// -w^2 / (m (w_n^2 - w^2 + 2 i zeta w_n w))). It is written to /reference/psd so a user sees the
// engine's RNG, synthesis, integration, Welch and averaging verified together.
#include <memory>
#include <vector>

#include "src/scenes/scene.hpp"

namespace rollspec::scenes {

std::vector<study::KeySpec> random_oscillator_keys();
// rollspec init's first keys (scene.hpp FirstKey).
std::vector<FirstKey> random_oscillator_first_keys();
std::unique_ptr<Scene> make_random_oscillator(const study::KeyReader& s);
// The shape of its /psd and /bands, from its settings (a sweep checks it before any point runs).
ResultShape random_oscillator_result_shape(const study::KeyReader& s);

// The exact acceleration PSD of D-19 at frequency f for a force PSD value s_f.
double random_oscillator_exact_psd(double f, double s_f, double mass, double natural_frequency, double damping_ratio,
                                   double sample_rate);

// Its memory model and the references a run cites (random_oscillator_row_parts.cpp).
std::vector<MemoryItem> random_oscillator_memory(const study::KeyReader& s, int threads);
std::vector<std::string> random_oscillator_references(const study::KeyReader& s);

}  // namespace rollspec::scenes
