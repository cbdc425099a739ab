#pragma once
// Command-line parsing shared by the subcommands (Boost.Program_options): usage errors become
// UserError with exit 64, and --help prints the usage text.
#include <boost/program_options.hpp>
#include <string>
#include <vector>

#include "src/run/study_args.hpp"

namespace rollspec::cli {

namespace po = boost::program_options;

// Parses args against `options` and `positional`; returns false (after printing help to stdout)
// when --help was given.
bool parse_options(const std::vector<std::string>& args, const std::string& usage, po::options_description& options,
                   const po::positional_options_description& positional, po::variables_map& vm);

// Parses args with the option "scene" (declared in `options`, into `scene`) as the optional positional
// SCENE of `keys` and `init`. Returns false when the command is done: --help printed, or no SCENE given
// and the scenes listed, one "name: description" a line.
bool parse_scene_options(const std::vector<std::string>& args, const std::string& usage,
                         po::options_description& options, const std::string& scene, po::variables_map& vm);

// The study-file positional argument and repeatable --set overrides every study command takes.
using run::StudyArgs;

// A study command's options: the study file and --set first (into `study`), then the command's own, which
// it adds to `options` before parse. required = false: the command checks for a missing study itself
// (run --resume reads the checkpoint's).
struct StudyCommandOptions {
  explicit StudyCommandOptions(bool required = true);
  // parse_options over them; false when --help was given (and printed).
  bool parse(const std::vector<std::string>& args, const std::string& usage);
  po::options_description options{"options"};
  po::positional_options_description positional;
  po::variables_map vm;
  StudyArgs study;
};

}  // namespace rollspec::cli
