#include "lesson/placeholders.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "lesson/lesson_parser.h"

namespace rt::lesson {
namespace {

std::optional<double> values(const std::string& name) {
  if (name == "F.a.b") return 0.19982;
  if (name == "iterations.jacobi") return 42;
  if (name == "half") return 0.5;
  return std::nullopt;
}

TEST(Placeholders, FormatsValues) {
  EXPECT_EQ(*formatValue(0.199824, ""), "0.2");
  EXPECT_EQ(*formatValue(0.199824, "4"), "0.1998");
  EXPECT_EQ(*formatValue(0.199824, ".2f"), "0.20");
  EXPECT_EQ(*formatValue(0.125, "%"), "12.5%");
  EXPECT_EQ(*formatValue(41.6, "int"), "42");
  EXPECT_EQ(*formatValue(42, ""), "42");
  EXPECT_FALSE(formatValue(1, "x"));
  EXPECT_FALSE(formatValue(1, ".f"));
}

TEST(Placeholders, ResolvesFromTheResult) {
  const std::string text = "F = {{F.a.b:4}}, after {{ iterations.jacobi }} sweeps; {{half:%}}.";
  EXPECT_EQ(resolvePlaceholders(text, 1, "l.md", values), "F = 0.1998, after 42 sweeps; 50.0%.");
}

TEST(Placeholders, GroupLargeWholeNumbersInThreesInTextAndInMaths) {
  auto lookup = [](const std::string& name) -> std::optional<double> {
    if (name == "n") return 56210;
    if (name == "bytes") return 25276502016;
    if (name == "small") return 2880;
    if (name == "negative") return -123456;
    return 0.5;
  };
  EXPECT_EQ(
      resolvePlaceholders("n = {{n}}, {{bytes:int}} bytes, {{small}}, {{negative:int}}", 1, "l.md", lookup),
      "n = 56,210, 25,276,502,016 bytes, 2880, -123,456");
  EXPECT_EQ(
      resolvePlaceholders("$n = {{n}}$ and $$8 n^2 = {{bytes:int}}$$, {{n}} \\$ {{n}}", 1, "l.md", lookup),
      "$n = 56{,}210$ and $$8 n^2 = 25{,}276{,}502{,}016$$, 56,210 \\$ 56,210");
  // Not whole numbers: as formatted.
  EXPECT_EQ(resolvePlaceholders("{{half:.5f}}, {{bytes:3}}", 1, "l.md", lookup), "0.50000, 2.53e+10");
}

TEST(Placeholders, UnknownNamesNameTheLine) {
  try {
    resolvePlaceholders("one\ntwo {{F.a.c}}\n", 10, "l.md", values, {"F.a.b"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 11);
    EXPECT_NE(std::string(e.what()).find("F.a.b"), std::string::npos);
  }
}

TEST(Placeholders, FindsMalformedOnes) {
  const auto found = findPlaceholders("a {{ok}} b {{bad name}} c {{x:zz}} {{open\n}}", 1);
  ASSERT_EQ(found.size(), 4u);
  EXPECT_TRUE(found[0].error.empty());
  EXPECT_FALSE(found[1].error.empty());
  EXPECT_FALSE(found[2].error.empty());
  EXPECT_FALSE(found[3].error.empty());
}

}  // namespace
}  // namespace rt::lesson

// A format with a huge digit count is an error at its line, not an exception from std::stoi (found by
// fuzzing).
TEST(Placeholders, AHugeDigitCountIsAnErrorAtItsLine) {
  const std::string text =
      "---\ntitle: T\norder: 1\n---\n\n## S\n\n```step\nstage: text\n```\n\nIt has {{elements:99999999999}} "
      "and "
      "{{x:.99999999999f}}.\n";
  try {
    rt::lesson::parseLesson(text, "t", "t.md");
    FAIL() << "accepted";
  } catch (const rt::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.md:12"), std::string::npos) << e.what();
  }
}
