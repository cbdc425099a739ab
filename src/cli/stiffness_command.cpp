// rollspec stiffness: build (or reuse) a study's contact stiffness table and print it.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "kernels/contact/hertz.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/ensemble/mpi_context.hpp"
#include "src/ensemble/ensemble_driver.hpp"
#include "src/ensemble/stop_signal.hpp"
#include "src/error.hpp"
#include "src/scenes/memory_estimate.hpp"
#include "src/scenes/scene.hpp"
#include "src/run/run_phases.hpp"
#include "src/run/study_stiffness_table.hpp"
#include "src/stiffness/stiffness_table.hpp"
#include "src/study/sections/stiffness_section.hpp"
#include "src/io/number_text.hpp"

namespace rollspec::cli {

using run::resolve_study;

int stiffness_command(const Args& args) {
  const std::string usage =
      "usage: rollspec stiffness STUDY.ini [--out FILE.h5] [--rebuild] [--quiet] [--set section.key=value ...]\n"
      "\n"
      "Builds the contact stiffness table of a `stiffness` or `ball-on-beam` study: force P(delta), stiffness\n"
      "k = dP/d delta and contact area against the approach from first contact, mean and standard deviation over\n"
      "rough-surface realisations (elastic-plastic half-space, FFT-accelerated). A table whose input hash\n"
      "matches is reused; one whose inputs differ, or a damaged file, is refused unless --rebuild.\n"
      "Prints the table and the stiffness at the ball's own weight next to the smooth Hertz value 2 E* a.";
  StudyCommandOptions cl;
  std::string out;
  cl.options.add_options()("out,o", po::value(&out),
                           "table file (default: [stiffness] table, auto = <table_dir>/stiffness-<hash>.h5)")(
      "rebuild", "replace a table whose inputs differ or that is damaged")("quiet,q", "no progress output")(
      "force", "build a table whose memory estimate exceeds the available memory");
  if (!cl.parse(args, usage)) return 0;
  if (out.empty() && cl.vm.count("out")) throw usage_error("--out is empty; allowed: the path of the file to write");
  if (!out.empty())
    cl.study.sets.push_back(study::StiffnessSection::table_setting(std::filesystem::absolute(out).string()));
  const run::StudyStiffnessTable answer = run::study_stiffness_table(
      resolve_study(cl.study), cl.vm.count("force") > 0, cl.vm.count("rebuild") > 0, cl.vm.count("quiet") > 0);
  const stiffness::StiffnessTable& t = answer.table;
  const scenes::BallContact& pair = answer.pair;
  const std::string& status = answer.status;
  if (ensemble::mpi_rank() != 0) return 0;  // every rank holds the table; rank 0 reports it
  std::printf("# stiffness table: %s\n# input hash %s, %s, ball radius %g m, E* %.6g Pa, H %g Pa\n", status.c_str(),
              t.input_hash.c_str(), io::counted(static_cast<unsigned long long>(t.realisations), "realisation").c_str(),
              t.ball_radius, t.effective_modulus, t.hardness);
  std::printf("%14s %14s %12s %14s %14s %12s %10s\n", "approach_m", "force_N", "force_std_N", "stiffness_N/m",
              "area_m2", "plastic", "iter");
  for (std::size_t j = 0; j < t.approach.size(); ++j)
    std::printf("%14.6g %14.6g %12.4g %14.6g %14.6g %12.4g %10.1f\n", t.approach[j], t.force_mean[j], t.force_std[j],
                t.stiffness_mean[j], t.contact_area_mean[j], t.plastic_cells_mean[j], t.iterations_mean[j]);
  // The fit is a summary; one beyond its tolerance says so on the same line (the dynamics use the table).
  if (t.fit_usable())
    std::printf("fit: P = %.6g * delta^%.4f (max relative error %.3g, within the %.0f %% tolerance)\n",
                t.fit_coefficient, t.fit_exponent, t.fit_max_relative_error, 100.0 * t.fit_tolerance);
  else
    std::printf(
        "fit: NOT USABLE: P = %.6g * delta^%.4f misses the table by up to %.0f %% (tolerance %.0f %%); a power law "
        "does not describe this table, use the table itself (the dynamics do)\n",
        t.fit_coefficient, t.fit_exponent, 100.0 * t.fit_max_relative_error, 100.0 * t.fit_tolerance);
  const double w = pair.weight;
  const double delta_h = contact::hertz::approach_at_load(t.ball_radius, t.effective_modulus, w);
  const double k_h = 2.0 * t.effective_modulus * std::sqrt(t.ball_radius * delta_h);
  if (std::isnan(t.approach_at(w)))
    std::printf(
        "at the ball's weight W = %.6g N: beyond the table (largest force %.6g N at approach %.6g m); raise "
        "[stiffness] approach_max (smooth Hertz: approach %.6g m, k = %.6g N/m)\n",
        w, t.force_mean.back(), t.approach.back(), delta_h, k_h);
  else
    std::printf(
        "at the ball's weight W = %.6g N: approach %.6g m, k = %.6g N/m (smooth Hertz: approach %.6g m, k = %.6g "
        "N/m)\n",
        w, t.approach_at(w), t.stiffness_at(w), delta_h, k_h);
  return 0;
}

}  // namespace rollspec::cli
