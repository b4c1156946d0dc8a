#include "lesson/placeholders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/input_error.h"

namespace rt::lesson {
namespace {

bool nameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
         c == '-' || c == '[' || c == ']';
}

// Whether `pos` lies inside $...$ or $$...$$ (a backslash escapes the character after it). A scan of its own:
// maths.h finds formulas with md4c, which the parser's builds (fuzzers, WebAssembly) do not link.
bool insideMaths(const std::string& text, std::size_t pos) {
  bool inlineMaths = false, display = false;
  for (std::size_t i = 0; i < pos && i < text.size(); ++i) {
    if (text[i] == '\\') {
      ++i;
    } else if (text[i] == '$' && i + 1 < text.size() && text[i + 1] == '$' && !inlineMaths) {
      display = !display;
      ++i;
    } else if (text[i] == '$' && !display) {
      inlineMaths = !inlineMaths;
    }
  }
  return inlineMaths || display;
}

// A whole number of five digits or more in groups of three, as a book prints it: 56,210 in text, 56{,}210 in
// maths (where TeX would otherwise space a comma as punctuation).
std::string groupDigits(const std::string& number, bool maths) {
  const std::size_t first = number[0] == '-' ? 1 : 0;
  if (number.find_first_not_of("0123456789", first) != std::string::npos || number.size() - first < 5)
    return number;
  std::string out = number.substr(0, first);
  for (std::size_t i = first; i < number.size(); ++i) {
    if (i > first && (number.size() - i) % 3 == 0) out += maths ? "{,}" : ",";
    out += number[i];
  }
  return out;
}

int lineAt(const std::string& text, std::size_t pos, int firstLine) {
  return firstLine + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

}  // namespace

std::vector<Placeholder> findPlaceholders(const std::string& text, int firstLine) {
  std::vector<Placeholder> out;
  std::size_t pos = 0;
  while ((pos = text.find("{{", pos)) != std::string::npos) {
    Placeholder p;
    p.begin = pos;
    p.line = lineAt(text, pos, firstLine);
    const std::size_t close = text.find("}}", pos + 2);
    const std::size_t newline = text.find('\n', pos);
    if (close == std::string::npos || (newline != std::string::npos && newline < close)) {
      p.end = pos + 2;
      p.error = "'{{' is not closed by '}}' on the same line";
      out.push_back(p);
      pos += 2;
      continue;
    }
    p.end = close + 2;
    std::string inner = text.substr(pos + 2, close - pos - 2);
    inner.erase(0, inner.find_first_not_of(' '));
    inner.erase(inner.find_last_not_of(' ') + 1);
    const auto colon = inner.find(':');
    p.name = inner.substr(0, colon);
    if (colon != std::string::npos) p.format = inner.substr(colon + 1);
    if (p.name.empty() || !std::all_of(p.name.begin(), p.name.end(), nameChar))
      p.error = "'{{" + inner + "}}' is not a placeholder name (letters, digits, '.', '-', '_', '[', ']')";
    else if (!p.format.empty() && !formatValue(1.0, p.format))
      p.error = "unknown placeholder format '" + p.format + "' (use N, .Nf, % or int)";
    out.push_back(p);
    pos = p.end;
  }
  return out;
}

std::optional<std::string> formatValue(double value, const std::string& format) {
  char buffer[64];
  if (!std::isfinite(value)) return std::string(std::isnan(value) ? "NaN" : (value > 0 ? "inf" : "-inf"));
  if (format.empty() ||
      std::all_of(format.begin(), format.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    if (format.size() > 2) return std::nullopt;  // at most 17 digits; a long number must not overflow stoi
    const int digits = format.empty() ? 3 : std::stoi(format);
    if (digits < 1 || digits > 17) return std::nullopt;
    if (format.empty() && value == std::round(value) && std::abs(value) < 1e9) {
      std::snprintf(buffer, sizeof buffer, "%.0f", value);
    } else {
      std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    }
    return std::string(buffer);
  }
  if (format == "int") {
    std::snprintf(buffer, sizeof buffer, "%.0f", std::round(value));
    return std::string(buffer);
  }
  if (format == "%") {
    std::snprintf(buffer, sizeof buffer, "%.1f%%", 100.0 * value);
    return std::string(buffer);
  }
  if (format.size() >= 3 && format[0] == '.' && format.back() == 'f') {
    const std::string digits = format.substr(1, format.size() - 2);
    if (digits.empty() || digits.size() > 2 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return std::nullopt;
    const int n = std::stoi(digits);
    if (n > 17) return std::nullopt;
    std::snprintf(buffer, sizeof buffer, "%.*f", n, value);
    return std::string(buffer);
  }
  return std::nullopt;
}

std::string resolvePlaceholders(const std::string& text, int firstLine, const std::string& file,
                                const ValueLookup& lookup, const std::vector<std::string>& available) {
  std::string out;
  std::size_t copied = 0;
  for (const auto& p : findPlaceholders(text, firstLine)) {
    if (!p.error.empty()) throw InputError({file, p.line}, p.error);
    const auto value = lookup(p.name);
    if (!value) {
      std::string known;
      for (std::size_t i = 0; i < available.size() && i < 40; ++i) known += (i ? ", " : "") + available[i];
      if (available.size() > 40) known += ", ...";
      throw InputError({file, p.line}, "this step computes no value '" + p.name + "'" +
                                           (known.empty() ? std::string() : " (it has: " + known + ")"));
    }
    out += text.substr(copied, p.begin - copied);
    out += groupDigits(*formatValue(*value, p.format), insideMaths(text, p.begin));
    copied = p.end;
  }
  out += text.substr(copied);
  return out;
}

}  // namespace rt::lesson
