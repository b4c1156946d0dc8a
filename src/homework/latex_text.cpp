#include "homework/latex_text.h"

#include <sstream>
#include <vector>

namespace rt::homework {
namespace {

// One line of prose: maths passes through, code becomes \texttt, reserved characters are escaped.
std::string inlineText(const std::string& line) {
  std::string out;
  bool maths = false, code = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '$' && !code) {
      maths = !maths;
      out += c;
    } else if (c == '`' && !maths) {
      code = !code;
      out += code ? "\\texttt{" : "}";
    } else if (maths) {
      out += c;
    } else if (c == '_' || c == '%' || c == '&' || c == '#' || c == '{' || c == '}') {
      out += std::string("\\") + c;
    } else if (c == '\\') {
      out += "\\textbackslash{}";
    } else if (c == '~' || c == '^') {
      out += std::string("\\") + c + "{}";
    } else {
      out += c;
    }
  }
  if (code) out += "}";
  return out;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t k = 1; k < row.size(); ++k) {
    if (row[k] == '|') {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += row[k];
    }
  }
  return out;
}

}  // namespace

std::string markdownToLatex(const std::string& markdown) {
  std::istringstream in(markdown);
  std::string line, out;
  bool table = false, list = false;
  while (std::getline(in, line)) {
    const bool isTable = !line.empty() && line[0] == '|';
    if (table && !isTable) {
      out += "\\end{tabular}\n\n";
      table = false;
    }
    const bool isItem = line.rfind("- ", 0) == 0;
    if (list && !isItem) {
      out += "\\end{itemize}\n";
      list = false;
    }
    if (isTable) {
      const auto row = cells(line);
      if (line.find("---") != std::string::npos) continue;  // the separator row
      if (!table) {
        out += "\\begin{tabular}{" + std::string(row.size(), 'l') + "}\n";
        table = true;
      }
      for (std::size_t k = 0; k < row.size(); ++k) out += (k ? " & " : "") + inlineText(row[k]);
      out += " \\\\\n";
    } else if (isItem) {
      if (!list) out += "\\begin{itemize}\n";
      list = true;
      out += "\\item " + inlineText(line.substr(2)) + "\n";
    } else if (line.rfind("### ", 0) == 0) {
      out += "\\subsubsection*{" + inlineText(line.substr(4)) + "}\n";
    } else if (line.rfind("## ", 0) == 0) {
      out += "\\subsection*{" + inlineText(line.substr(3)) + "}\n";
    } else if (line.rfind("# ", 0) == 0) {
      out += "\\section*{" + inlineText(line.substr(2)) + "}\n";
    } else if (line.rfind("![", 0) == 0) {
      continue;  // figures: the LaTeX writer places the picture version itself
    } else {
      out += inlineText(line) + "\n";
    }
  }
  if (table) out += "\\end{tabular}\n";
  if (list) out += "\\end{itemize}\n";
  return out;
}

std::string latexDocument(const std::string& title, const std::string& body) {
  return "\\documentclass[11pt]{article}\n\\usepackage[a4paper,margin=2cm]{geometry}\n"
         "\\usepackage{amsmath,amssymb}\n\\usepackage[T1]{fontenc}\n"
         "\\usepackage{textcomp}\n\\setcounter{MaxMatrixCols}{20}\n\\title{" +
         title + "}\n\\date{}\n\\begin{document}\n\\maketitle\n" + body + "\\end{document}\n";
}

}  // namespace rt::homework
