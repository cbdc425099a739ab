// rollspec plan: which stages a study runs, reuses from cache, or skips, and why.
#include <cstdio>
#include <iostream>

#include "src/cli/commands.hpp"
#include "src/cli/parse_options.hpp"
#include "src/scenes/scene.hpp"
#include "src/study/study.hpp"

namespace rollspec::cli {

int plan_command(const Args& args) {
  const std::string usage =
      "usage: rollspec plan STUDY.ini [--set section.key=value ...]\n"
      "\n"
      "Validates the study and prints each stage of its scene as run / cached / skipped with the\n"
      "reason. Nothing is computed and no file is written.";
  po::options_description opts("options");
  StudyArgs study;
  po::positional_options_description pos;
  add_study_options(opts, pos, study);
  po::variables_map vm;
  if (!parse_options(args, usage, opts, pos, vm)) return 0;

  const study::Study s = study::Study::load(study.file, study.sets, scenes::schema_for);
  const auto scene = scenes::find_scene(s.scene()).make(s);
  std::cout << "study " << study.file << ": scene " << s.scene() << ", " << s.integer("study.realisations")
            << " realisations, seed " << s.integer("study.seed") << "\n";
  std::printf("%-16s %-8s %s\n", "stage", "status", "reason");
  for (const auto& p : scene->plan())
    std::printf("%-16s %-8s %s\n", p.stage.c_str(), scenes::to_string(p.status), p.reason.c_str());
  return 0;
}

}  // namespace rollspec::cli
