#pragma once
// The `rollspec` subcommands. Each takes its own arguments (argv after the subcommand name) and
// returns the process exit code; errors reach main() as UserError.
#include <string>
#include <vector>

namespace rollspec::cli {

using Args = std::vector<std::string>;

int run_command(const Args& args);
int plan_command(const Args& args);
int psd_command(const Args& args);
int compare_command(const Args& args);
int fit_command(const Args& args);
int keys_command(const Args& args);
int init_command(const Args& args);
int texture_command(const Args& args);
int modes_command(const Args& args);
int stiffness_command(const Args& args);
int version_command(const Args& args);

}  // namespace rollspec::cli
