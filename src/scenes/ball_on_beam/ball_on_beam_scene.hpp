#pragma once
// Scene `ball-on-beam`'s class, shared by the files of its folder: ball_on_beam.cpp (the realisations, the
// results, the table jackknife's plan) and ball_on_beam_stages.cpp (the pipeline's stages: the contact tables
// wired to the law they complete, and prepare()).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernels/beam/ball_on_beam.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/spectral/welch.hpp"
#include "kernels/texture/line_texture.hpp"
#include "src/io/loss_effect.hpp"
#include "src/io/table_error.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_contact.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_excitation.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_sections.hpp"
#include "src/scenes/ball_on_beam/ball_on_beam_settings.hpp"
#include "src/scenes/psd_rows.hpp"
#include "src/stiffness/blocked_force_geometry.hpp"
#include "src/stiffness/blocked_force_table.hpp"
#include "src/stiffness/equivalent_roughness_table.hpp"
#include "src/stiffness/path_table.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/stiffness/table_study.hpp"

namespace rollspec::scenes {

struct BallOnBeamWorkspace {
  beam::BallOnBeamResult result;
  spectral::WelchWorkspace welch;
  explicit BallOnBeamWorkspace(std::size_t segment) : welch(segment) {}
};

class BallOnBeam final : public EnsembleScene {
 public:
  explicit BallOnBeam(const BallOnBeamSections& s);

  // plan: the equivalent-roughness table of filter = solver, when it is not cached, from a few of its
  // solves (its cost follows the texture's listed cells, which the plan's model cannot see).
  std::vector<TableEstimate> probe_tables(double max_probe_seconds) const override;

  // D-30: one random table, of at least 2 surfaces, strips or Welch segments of F0.
  void check_table_jackknife() const;

  // [blocked_force] leave_out (D-30d): a Welch segment of the solver's F0, which must exist.
  void check_blocked_force_leave_out() const;
  bool jackknifes_stiffness_table() const { return estimates_table_error() && uses_table() && b_.stiffness.rough; }

  // D-30, D-31: explicit jackknife (checked in the constructor), or auto with exactly one random table
  // of at least two units. Sub-tables and legs of a blocked-force or equivalent-roughness leave-out run none.
  bool estimates_table_error() const override;

  // The tables drawn from random surfaces or strips that every realisation shares: the intervals are
  // conditional on them (kernels/spectral/README.md D-28).
  std::string random_tables() const;

  // texture, surface, stiffness_table, blocked_force, dynamics, spectra: the tables are stage
  // objects whose inspection `plan` prints and whose resolution prepare() runs.
  void add_pipeline_stages(const stiffness::TableStudy& tables);

  // The path table's grid along the ball's whole path (law = path, and line = strip on its grid).
  stiffness::PathTableGeometry path_grid(bool strip_line = false) const;

  // The strip's grid: the study's keys where set, else derived from the contact radius and the
  // texture; the path step at most v / f_s so F0 (and h_eq) reach the output's Nyquist frequency.
  stiffness::BlockedForceGeometry blocked_force_grid() const;

  // A cached table of strip 0 that the contact law takes: its file and hash from (study, grid, R, E*,
  // W), built from the same, completed by a use_* member.
  template <class Table, class Grid>
  void add_contact_table_stage(const char* name, const stiffness::TableStudy& s, const Grid& grid,
                               stiffness::CachedTable (*cached)(const stiffness::TableStudy&, const Grid&, double,
                                                                double, double),
                               Table (*build)(const stiffness::TableStudy&, const Grid&, double, double, double, bool),
                               void (BallOnBeam::*use)(const Table&, const std::string&, bool), std::string detail);

  void prepare(bool quiet, bool rebuild) override;

  // The tables' stages: each completes the resolved contact (ball_on_beam_contact.hpp) and says so.
  void use_stiffness_table(const stiffness::StiffnessTable& t, const std::string& status, bool quiet);

