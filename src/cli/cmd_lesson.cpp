#include "cli/commands.h"

namespace rt::cli {

void addLessonCommand(CLI::App& app) {
  auto* command = app.add_subcommand("lesson", "(not available yet)");
  command->callback([] { throw std::runtime_error("'lesson' is not available yet"); });
}

}  // namespace rt::cli
