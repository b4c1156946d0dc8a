// Wavefront MTL material libraries, as modelling tools write them: Kd = diffuse reflectance, Ke = emission
// (W/m^2). Everything else a library may hold (specular terms, texture maps) has no meaning for diffuse
// radiosity and is skipped; texture maps get one warning per material, since a textured wall loses its
// picture here. Internal to src/core/io (the OBJ loader and the fuzz targets use it).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"

namespace rt::io_detail {

struct MtlMaterial {
  Material material;        // reflectance from Kd, emission from Ke (0 without one)
  SourceLocation newmtl;    // where it is defined, for messages
  bool hasKd = false;       // false: using it on a face is an error (a library may define unused ones)
  std::string ignoredMaps;  // the first texture map statement, reported once
};

struct MtlLibrary {
  std::vector<MtlMaterial> materials;  // in file order; a name defined twice keeps its later definition
  std::vector<std::string> warnings;   // "file:line: warning: ..."
};

// Parses the text of one .mtl file (`path` only names it in messages). Throws InputError at the line for a
// malformed or out-of-range Kd/Ke (reflectance outside [0,1), negative or non-finite emission).
MtlLibrary parseMtl(const std::string& text, const std::string& path);

// Lines of a text without their terminators ("\r\n" or "\n"); a line ending in '\' continues on the next
// (OBJ and MTL allow it), counted at its first line. Returns (line number, text) pairs.
std::vector<std::pair<int, std::string>> logicalLines(const std::string& text);
std::string trimmed(const std::string& text);  // without leading and trailing white space
// The statement part of a line: everything before '#', trimmed.
std::string withoutComment(const std::string& line);
std::vector<std::string> splitWords(const std::string& line);
// The rest of a line after its keyword: "newmtl red wall" -> "red wall".
std::string afterFirstWord(const std::string& line);
// A number that is all of `word`; nullopt for "1.5x", "", "abc".
std::optional<double> parseNumber(const std::string& word);

}  // namespace rt::io_detail