  void use_path_table(const stiffness::PathTableData& t, const std::string& status, bool quiet);

  void use_strip_equivalent_roughness(const stiffness::EquivalentRoughnessTable& t, const std::string& status,
                                      bool quiet);

  void apply_equivalent_stiffness(const stiffness::EquivalentRoughnessTable& t, bool quiet);

  // filter = solver: the line is drawn from h_eq's PSD, so its generator is made again.
  // [equivalent_roughness] leave_out = i: the cached table without strip i (D-30; no new solve).
  void use_equivalent_roughness(const stiffness::EquivalentRoughnessTable& full, const std::string& status, bool quiet);

  // [blocked_force] leave_out = i: the cached table without Welch segment i of F0 (D-30d; no new solve).
  void use_blocked_force(const stiffness::BlockedForceTable& full, const std::string& status, bool quiet);

  std::vector<std::string> warnings() const override { return b_.warnings; }
  std::size_t rows() const { return rows_->rows(); }
  // PsdRows layout, then the extras: contact-force PSD, ball-acceleration PSD, loss-of-contact share.
  std::size_t values_per_realisation() const override { return rows_->size(); }

  // Simulates realisation `id` into ws.result (shared by the ensemble and the time-history output).
  void simulate(std::uint64_t id, int thread, BallOnBeamWorkspace& ws) const;

  void run_realisation(std::uint64_t id, int thread, double* values) const override;

  void write_results(io::Hdf5Writer& w, const ensemble::EnsembleSums& sums) const override;

  io::PsdEnsemble spectra(const ensemble::EnsembleSums& sums) const override;

  std::size_t linear_spectral_values() const override { return rows_->linear_values(); }

  TableJackknifePlan table_jackknife() const override;

  void include_table_error(io::TableError e) override { table_error_ = std::move(e); }

  // D-35: the linearised law assumes a closed contact; where the run lost it, the same realisations run
  // again with one that never opens size what that moved.
  std::vector<std::string> closed_contact_sets(const ensemble::EnsembleSums& sums) const override;
  void include_loss_effect(io::LossEffect e) override { loss_effect_ = std::move(e); }

 private:
  // Realisations 0..n-1 again (deterministic: same Philox keys), so histories survive --resume;
  // with --only, the history of that one realisation.
  void write_time_histories(io::Hdf5Writer& w, std::int64_t only) const;

  const BallOnBeamSettings b_;  // the keys' values; the table stages resolve contact_
  ResolvedContact contact_;
  io::LossEffect loss_effect_;  // D-35: what lost contact moved (measured: the law assumes a closed contact)
  io::TableError table_error_;  // what the intervals include besides the realisations
  std::optional<stiffness::TableStudy> tables_;         // table_error = jackknife: the sub-tables' inputs
  std::optional<stiffness::TableStudy> filter_tables_;  // filter = solver: what plan --probe solves
  bool linearised() const { return b_.linearised(); }
  bool uses_table() const { return b_.uses_table(); }
  bool blocked_solver() const { return b_.blocked_solver(); }
  bool solver_filter() const { return b_.filter == ContactFilter::solver; }
  bool writes_reference() const { return b_.linearised() && b_.reference; }
  void write_spectra_only() override { spectra_only_ = true; }
  bool quiet_ = false;
  bool spectra_only_ = false;
  std::shared_ptr<const texture::LineTextureGenerator> lines_;  // of contact_.line_psd
  std::unique_ptr<const beam::BallOnBeamModel> model_;          // the settings' model with contact_'s law
  std::unique_ptr<beam::ExactStepIntegrator> integrator_;
  std::unique_ptr<BallOnBeamExcitation> excitation_;  // what drives the beam per realisation
  std::unique_ptr<spectral::WelchPlan> welch_;
  std::unique_ptr<PsdRows> rows_;
  std::vector<std::unique_ptr<BallOnBeamWorkspace>> workspaces_;
};

}  // namespace rollspec::scenes
