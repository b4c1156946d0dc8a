#include "cli/commands.h"

namespace rt::cli {

void addFigureCommand(CLI::App& app) {
  auto* command = app.add_subcommand("figure", "(not available yet)");
  command->callback([] { throw std::runtime_error("'figure' is not available yet"); });
}

}  // namespace rt::cli
