// Markdown to HTML with md4c (CommonMark, tables, strikethrough, LaTeX maths spans). Maths comes out as
// <x-equation>TeX</x-equation> (type="display" for $$...$$), for the typesetter to replace.
#pragma once

#include <string>

namespace rt::lesson {

std::string markdownToHtml(const std::string& markdown);

// Escapes &, <, > and " for HTML text and attribute values.
std::string escapeHtml(const std::string& text);

}  // namespace rt::lesson
