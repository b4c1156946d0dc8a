// The subcommands of `radiosity`. Each lives in its own cmd_*.cpp and adds itself to the CLI11 app; its
// callback does the work and throws on error (main prints the message to stderr and exits non-zero).
#pragma once

#include <CLI/CLI.hpp>

namespace rt::cli {

void addFormFactorsCommand(CLI::App& app);
void addSolveCommand(CLI::App& app);
void addIrradianceCommand(CLI::App& app);
void addComparePtCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addMatrixCommand(CLI::App& app);
void addFigureCommand(CLI::App& app);
void addLessonCommand(CLI::App& app);
void addBookCommand(CLI::App& app);
// `radiosity bench formfactors`, `solvers` and `sampling` share the `bench` parent.
void addBenchFormFactorsCommand(CLI::App& bench);
void addBenchSolversCommand(CLI::App& bench);
void addBenchSamplingCommand(CLI::App& bench);
// `radiosity homework new`, `check` and `topics` share the `homework` parent.
void addHomeworkNewCommand(CLI::App& homework);
void addHomeworkPdfCommand(CLI::App& homework);
void addHomeworkCheckCommand(CLI::App& homework);
void addHomeworkTopicsCommand(CLI::App& homework);

}  // namespace rt::cli
