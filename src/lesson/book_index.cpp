#include "lesson/book_index.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "lesson/book_html.h"
#include "lesson/markdown_html.h"

namespace rt::lesson {
namespace {

using Range = std::pair<std::size_t, std::size_t>;

struct Mark {
  Range range;
  std::string html;  // what opens the mark; it closes with closeTag
  std::string closeTag;
};

std::string lowerCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string apply(std::string text, std::vector<Mark> marks) {
  std::sort(marks.begin(), marks.end(), [](const Mark& a, const Mark& b) { return a.range > b.range; });
  for (const Mark& m : marks) {
    text.insert(m.range.second, m.closeTag);
    text.insert(m.range.first, m.html);
  }
  return text;
}

}  // namespace

std::vector<IndexEntry> markIndexTerms(std::vector<RenderedLesson>& chapters,
                                       const std::vector<GlossaryEntry>& terms) {
  std::map<std::string, IndexEntry> index;  // by the lower-case term: sorted as the index prints it
  for (RenderedLesson& chapter : chapters) {
    const std::string page = lessonPageFile(chapter);
    const std::string number = std::to_string(chapter.order);
    std::vector<std::string*> sections{&chapter.intro};
    for (RenderedStep& step : chapter.steps) sections.push_back(&step.text);
    std::map<std::string, bool> linked;  // terms whose definition this chapter already links to
    for (std::size_t k = 0; k < sections.size(); ++k) {
      std::string& text = *sections[k];
      std::vector<Mark> marks;
      for (const TermUse& use : firstTermUses(text, terms)) {
        const GlossaryEntry* t = use.entry;
        const std::string anchor =
            "ix-" + glossaryAnchor(t->term).substr(3) + "-" + number + "-" + std::to_string(k);
        IndexEntry& entry = index[lowerCase(t->term)];
        entry.term = t->term;
        entry.defined = !t->indexOnly;
        entry.locators.push_back({page, anchor, k == 0 ? number : number + "." + std::to_string(k)});
        if (!t->indexOnly && !linked[t->term]) {
          linked[t->term] = true;
          marks.push_back({use.range,
                           "<a class=\"term\" id=\"" + anchor + "\" href=\"" + kGlossaryPage + "#" +
                               glossaryAnchor(t->term) + "\" title=\"" + escapeHtml(definitionText(*t)) +
                               "\">",
                           "</a>"});
        } else {
          marks.push_back({use.range, "<span class=\"term-use\" id=\"" + anchor + "\">", "</span>"});
        }
      }
      text = apply(text, std::move(marks));
    }
  }
  std::vector<IndexEntry> sorted;
  for (auto& [key, entry] : index) sorted.push_back(std::move(entry));
  return sorted;
}

std::string indexHtml(const std::vector<IndexEntry>& index) {
  // One block per line and no blank line: Markdown passes the whole body through as HTML.
  std::string html;
  char letter = 0;
  for (const IndexEntry& e : index) {
    const char first = static_cast<char>(std::toupper(static_cast<unsigned char>(e.term.front())));
    if (first != letter) {
      letter = first;
      html += "<h3 class=\"index-letter\">" + escapeHtml(std::string(1, letter)) + "</h3>\n";
    }
    const std::string term = escapeHtml(e.term);
    html += "<p class=\"index-entry\"><span class=\"index-term\">" +
            (e.defined ? "<a href=\"" + std::string(kGlossaryPage) + "#" + glossaryAnchor(e.term) + "\">" +
                             term + "</a>"
                       : term) +
            "</span> ";
    for (std::size_t k = 0; k < e.locators.size(); ++k) {
      const IndexLocator& l = e.locators[k];
      html += (k ? ", " : "") + std::string("<a class=\"index-ref\" href=\"") + l.page + "#" + l.anchor +
              "\">" + l.label + "</a>";
    }
    html += "</p>\n";
  }
  return html;
}

std::string indexStyleSheet() {
  return R"(/* The index: each term with every section that uses it. */
.index-letter { margin: 0.8em 0 0.2em; }
.index-entry { margin: 0.1em 0 0.1em 1.5em; text-indent: -1.5em; }
.index-entry .index-term a { color: inherit; text-decoration: none; font-weight: bold; }
/* Printed, a reference holds the width of a page number until the layout has written one in (never wider). */
.print .index-entry a.index-ref { display: inline-block; min-width: 1.8em; text-indent: 0; }
)";
}

}  // namespace rt::lesson
