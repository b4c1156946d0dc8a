#include "core/io/mtl_reader.h"

#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "core/io/scene_assembly.h"

namespace rt::io_detail {
namespace {

bool isTextureMap(const std::string& key) {
  return key.rfind("map_", 0) == 0 || key == "bump" || key == "disp" || key == "decal" || key == "refl" ||
         key == "norm";
}

// Statements of the MTL format (and common extensions) that mean nothing for a diffuse radiosity scene.
const std::set<std::string>& skippedStatements() {
  static const std::set<std::string> keys{"Ka", "Ks",    "Ns",        "Ni",     "d",  "Tr",
                                          "Tf", "illum", "sharpness", "Pr",     "Pm", "Ps",
                                          "Pc", "Pcr",   "aniso",     "anisor", "Ke2"};
  return keys;
}

Rgb parseColour(const std::vector<std::string>& words, const SourceLocation& where) {
  // "Kd r" means grey, "Kd r g b" a colour; the spectral and xyz forms are not supported.
  if (words.size() != 2 && words.size() != 4)
    throw InputError(where, words[0] + " needs 1 or 3 numbers ('" + words[0] + " r g b'), found " +
                                std::to_string(words.size() - 1) + " values");
  Rgb value;
  for (std::size_t k = 1; k < words.size(); ++k) {
    const std::optional<double> x = parseNumber(words[k]);
    if (!x) throw InputError(where, words[0] + ": '" + words[k] + "' is not a number");
    value[static_cast<int>(k - 1)] = *x;
  }
  if (words.size() == 2) value = Rgb::Constant(value[0]);
  return value;
}

}  // namespace

std::vector<std::pair<int, std::string>> logicalLines(const std::string& text) {
  std::vector<std::pair<int, std::string>> lines;
  std::istringstream in(text);
  int number = 0;
  bool continues = false;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const bool next = !line.empty() && line.back() == '\\';
    if (next) line.back() = ' ';
    if (continues)
      lines.back().second += line;
    else
      lines.emplace_back(number, line);
    continues = next;
  }
  return lines;
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\f\v");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\f\v") - first + 1);
}

std::string withoutComment(const std::string& line) {
  return trimmed(line.substr(0, line.find('#')));
}

std::vector<std::string> splitWords(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::string afterFirstWord(const std::string& line) {
  const std::string text = trimmed(line);
  const std::size_t gap = text.find_first_of(" \t");
  return gap == std::string::npos ? "" : trimmed(text.substr(gap));
}

std::optional<double> parseNumber(const std::string& word) {
  if (word.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size()) return std::nullopt;
  return value;
}

MtlLibrary parseMtl(const std::string& text, const std::string& path) {
  MtlLibrary library;
  std::map<std::string, std::size_t> byName;
  std::set<std::string> unknownReported;
  MtlMaterial* current = nullptr;
  for (const auto& [number, raw] : logicalLines(text)) {
    const SourceLocation where{path, number, ""};
    const std::string line = withoutComment(raw);
    const std::vector<std::string> words = splitWords(line);
    if (words.empty()) continue;
    const std::string& key = words[0];
    if (key == "newmtl") {
      const std::string name = afterFirstWord(line);
      if (name.empty()) throw InputError(where, "newmtl needs a material name");
      const auto [at, added] = byName.emplace(name, library.materials.size());
      if (added) {
        library.materials.emplace_back();
      } else {
        library.warnings.push_back(where.describe() + ": warning: material '" + name +
                                   "' is defined again; this later definition is used");
        library.materials[at->second] = MtlMaterial{};
      }
      current = &library.materials[at->second];
      current->material.name = name;
      current->newmtl = where;
    } else if (key == "Kd" || key == "Ke") {
      if (!current) throw InputError(where, key + " before any 'newmtl <name>'");
      Material& m = current->material;
      (key == "Kd" ? m.reflectance : m.emission) = parseColour(words, where);
      if (key == "Kd") current->hasKd = true;
      // The value is checked where it is written; the other one may still be unset (zero), which passes.
      checkMaterial(m, where);
    } else if (isTextureMap(key)) {
      if (current && current->ignoredMaps.empty()) {
        current->ignoredMaps = key;
        library.warnings.push_back(where.describe() + ": warning: material '" + current->material.name +
                                   "': " + key +
                                   " (a texture) is ignored; its Kd is used as one uniform reflectance");
      }
    } else if (!skippedStatements().count(key) && unknownReported.insert(key).second) {
      library.warnings.push_back(where.describe() + ": warning: unknown statement '" + key + "' ignored");
    }
  }
  return library;
}

}  // namespace rt::io_detail
