// Reading the values of lesson files (`key: value`): numbers with ranges, booleans, comma-separated lists,
// colours and vectors. Every failure is an InputError at the value's location, saying what was expected.
#pragma once

#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/vec.h"

namespace rt::lesson {

int parseInt(const std::string& text, const SourceLocation& where, const std::string& key, int min, int max);
double parseDouble(const std::string& text, const SourceLocation& where, const std::string& key, double min,
                   double max);
bool parseBool(const std::string& text, const SourceLocation& where, const std::string& key);
// "a, b, c" or "a b c": trimmed, empty items dropped.
std::vector<std::string> parseList(const std::string& text);
// "a, b, c": the names an error message offers.
std::string joinedNames(const std::vector<std::string>& names);
std::vector<int> parseIntList(const std::string& text, const SourceLocation& where, const std::string& key,
                              int min, int max);
// One number (grey) or three (r g b), each in [min, max].
Rgb parseRgb(const std::string& text, const SourceLocation& where, const std::string& key, double min,
             double max);
Vec3 parseVec3(const std::string& text, const SourceLocation& where, const std::string& key);

}  // namespace rt::lesson
