#include "typeset/book_printer.h"

#include <QFile>
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
// The blocks are measured in one layout (the flow set at the page's width) and grouped by their heights;
// laying out after every block instead costs a layout of the whole document per block, minutes for a
// document of 250 pages. A list or table taller than a page is split between its items or rows (a page clips
// what overflows it). A check per page then moves what still overflows (the measures are of one long flow,
// not of pages) to the top of the next page of the same chapter, or to a new page at a chapter's end; the
// next page is checked in turn, so no page is left holding a stray line. Then numbers the pages (not a book's
// title page; a document's first page is numbered), writes each contents line's page and turns each index
// link into the page number of the use it points to, each page once per term. Returns, as JSON, the page
// count and the displayed equations wider than the text.
const char* kPaginate = R"JS((function () {
  var flow = document.getElementById('flow');
  var blocks = Array.prototype.slice.call(flow.children);
  var pages = [];
  function newPage(before) {
    var page = document.createElement('div');
    page.className = 'page';
    var body = document.createElement('div');
    body.className = 'page-body';
    var number = document.createElement('div');
    number.className = 'page-number';
    page.appendChild(body);
    page.appendChild(number);
    document.body.insertBefore(page, before || null);
    return page;
  }
  function isHeading(b) { return /^H[1-4]$/.test(b.tagName); }
  function startsPage(b) { return b.classList.contains('chapter') || b.classList.contains('toc-title'); }
  function parts(b) {  // the items of a list, the body rows of a table
    if (b.tagName === 'UL' || b.tagName === 'OL') return Array.prototype.slice.call(b.children);
    if (b.tagName === 'TABLE' && b.tBodies.length === 1) return Array.prototype.slice.call(b.tBodies[0].rows);
    return [];
  }

  // Measuring: reads only, in one layout.
  var probe = newPage();
  var limit = probe.firstChild.clientHeight;
  probe.style.height = 'auto';
  probe.style.contain = 'none';
  probe.firstChild.style.height = 'auto';
  probe.firstChild.appendChild(flow);
  var tops = blocks.map(function (b) { return b.getBoundingClientRect().top; });
  tops.push(blocks.length ? blocks[blocks.length - 1].getBoundingClientRect().bottom : 0);
  var splits = {};
  blocks.forEach(function (b, i) {
    var p = parts(b);
    if (tops[i + 1] - tops[i] <= limit || p.length < 2) return;
    splits[i] = p.map(function (part) { var r = part.getBoundingClientRect(); return [r.top, r.bottom]; });
  });
  document.body.removeChild(probe);
  flow.parentNode && flow.parentNode.removeChild(flow);

  // The blocks with their heights; a tall list or table becomes pieces that each fit a page.
  var items = [];
  blocks.forEach(function (b, i) {
    var height = tops[i + 1] - tops[i];
    var spans = splits[i];
    if (!spans) { items.push({ el: b, height: height }); return; }
    var elements = parts(b);
    var overhead = height - (spans[spans.length - 1][1] - spans[0][0]);  // margins, a table's header
    var first = 0;
    while (first < elements.length) {
      var last = first;
      while (last + 1 < elements.length && spans[last + 1][1] - spans[first][0] + overhead <= limit) ++last;
      var piece = b.cloneNode(false);
      var holder = piece;
      if (b.tagName === 'TABLE') {
        if (b.tHead) piece.appendChild(b.tHead.cloneNode(true));
        holder = piece.appendChild(document.createElement('tbody'));
      } else if (b.tagName === 'OL') {
        piece.start = (b.start || 1) + first;
      }
      for (var k = first; k <= last; ++k) holder.appendChild(elements[k]);
      items.push({ el: piece, height: spans[last][1] - spans[first][0] + overhead });
      first = last + 1;
    }
  });

  var groups = [[]], used = 0;
  items.forEach(function (item) {
    var group = groups[groups.length - 1];
    if (group.length > 0 && (startsPage(item.el) || used + item.height > limit)) {
      var carried = [];
      if (!startsPage(item.el) && isHeading(group[group.length - 1].el) && group.length > 1)
        carried.push(group.pop());
      groups.push(carried);
      used = carried.reduce(function (sum, c) { return sum + c.height; }, 0);
      group = carried;
    }
    group.push(item);
    used += item.height;
  });
  groups.forEach(function (group) {
    var body = newPage().firstChild;
    group.forEach(function (item) { body.appendChild(item.el); });
    pages.push(body.parentNode);
  });
  for (var p = 0; p < pages.length; ++p) {
    var body = pages[p].firstChild;
    if (body.scrollHeight <= body.clientHeight + 1 || body.children.length < 2) continue;
    var next = pages[p + 1];
    if (!next || !next.firstChild.firstElementChild || startsPage(next.firstChild.firstElementChild)) {
      next = newPage(pages[p].nextSibling);
      pages.splice(p + 1, 0, next);
    }
    var into = next.firstChild;
    while (body.scrollHeight > body.clientHeight + 1 && body.children.length > 1) {
      into.insertBefore(body.lastElementChild, into.firstChild);
      if (body.children.length > 1 && isHeading(body.lastElementChild))
        into.insertBefore(body.lastElementChild, into.firstChild);
    }
  }
  pages.forEach(function (page, i) {
    page.querySelector('.page-number').textContent =
        i === 0 && !document.body.classList.contains('document') ? '' : String(i + 1);
  });
  document.querySelectorAll('.toc-page').forEach(function (slot) {
    var link = slot.parentNode.querySelector('a');
    var target = document.getElementById(link.getAttribute('href').slice(1));
    var page = target ? target.closest('.page') : null;
    slot.textContent = page ? String(pages.indexOf(page) + 1) : '';
  });
  document.querySelectorAll('.index-entry').forEach(function (entry) {
    var refs = Array.prototype.slice.call(entry.querySelectorAll('a.index-ref'));
    if (!refs.length) return;
    var term = refs[0].previousSibling;
    while (term && term.nodeType !== 1) term = term.previousSibling;
    var seen = {};
    var kept = refs.filter(function (link) {
      var target = document.getElementById(link.getAttribute('href').slice(1));
      var page = target ? target.closest('.page') : null;
      var number = page ? String(pages.indexOf(page) + 1) : '';
      if (!number || seen[number]) return false;
      seen[number] = true;
      link.textContent = number;
      link.style.display = 'inline';  // the width held for the number is no longer needed
      return true;
    });
    while (term && term.nextSibling) entry.removeChild(term.nextSibling);
    kept.forEach(function (link, i) {
      entry.appendChild(document.createTextNode(i ? ', ' : ' '));
      entry.appendChild(link);
    });
  });
  // Displayed equations wider than the text: print shows them cut, with a scroll bar.
  var tooWide = [];
  pages.forEach(function (page, i) {
    page.querySelectorAll('.katex-display').forEach(function (display) {
      if (display.scrollWidth <= display.clientWidth + 1) return;
      var tex = display.querySelector('annotation');
      tooWide.push('page ' + (i + 1) + ': ' + (tex ? tex.textContent.replace(/\s+/g, ' ').trim() : '?'));
    });
  });
  return JSON.stringify({ pages: pages.length, tooWide: tooWide });
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
  const QJsonObject laidOut = QJsonDocument::fromJson(page.run(kPaginate).toString().toUtf8()).object();
  book.pages = laidOut.value("pages").toInt();
  for (const auto& e : laidOut.value("tooWide").toArray()) book.tooWide.push_back(e.toString().toStdString());
  if (!page.printToPdf(pdfFile)) throw std::runtime_error(pdfFile.toStdString() + ": cannot write the PDF");
  // WebEngine writes the PDF for its owner only; a book or a handout is for handing out.
  QFile::setPermissions(pdfFile,
                        QFile::permissions(pdfFile) | QFileDevice::ReadGroup | QFileDevice::ReadOther);
  return book;
}

}  // namespace rt::typeset
