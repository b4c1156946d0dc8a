#include "cli/commands.h"

namespace rt::cli {

void addBenchFormFactorsCommand(CLI::App& bench) {
  auto* command = bench.add_subcommand("formfactors", "(not available yet)");
  command->callback([] { throw std::runtime_error("'bench formfactors' is not available yet"); });
}

}  // namespace rt::cli
