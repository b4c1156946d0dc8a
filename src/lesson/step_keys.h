// The one table of step keys (docs/lesson-format.md): every key a ```step block accepts, with its type,
// range, default, label and tooltip, the stages it belongs to, and whether the reader may change it in the
// app
// (`controls:`). The lesson parser reads values through it, the app's parameter panel builds its widgets from
// it, the placeholders and the docs list it: a key added here is parsed, offered and documented everywhere.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/input_error.h"
#include "lesson/lesson.h"

namespace rt::lesson {

enum class KeyType {
  Int,      // whole number in [min, max]
  Double,   // number in [min, max]
  Bool,     // true/false, yes/no, on/off
  Choice,   // one of choices()
  Choices,  // a comma-separated list of choices()
  Ints,     // a comma-separated list of whole numbers in [min, max]
  Rgb,      // one number (grey) or three (r g b)
  Vec3,     // three numbers
  Text,     // free text, checked by the parser or the runner
};

// Where a parameter key stores its value in StepParameters (keys that describe the step itself, such as
// `scene` or `views`, have none: the parser handles them).
using ParameterSlot =
    std::variant<std::monostate, std::optional<int> StepParameters::*, int StepParameters::*,
                 std::optional<double> StepParameters::*, double StepParameters::*, bool StepParameters::*,
                 std::string StepParameters::*, std::vector<std::string> StepParameters::*,
                 std::vector<int> StepParameters::*, std::optional<std::uint64_t> StepParameters::*>;

struct StepKey {
  std::string name;
  KeyType type = KeyType::Text;
  double min = 0, max = 0;                                 // Int, Double, Ints
  const std::vector<std::string>& (*choices)() = nullptr;  // Choice, Choices
  std::string defaultText;                                 // what an unset key means, as the docs say it
  std::string label;                                       // the app's row label
  std::string tooltip;                                     // the app's tooltip and the docs' description
  bool control = false;       // may be named in `controls:`, gets a widget in the app
  bool logScale = false;      // Double spanning decades (tolerances): typed, not spun
  int decimals = 2;           // Double widgets
  double step = 1;            // Int and Double widgets: the arrow keys' step
  std::string zeroText;       // numeric keys where 0 stands for a choice made for the reader ("automatic")
  std::vector<Stage> stages;  // empty: every stage that computes something
  ParameterSlot slot;

  // Every allowed value of a Choice key.
  std::vector<std::string> allowed() const { return choices ? choices() : std::vector<std::string>{}; }
  bool acceptedBy(Stage stage) const;
};

const std::vector<StepKey>& stepKeyTable();
// The row of `name`; `reflectance.<surface>` is the row "reflectance". Null for unknown keys.
const StepKey* findStepKey(const std::string& name);

// Parses `value` as the key's type and range (InputError at `where` otherwise) and stores it in `p`. For
// `reflectance.<surface>` the surface comes from `name`. Keys without a slot are not handled here.
void applyStepValue(StepParameters& p, const StepKey& key, const std::string& name, const std::string& value,
                    const SourceLocation& where);
// The value of a parameter key in `p`, written as a lesson would write it; nullopt when unset (the method's
// or solver's own default applies).
std::optional<std::string> stepValueText(const StepParameters& p, const StepKey& key,
                                         const std::string& name);

// The table as Markdown (docs/lesson-format.md includes it; a test keeps the two equal).
std::string stepKeyTableMarkdown();

}  // namespace rt::lesson
