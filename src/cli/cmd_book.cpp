// radiosity book: the whole book as a self-contained HTML site (index, one page per lesson, KaTeX's style and
// fonts copied beside them, equations set in the pages) and as one PDF, from the lessons the app shows.
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/lesson_rendering.h"
#include "cli/web_edition.h"
#include "core/input_error.h"
#include "lesson/book_html.h"
#ifdef RT_HAVE_TYPESET
#include <QDir>
#include <QString>

#include "typeset/book_printer.h"
#include "typeset/typesetter.h"
#include "typeset/web_engine.h"
#endif

namespace rt::cli {
namespace {

namespace fs = std::filesystem;

struct BookOptions {
  LessonArguments lessons;
  std::string output;
  RenderSettings figures;
  bool pdf = true;
  bool web = false;  // the web edition: live views computed in the browser (web_edition.h)
  WebAssets assets = defaultWebAssets();
};

#ifdef RT_HAVE_TYPESET
void write(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

// KaTeX's style sheet and fonts, so that the pages need nothing from elsewhere.
void copyKatex(const fs::path& output) {
  const fs::path katex = typeset::katexDirectory().toStdString();
  if (!fs::exists(katex / "katex.min.css"))
    throw std::runtime_error(katex.string() + ": KaTeX is not there (install libjs-katex)");
  fs::create_directories(output / "katex");
  fs::copy_file(katex / "katex.min.css", output / "katex" / "katex.min.css",
                fs::copy_options::overwrite_existing);
  fs::copy(katex / "fonts", output / "katex" / "fonts",
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

void fail(const std::vector<std::string>& problems, const std::string& what) {
  for (const auto& p : problems) std::cerr << p << "\n";
  throw InputError({}, std::to_string(problems.size()) + " " + what + " (listed above)");
}

void book(BookOptions o) {
  if (o.lessons.ids.empty()) o.lessons.all = true;
  const typeset::WebSession session;
  const auto folders = o.lessons.folders();
  const auto files = o.lessons.files();
  // Every formula first: a typing mistake in one is reported at its line before anything is computed.
  std::vector<std::string> problems;
  for (const auto& file : files)
    for (auto& p : lessonTextProblems(lesson::loadLesson(file, folders.scenes)))
      problems.push_back(std::move(p));
  if (!problems.empty()) fail(problems, "problem(s) in the lessons' text");

  o.figures.format = "svg";  // vectors where the view is 2D (3D views are pictures inside the SVG)
  o.figures.prepareText = true;
  o.figures.lessonWord = "chapter";  // as the book's headings: "Chapter 19"
  const auto lessons = renderLessons(files, folders, o.output, o.figures);
  const fs::path out = o.output;
  copyKatex(out);
  write(out / lesson::kBookStyleFile, lesson::bookStyleSheet());
  std::vector<fs::path> pages{out / lesson::kBookIndexFile};
  write(pages.front(), lesson::indexPageHtml(lessons, o.pdf));
  for (const auto& l : lessons) {
    pages.push_back(out / lesson::lessonPageFile(l));
    write(pages.back(), lesson::lessonPageHtml(l, lessons));
  }
  int formulas = 0;
  for (const auto& page : pages) {
    const auto report = typeset::typesetHtmlFile(QString::fromStdString(page.string()));
    formulas += report.formulas;
    for (const auto& e : report.errors) problems.push_back(page.string() + ": error: " + e);
  }
  if (!problems.empty()) fail(problems, "formula(s) did not typeset");
  std::cout << out.string() << "/index.html: " << pages.size() << " pages, " << formulas << " formulas\n";
  if (o.web) {
    const int views = writeWebEdition(o.output, lessons, files, folders, o.assets);
    std::cout << out.string() << "/web: " << views << " live views, computed in the browser\n";
  }
  if (!o.pdf) return;
  const fs::path print = out / lesson::kBookPrintFile;
  write(print, lesson::printBookHtml(lessons));
  const auto printed = typeset::printBook(QString::fromStdString(print.string()),
                                          QString::fromStdString((out / "book.pdf").string()));
  fs::remove(print);
  if (!printed.maths.errors.empty()) fail(printed.maths.errors, "formula(s) did not typeset in the PDF");
  // Not an error: the page is still readable, but the equation wants a line break (aligned, or split).
  for (const auto& wide : printed.tooWide)
    std::cerr << (out / "book.pdf").string() << ", " << wide
              << ": warning: the equation is wider than the text\n";
  std::cout << out.string() << "/book.pdf: " << printed.pages << " pages\n";
}
#endif

}  // namespace

void addBookCommand(CLI::App& app) {
  auto options = std::make_shared<BookOptions>();
  auto* command = app.add_subcommand(
      "book",
      "Write the book: an HTML site (DIR/index.html, one page per lesson, figures as SVG) and DIR/book.pdf, "
      "with every equation typeset (run it under xvfb-run without a display: the figures need X)");
  options->lessons.add(command);
  command->add_option("--output,-o", options->output, "Output folder")->required();
  command->add_flag("--quick", options->figures.quick, "Small meshes, resolutions and figures (for tests)");
  command->add_flag("!--no-pdf", options->pdf, "Write the HTML site only");
  command->add_flag("--web", options->web,
                    "The web edition: every step that solves a scene in 3D gets a live view under its figure "
                    "(rotate, scrub the iterations, change the light and a reflectance), computed in the "
                    "browser by the WebAssembly core; opens from the file system or any static server");
  command->add_option("--wasm", options->assets.module,
                      "--web: the WebAssembly core to ship (default: the wasm preset's build)");
  command->add_option("--width", options->figures.width, "Figure width in pixels")
      ->check(CLI::Range(64, 8192));
  command->add_option("--height", options->figures.height, "Figure height in pixels")
      ->check(CLI::Range(64, 8192));
  command->callback([options] {
#ifdef RT_HAVE_TYPESET
    BookOptions o = *options;
    if (o.figures.quick) {
      o.figures.width = std::min(o.figures.width, 480);
      o.figures.height = std::min(o.figures.height, 360);
    }
    book(o);
#else
    throw std::runtime_error(
        "this build has no typesetting (Qt WebEngine and KaTeX): install qt6-webengine-dev and libjs-katex "
        "(./install-deps.sh) and build with the dev or release preset; `radiosity lesson render` writes the "
        "book as Markdown");
#endif
  });
}

}  // namespace rt::cli
