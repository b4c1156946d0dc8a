#include "cli/commands.h"

namespace rt::cli {

void addBenchSolversCommand(CLI::App& bench) {
  auto* command = bench.add_subcommand("solvers", "(not available yet)");
  command->callback([] { throw std::runtime_error("'bench solvers' is not available yet"); });
}

}  // namespace rt::cli
