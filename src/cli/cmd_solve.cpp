#include "cli/commands.h"

namespace rt::cli {

void addSolveCommand(CLI::App& app) {
  auto* command = app.add_subcommand("solve", "(not available yet)");
  command->callback([] { throw std::runtime_error("'solve' is not available yet"); });
}

}  // namespace rt::cli
