#include "typeset/book_printer.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUrl>
#include <stdexcept>

#include "typeset/web_engine.h"

namespace rt::typeset {
namespace {

// Moves the blocks of #flow into pages of fixed height: a block that does not fit starts the next page, a
// chapter or the contents always starts one, and a heading left last on a page goes over with its block.
// Then numbers the pages (not the title page) and writes each contents line's page. Returns the page count.
const char* kPaginate = R"JS((function () {
  var flow = document.getElementById('flow');
  var blocks = Array.prototype.slice.call(flow.children);
  flow.parentNode.removeChild(flow);
  var pages = [];
  function newPage() {
    var page = document.createElement('div');
    page.className = 'page';
    var body = document.createElement('div');
    body.className = 'page-body';
    var number = document.createElement('div');
    number.className = 'page-number';
    page.appendChild(body);
    page.appendChild(number);
    document.body.appendChild(page);
    pages.push(page);
    return body;
  }
  var body = newPage();
  blocks.forEach(function (block) {
    var starts = block.classList.contains('chapter') || block.classList.contains('toc-title');
    if (starts && body.children.length > 0) body = newPage();
    body.appendChild(block);
    if (body.scrollHeight <= body.clientHeight + 1 || body.children.length === 1) return;
    var carried = [block];
    var previous = block.previousElementSibling;
    if (previous && /^H[1-4]$/.test(previous.tagName) && body.children.length > 2) carried.unshift(previous);
    body = newPage();
    carried.forEach(function (b) { body.appendChild(b); });
  });
  pages.forEach(function (page, i) {
    page.querySelector('.page-number').textContent = i === 0 ? '' : String(i + 1);
  });
  document.querySelectorAll('.toc-page').forEach(function (slot) {
    var link = slot.parentNode.querySelector('a');
    var target = document.getElementById(link.getAttribute('href').slice(1));
    var page = target ? target.closest('.page') : null;
    slot.textContent = page ? String(pages.indexOf(page) + 1) : '';
  });
  return pages.length;
})())JS";

}  // namespace

PrintedBook printBook(const QString& htmlFile, const QString& pdfFile) {
  SyncPage page;
  if (!page.load(QUrl::fromLocalFile(htmlFile)))
    throw std::runtime_error(htmlFile.toStdString() + ": cannot load the book");
  page.loadKatex();
  PrintedBook book;
  const QJsonObject maths = QJsonDocument::fromJson(page.run(typesetScript()).toString().toUtf8()).object();
  book.maths.formulas = maths.value("formulas").toInt();
  for (const auto& e : maths.value("errors").toArray())
    book.maths.errors.push_back(e.toString().toStdString());
  // The layout measures the blocks: KaTeX's fonts and the figures must be there first.
  page.run("document.fonts.ready.then(function () { window.rtFontsReady = true; }); true");
  page.waitFor("window.rtFontsReady === true", 20000);
  page.waitFor("Array.prototype.every.call(document.images, function (i) { return i.complete; })", 20000);
  book.pages = page.run(kPaginate).toInt();
  if (!page.printToPdf(pdfFile)) throw std::runtime_error(pdfFile.toStdString() + ": cannot write the PDF");
  return book;
}

}  // namespace rt::typeset
