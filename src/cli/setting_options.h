// Command-line options generated from the table of step keys (lesson/step_keys.h): every subcommand spells a
// setting the way a lesson does (`--method`, `--solver`, `--resolution`, `--tone-map`...), with the table's
// description, default and range, so that `solve`, `matrix`, `figure` and `formfactors` cannot disagree. Old
// spellings stay as aliases that print a deprecation note.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace rt::cli {

// `--<key>` bound to `target`, described, defaulted and checked as the table says. Throws std::logic_error
// for a key the table does not have.
CLI::Option* addSettingOption(CLI::App& command, const std::string& key, std::string& target);
CLI::Option* addSettingOption(CLI::App& command, const std::string& key, int& target);
CLI::Option* addSettingOption(CLI::App& command, const std::string& key, double& target);
CLI::Option* addSettingOption(CLI::App& command, const std::string& key, std::uint64_t& target);
// A true/false key as a flag: `--<key>` when its default is false, `--no-<key>` when it is true (the flag
// then stores false in `target`).
CLI::Option* addSettingFlag(CLI::App& command, const std::string& key, bool& target);

// `oldName` (e.g. "--tonemap") still sets what `option` sets, and says once on stderr that `option` is the
// spelling to use.
void addDeprecatedAlias(CLI::App& command, const std::string& oldName, CLI::Option* option);

// The name of the check an option gets from the table (deactivate it with get_validator(kTableCheck)).
inline const char* kTableCheck = "step-key table";

// Whether `name` is a solver's name (lesson::knownSolvers).
bool isSolverName(const std::string& name);

// The colour channel: r, g or b (0, 1 and 2 are accepted with a note). Returns 0, 1 or 2.
int channelIndex(const std::string& text);

}  // namespace rt::cli
