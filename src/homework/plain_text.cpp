#include "homework/plain_text.h"

#include <cctype>
#include <utility>
#include <vector>

namespace rt::homework {

std::string plainText(const std::string& markdown) {
  static const std::vector<std::pair<std::string, std::string>> symbols{
      {"alpha", "α"},      {"beta", "β"},        {"gamma", "γ"},  {"theta", "θ"},  {"lambda", "λ"},
      {"rho", "ρ"},        {"pi", "π"},          {"sigma", "σ"},  {"omega", "ω"},  {"Omega", "Ω"},
      {"varepsilon", "ε"}, {"epsilon", "ε"},     {"Delta", "Δ"},  {"sum", "Σ"},    {"int", "∫"},
      {"sqrt", "√"},       {"le", "≤"},          {"ge", "≥"},     {"ne", "≠"},     {"to", "→"},
      {"times", "×"},      {"cdot", "·"},        {"propto", "∝"}, {"approx", "≈"}, {"infty", "∞"},
      {"circ", "°"},       {"dots", "…"},        {"ldots", "…"},  {"hat", ""},     {"frac", ""},
      {"text", ""},        {"operatorname", ""}, {"mathrm", ""},  {"left", ""},    {"right", ""},
      {",", " "},          {";", " "},           {"!", ""},       {" ", " "}};
  std::string out;
  for (std::size_t i = 0; i < markdown.size(); ++i) {
    const char c = markdown[i];
    if (c == '$' || c == '{' || c == '}') continue;
    if (c != '\\') {
      out += c;
      continue;
    }
    // A command: letters, or one other character.
    std::size_t end = i + 1;
    while (end < markdown.size() && std::isalpha(static_cast<unsigned char>(markdown[end]))) ++end;
    if (end == i + 1 && end < markdown.size()) ++end;
    const std::string name = markdown.substr(i + 1, end - i - 1);
    bool known = false;
    for (const auto& [command, symbol] : symbols)
      if (command == name) {
        out += symbol;
        known = true;
        break;
      }
    if (!known) out += name;  // \cos, \ln, \max read as their names
    // A root binds to what follows it: "\sqrt N" reads √N.
    if (name == "sqrt")
      while (end < markdown.size() && markdown[end] == ' ') ++end;
    i = end - 1;
  }
  return out;
}

}  // namespace rt::homework
