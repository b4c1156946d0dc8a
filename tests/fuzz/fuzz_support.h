// What every fuzz target shares: a small memory budget (so that "refused: needs N GB" is exercised instead of
// the fuzzer's RSS limit), and the loader contract: either a valid result or an InputError that says where.
// Anything else (another exception, a sanitizer report, an RT_CHECK failure) is a finding.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "core/input_error.h"

namespace rt::fuzz {

inline void limitMemory() {
  setenv("RT_MEMORY_LIMIT_MB", "256", 1);
}

// Aborts (a finding) with a message; libFuzzer then saves the input.
[[noreturn]] inline void broken(const std::string& what) {
  std::fprintf(stderr, "loader contract broken: %s\n", what.c_str());
  std::abort();
}

// Runs `load`; an InputError must name a file (the fuzz targets always give one). Other exceptions escape
// to libFuzzer, which reports them as a crash.
template <typename Load>
void expectValidOrInputError(Load&& load) {
  try {
    load();
  } catch (const InputError& e) {
    if (e.where().file.empty()) broken(std::string("InputError without a location: ") + e.what());
  }
}

}  // namespace rt::fuzz
