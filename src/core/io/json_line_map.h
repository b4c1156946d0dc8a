// Line numbers of the values in a JSON text, by JSON pointer ("/surfaces/3/polygons/0/2"), so that messages
// about a value can say "file:12 at /surfaces/3/..." and a user can jump to it. nlohmann::json keeps no
// positions of its own.
#pragma once

#include <string>
#include <unordered_map>

namespace rt::io_detail {

class JsonLineMap {
 public:
  // `text` should be valid JSON (parse it first); on malformed text the map is simply incomplete.
  explicit JsonLineMap(const std::string& text);
  // 1-based line where the value at `pointer` starts; 0 when unknown. "" is the root.
  int lineOf(const std::string& pointer) const;
  // JSON pointer of the first key that appears twice in one object ("" when none). nlohmann::json keeps only
  // one of the two values, so a repeated key would otherwise silently lose data.
  const std::string& firstDuplicateKey() const { return duplicate_; }

 private:
  std::unordered_map<std::string, int> lines_;
  std::string duplicate_;
};

// RFC 6901 escaping of one reference token ("~" -> "~0", "/" -> "~1").
std::string escapeJsonPointerToken(const std::string& token);

}  // namespace rt::io_detail
