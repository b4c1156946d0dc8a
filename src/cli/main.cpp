// radiosity: everything the app computes, headless. Thin: parses arguments, runs a subcommand, reports
// errors with one exit code per class of error (cli_common.h, docs/robustness.md).
#include <CLI/CLI.hpp>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/check.h"
#include "core/input_error.h"
#include "core/vector_state.h"
#include "plugins/optional_methods.h"

namespace {

// A scene or matrix named on the command line that does not exist is an input error, reported as the loaders
// report it, whichever subcommand names it (CLI11's own check would make it a usage error).
void reportMissingFilesAsInputErrors(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    for (int k = 0;; ++k) {
      CLI::Validator* validator = nullptr;
      try {
        validator = option->get_validator(k);
      } catch (const CLI::OptionNotFound&) {
        break;
      }
      if (validator->get_description() != "FILE") continue;  // CLI::ExistingFile describes itself so
      validator->operation([](std::string& path) -> std::string {
        if (!std::filesystem::is_regular_file(path))
          throw rt::InputError({path}, "cannot open the file (missing or not readable)");
        return {};
      });
    }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    reportMissingFilesAsInputErrors(*sub);
}

}  // namespace

int main(int argc, char** argv) {
  // Before any thread exists: the threads made later start from this state (core/vector_state.h).
  rt::clearUpperVectorState();
  using rt::cli::ExitCode;
  CLI::App app{"radiosity: the Radiosity Textbook's command line (form factors, solvers, figures, lessons)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "radiosity 0.1.0");
  app.footer(rt::cli::kExitCodeHelp);
  rt::registerOptionalMethods();
  rt::cli::addFormFactorsCommand(app);
  rt::cli::addSolveCommand(app);
  rt::cli::addIrradianceCommand(app);
  rt::cli::addComparePtCommand(app);
  rt::cli::addRenderCommand(app);
  rt::cli::addMatrixCommand(app);
  rt::cli::addFigureCommand(app);
  rt::cli::addLessonCommand(app);
  rt::cli::addBookCommand(app);
  auto* bench = app.add_subcommand("bench", "Run time against error (prints CSV, writes plots)");
  bench->require_subcommand(1);
  rt::cli::addBenchFormFactorsCommand(*bench);
  rt::cli::addBenchSolversCommand(*bench);
  rt::cli::addBenchSamplingCommand(*bench);
  auto* homework = app.add_subcommand("homework", "Randomised exercises with answer keys, and their grading");
  homework->require_subcommand(1);
  rt::cli::addHomeworkNewCommand(*homework);
  rt::cli::addHomeworkPdfCommand(*homework);
  rt::cli::addHomeworkCheckCommand(*homework);
  rt::cli::addHomeworkTopicsCommand(*homework);
  reportMissingFilesAsInputErrors(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with code 0 to CLI11.
    return app.exit(e) == 0 ? ExitCode::Success : ExitCode::Usage;
  } catch (const rt::InputError& e) {
    std::cerr << "radiosity: " << e.what() << "\n";
    return ExitCode::Input;
  } catch (const std::bad_alloc&) {
    std::cerr << "radiosity: out of memory: use a coarser mesh (--max-edge, --subdivide) or fewer samples\n";
    return ExitCode::OutOfMemory;
  } catch (const rt::CheckFailure& e) {
    std::cerr << "radiosity: " << e.what()
              << "\nThis is a bug in radiosity: please report it with the command.\n";
    return ExitCode::Internal;
  } catch (const std::invalid_argument& e) {
    std::cerr << "radiosity: " << e.what() << "\n";  // an unknown method or solver name
    return ExitCode::Usage;
  } catch (const std::exception& e) {
    std::cerr << "radiosity: " << e.what() << "\n";
    return ExitCode::Failure;
  }
  return ExitCode::Success;
}
