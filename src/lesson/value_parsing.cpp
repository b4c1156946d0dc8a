#include "lesson/value_parsing.h"

#include <charconv>
#include <cmath>
#include <locale>
#include <sstream>
#include <version>

namespace rt::lesson {
namespace {

std::vector<std::string> words(const std::string& text) {
  std::string spaced = text;
  for (char& c : spaced)
    if (c == ',') c = ' ';
  std::istringstream in(spaced);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool toDouble(const std::string& word, double& value) {
#if defined(__cpp_lib_to_chars)
  const char* end = word.data() + word.size();
  auto [ptr, ec] = std::from_chars(word.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
#else
  // A standard library without the floating-point from_chars (Emscripten's libc++, which the web edition's
  // core is built with): a stream in the classic locale, so that the reader's locale never changes a number.
  std::istringstream in(word);
  in.imbue(std::locale::classic());
  in >> value;
  return !in.fail() && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
#endif
}

std::string range(double min, double max) {
  std::ostringstream out;
  out << "[" << min << ", " << max << "]";
  return out.str();
}

}  // namespace

int parseInt(const std::string& text, const SourceLocation& where, const std::string& key, int min, int max) {
  int value = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end)
    throw InputError(where, key + " must be a whole number, not '" + text + "'");
  if (value < min || value > max)
    throw InputError(where, key + " must be in " + range(min, max) + ", not " + text);
  return value;
}

double parseDouble(const std::string& text, const SourceLocation& where, const std::string& key, double min,
                   double max) {
  double value = 0;
  if (!toDouble(text, value)) throw InputError(where, key + " must be a number, not '" + text + "'");
  if (value < min || value > max)
    throw InputError(where, key + " must be in " + range(min, max) + ", not " + text);
  return value;
}

bool parseBool(const std::string& text, const SourceLocation& where, const std::string& key) {
  if (text == "true" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "no" || text == "off") return false;
  throw InputError(where, key + " must be true or false, not '" + text + "'");
}

std::vector<std::string> parseList(const std::string& text) {
  return words(text);
}

std::vector<int> parseIntList(const std::string& text, const SourceLocation& where, const std::string& key,
                              int min, int max) {
  std::vector<int> out;
  for (const auto& w : words(text)) out.push_back(parseInt(w, where, key, min, max));
  if (out.empty()) throw InputError(where, key + " needs at least one number");
  return out;
}

Rgb parseRgb(const std::string& text, const SourceLocation& where, const std::string& key, double min,
             double max) {
  const auto w = words(text);
  if (w.size() != 1 && w.size() != 3)
    throw InputError(where, key + " is one number (grey) or three (r g b), not '" + text + "'");
  Rgb c;
  for (int i = 0; i < 3; ++i) c[i] = parseDouble(w[w.size() == 1 ? 0 : i], where, key, min, max);
  return c;
}

Vec3 parseVec3(const std::string& text, const SourceLocation& where, const std::string& key) {
  const auto w = words(text);
  if (w.size() != 3) throw InputError(where, key + " is three numbers (x y z), not '" + text + "'");
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = parseDouble(w[i], where, key, -1e12, 1e12);
  return v;
}

std::string joinedNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace rt::lesson
