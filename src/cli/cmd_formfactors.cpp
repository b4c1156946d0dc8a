#include "cli/commands.h"

namespace rt::cli {

void addFormFactorsCommand(CLI::App& app) {
  auto* command = app.add_subcommand("formfactors", "(not available yet)");
  command->callback([] { throw std::runtime_error("'formfactors' is not available yet"); });
}

}  // namespace rt::cli
