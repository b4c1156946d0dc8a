#include "cli/setting_options.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>

#include "core/input_error.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_keys.h"

namespace rt::cli {
namespace {

const lesson::StepKey& row(const std::string& key) {
  const lesson::StepKey* k = lesson::findStepKey(key);
  if (!k) throw std::logic_error("no step key '" + key + "' to make an option of");
  return *k;
}

// The table's description, default and check on a CLI11 option. The check is the lesson parser's, so a value
// is refused with the same words ("resolution must be in [2, 4096], not 0"; "unknown solver 'x' (known:
// ...)").
CLI::Option* describe(CLI::Option* option, const lesson::StepKey& k) {
  option->description(k.tooltip);
  if (!k.defaultText.empty()) option->default_str(k.defaultText);
  const lesson::StepKey* key = &k;
  option->check(CLI::Validator(
                    [key](std::string& value) -> std::string {
                      lesson::StepParameters scratch;
                      try {
                        lesson::applyStepValue(scratch, *key, key->name, value, {});
                      } catch (const InputError& e) {
                        return e.message();
                      }
                      return {};
                    },
                    ""),
                kTableCheck);
  return option;
}

}  // namespace

CLI::Option* addSettingOption(CLI::App& command, const std::string& key, std::string& target) {
  return describe(command.add_option("--" + key, target), row(key));
}

CLI::Option* addSettingOption(CLI::App& command, const std::string& key, int& target) {
  return describe(command.add_option("--" + key, target), row(key));
}

CLI::Option* addSettingOption(CLI::App& command, const std::string& key, double& target) {
  return describe(command.add_option("--" + key, target), row(key));
}

CLI::Option* addSettingOption(CLI::App& command, const std::string& key, std::uint64_t& target) {
  return describe(command.add_option("--" + key, target), row(key));
}

CLI::Option* addSettingFlag(CLI::App& command, const std::string& key, bool& target) {
  const lesson::StepKey& k = row(key);
  if (k.defaultText == "true") {
    target = true;
    return command.add_flag_callback(
        "--no-" + key, [&target] { target = false; }, k.tooltip + " (on unless --no-" + key + ")");
  }
  return command.add_flag("--" + key, target, k.tooltip);
}

void addDeprecatedAlias(CLI::App& command, const std::string& oldName, CLI::Option* option) {
  const std::string newName = option->get_name();
  command
      .add_option_function<std::string>(
          oldName,
          [&command, option, oldName, newName](const std::string& value) {
            std::cerr << "radiosity: " << oldName << " is deprecated, use " << newName << "\n";
            command.get_option(newName)->clear();
            option->add_result(value);
            option->run_callback();
          },
          "Deprecated spelling of " + newName)
      ->group("");  // not listed in --help
}

bool isSolverName(const std::string& name) {
  const auto& solvers = lesson::knownSolvers();
  return std::find(solvers.begin(), solvers.end(), name) != solvers.end();
}

int channelIndex(const std::string& text) {
  if (text == "r" || text == "red") return 0;
  if (text == "g" || text == "green") return 1;
  if (text == "b" || text == "blue") return 2;
  if (text == "0" || text == "1" || text == "2") {
    std::cerr << "radiosity: --channel " << text << " is deprecated, use r, g or b\n";
    return text[0] - '0';
  }
  throw CLI::ValidationError("--channel", "the channel is r, g or b, not '" + text + "'");
}

}  // namespace rt::cli
