#include "cli/commands.h"

namespace rt::cli {

void addMatrixCommand(CLI::App& app) {
  auto* command = app.add_subcommand("matrix", "(not available yet)");
  command->callback([] { throw std::runtime_error("'matrix' is not available yet"); });
}

}  // namespace rt::cli
