// radiosity: everything the app computes, headless. Thin: parses arguments, runs a subcommand, reports
// errors.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/commands.h"
#include "plugins/optional_methods.h"

int main(int argc, char** argv) {
  CLI::App app{"radiosity: the Radiosity Textbook's command line (form factors, solvers, figures, lessons)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "radiosity 0.1.0");
  rt::registerOptionalMethods();
  rt::cli::addFormFactorsCommand(app);
  rt::cli::addSolveCommand(app);
  rt::cli::addMatrixCommand(app);
  rt::cli::addFigureCommand(app);
  rt::cli::addLessonCommand(app);
  auto* bench = app.add_subcommand("bench", "Run time against error (prints CSV, writes plots)");
  bench->require_subcommand(1);
  rt::cli::addBenchFormFactorsCommand(*bench);
  rt::cli::addBenchSolversCommand(*bench);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "radiosity: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
