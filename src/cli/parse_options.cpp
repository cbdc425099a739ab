#include "src/cli/parse_options.hpp"

#include <iostream>

#include "src/error.hpp"
#include "src/scenes/scene.hpp"

namespace rollspec::cli {

bool parse_options(const std::vector<std::string>& args, const std::string& usage, po::options_description& options,
                   const po::positional_options_description& positional, po::variables_map& vm) {
  options.add_options()("help,h", "print this help and exit");
  try {
    po::store(po::command_line_parser(args).options(options).positional(positional).run(), vm);
    if (vm.count("help")) {
      std::cout << usage << "\n" << options << "\n";
      return false;
    }
    po::notify(vm);
  } catch (const po::error& e) {
    throw usage_error(std::string(e.what()) + "\n\n" + usage + "\n(see --help)");
  }
  return true;
}

bool parse_scene_options(const std::vector<std::string>& args, const std::string& usage,
                         po::options_description& options, const std::string& scene, po::variables_map& vm) {
  po::positional_options_description pos;
  pos.add("scene", 1);
  if (!parse_options(args, usage, options, pos, vm)) return false;
  if (!scene.empty()) return true;
  for (const auto& s : scenes::scene_registry()) std::cout << s.name << ": " << s.description << "\n";
  return false;
}

StudyCommandOptions::StudyCommandOptions(bool required) {
  auto* file = po::value(&study.file);
  if (required) file->required();
  options.add_options()("study", file, "study file (INI)")(
      "set", po::value(&study.sets)->composing(), "override a study key: --set section.key=value (repeatable)");
  positional.add("study", 1);
}

bool StudyCommandOptions::parse(const std::vector<std::string>& args, const std::string& usage) {
  return parse_options(args, usage, options, positional, vm);
}

}  // namespace rollspec::cli
