// The handouts' Markdown as LaTeX source: the maths is already LaTeX ($...$), so only the prose needs
// converting: `code` to \texttt, pipe tables to tabular, headings, list items, and the characters LaTeX
// reserves escaped outside maths.
#pragma once

#include <string>

namespace rt::homework {

std::string markdownToLatex(const std::string& markdown);
// A complete document around a body (amsmath and amssymb only, so any TeX installation typesets it).
std::string latexDocument(const std::string& title, const std::string& body);

}  // namespace rt::homework
