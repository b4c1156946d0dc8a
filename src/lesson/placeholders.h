// Numbers in lesson text are never typed in: the text says {{F.floor.light}} or {{iterations.jacobi:int}} and
// the value is filled in from the step's computed result when the lesson is shown. Syntax: {{name}} or
// {{name:format}}, format = N (significant digits, default 3), .Nf (fixed decimals), % (percent, one
// decimal), int (rounded).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rt::lesson {

struct Placeholder {
  std::string name;
  std::string format;              // as written after ':', empty for the default
  int line = 0;                    // absolute line in the lesson file
  std::size_t begin = 0, end = 0;  // the whole {{...}} in the text
  std::string error;               // non-empty when malformed
};

// `firstLine` is the file line of the text's first line, so that each placeholder knows its own line.
std::vector<Placeholder> findPlaceholders(const std::string& text, int firstLine);

// Formats a value with a placeholder format; returns nullopt for an unknown format.
std::optional<std::string> formatValue(double value, const std::string& format);

// Replaces every placeholder by lookup(name) formatted; whole numbers of five digits or more are grouped in
// threes (56,210; 56{,}210 inside $...$). An unknown name or format is an InputError naming
// `file` and the placeholder's line, and listing what is available (`available`).
using ValueLookup = std::function<std::optional<double>(const std::string& name)>;
std::string resolvePlaceholders(const std::string& text, int firstLine, const std::string& file,
                                const ValueLookup& lookup, const std::vector<std::string>& available = {});

}  // namespace rt::lesson
