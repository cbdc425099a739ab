#pragma once
// `rollspec run` and `rollspec plan` of a study with a [sweep] section (or --sweep): one run per
// point, each the study with one --set per swept key, stacked into one result file.
//   run:  each point runs with every thread and rank, in order, into OUT.sweep/point_NNNN.h5 (with
//         its own checkpoint); the finished points are stacked onto OUT, and the directory removed.
//         --resume keeps finished points (checked against their study) and resumes the interrupted one.
//   plan: the points, each point's stages (tables shared between points show the same cache file),
//         and with --probe the estimated total time.
#include <optional>
#include <string>
#include <vector>

#include "src/run/run_phases.hpp"
#include "src/study/sections/sweep_section.hpp"

namespace rollspec::run {

// What a sweep is checked against before any work.
struct SweepLimits {
  std::size_t max_points = kDefaultMaxSweepPoints;  // --max-points
  bool force = false;     // run --force: a point's memory estimate may exceed the available memory
  bool announce = false;  // print the line that says what the sweep will do, before the checks
};

struct SweepStudy {
  StudyArgs args;  // the study file, its text without [sweep], and the --set overrides
  study::SweepSection sweep;
  std::string study_text;      // the resolved base study with its [sweep], for the result file
  bool from_manifest = false;  // `run --resume --out X.h5`: read from X.h5.sweep/sweep.ini

  std::size_t points() const { return sweep.points(); }
  StudyArgs point(std::size_t i) const;    // the study of point i (args with the point's --set)
  std::string label(std::size_t i) const;  // "ball.speed=1, ball.radius=0.01"
};

// nullopt: the study has no [sweep] and no --sweep was given (an ordinary run). The sweep is checked
// as a whole now, before any work: its point count against `limits.max_points` first, then every
// swept value (strictly: no empty item, no value twice, no key also given by --set), every point's
// result shape and memory estimate.
std::optional<SweepStudy> load_sweep(const StudyArgs& args, const std::vector<std::string>& sweeps,
                                     const SweepLimits& limits = {});

// `run --resume --out OUT` without a study file: the sweep whose work directory OUT.sweep holds its
// manifest (sweep.ini: the resolved study with its [sweep]); nullopt if there is no such directory.
std::optional<SweepStudy> load_sweep_manifest(const std::string& out, const SweepLimits& limits);

// The study file with `sets`, its [sweep] (if any) left out: a sweep point's checkpoint compares
// the study on disk with its own on --resume. A non-empty `text` is the study's, read as that file
// (a study the caller holds as text: Python's Study.from_text, a sweep point).
study::Study load_study_without_sweep(const std::string& file, const std::vector<std::string>& sets,
                                      const std::string& text = {});

// Refuses a sweep whose points give /psd or /bands different shapes or coordinates (from each
// point's settings, before any point runs), naming the swept keys, their values and the shapes, and
// a point whose memory estimate exceeds the available memory (unless forced).
void check_sweep_points(const SweepStudy& sweep, bool force);

int run_sweep(const SweepStudy& sweep, const RunRequest& request);

}  // namespace rollspec::run
