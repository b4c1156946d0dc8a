#include "core/io/json_line_map.h"

namespace rt::io_detail {

namespace {

// A minimal recursive-descent walk over JSON text that records the line of every value under its JSON
// pointer.
class Scanner {
 public:
  Scanner(const std::string& text, std::unordered_map<std::string, int>& lines, std::string& duplicate)
      : text_(text), lines_(lines), duplicate_(duplicate) {}
  void value(const std::string& pointer);

 private:
  void object(const std::string& pointer);
  void array(const std::string& pointer);
  std::string string();
  void skipWhitespace();

  const std::string& text_;
  std::unordered_map<std::string, int>& lines_;
  std::string& duplicate_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

void Scanner::skipWhitespace() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
    } else if (c != ' ' && c != '\t' && c != '\r') {
      return;
    }
    ++pos_;
  }
}

void Scanner::value(const std::string& pointer) {
  skipWhitespace();
  if (pos_ >= text_.size()) return;
  lines_[pointer] = line_;
  const char c = text_[pos_];
  if (c == '{') {
    object(pointer);
  } else if (c == '[') {
    array(pointer);
  } else if (c == '"') {
    string();
  } else {
    // Number or literal: runs until a structural character or whitespace.
    static const std::string kEnd = ",]} \t\r\n";
    while (pos_ < text_.size() && kEnd.find(text_[pos_]) == std::string::npos) ++pos_;
  }
}

void Scanner::object(const std::string& pointer) {
  ++pos_;  // '{'
  skipWhitespace();
  if (pos_ < text_.size() && text_[pos_] == '}') {
    ++pos_;
    return;
  }
  while (pos_ < text_.size()) {
    skipWhitespace();
    const std::string key = string();
    skipWhitespace();
    if (pos_ >= text_.size() || text_[pos_] != ':') return;
    ++pos_;
    const std::string child = pointer + "/" + escapeJsonPointerToken(key);
    if (duplicate_.empty() && lines_.count(child)) duplicate_ = child;
    value(child);
    skipWhitespace();
    if (pos_ >= text_.size()) return;
    if (text_[pos_++] != ',') return;  // '}' ends the object
  }
}

void Scanner::array(const std::string& pointer) {
  ++pos_;  // '['
  skipWhitespace();
  if (pos_ < text_.size() && text_[pos_] == ']') {
    ++pos_;
    return;
  }
  for (int index = 0; pos_ < text_.size(); ++index) {
    value(pointer + "/" + std::to_string(index));
    skipWhitespace();
    if (pos_ >= text_.size()) return;
    if (text_[pos_++] != ',') return;  // ']' ends the array
  }
}

std::string Scanner::string() {
  std::string out;
  if (pos_ >= text_.size() || text_[pos_] != '"') return out;
  ++pos_;
  while (pos_ < text_.size() && text_[pos_] != '"') {
    if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) {
      // Simple escapes decode to the character; \uXXXX stays as written (keys of scene files are plain
      // ASCII).
      const char e = text_[++pos_];
      out += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'u' ? 'u' : e;
    } else {
      out += text_[pos_];
    }
    ++pos_;
  }
  ++pos_;  // closing quote
  return out;
}

}  // namespace

JsonLineMap::JsonLineMap(const std::string& text) {
  Scanner(text, lines_, duplicate_).value("");
}

int JsonLineMap::lineOf(const std::string& pointer) const {
  const auto it = lines_.find(pointer);
  return it == lines_.end() ? 0 : it->second;
}

std::string escapeJsonPointerToken(const std::string& token) {
  std::string out;
  for (const char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace rt::io_detail
