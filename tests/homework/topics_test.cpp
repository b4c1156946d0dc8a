// Every topic of the table: 200 seeds give well-posed variants, a seed gives the same variant again, and
// students get different numbers.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "homework/topic_table.h"
#include "support/test_paths.h"

namespace rt::homework {
namespace {

TEST(HomeworkTopics, TableHasTwelveTopicsWithGenerators) {
  EXPECT_GE(topicTable().size(), 12u);
  std::set<std::string> ids;
  for (const Topic& t : topicTable()) {
    EXPECT_TRUE(ids.insert(t.id).second) << t.id;
    EXPECT_NE(t.generate, nullptr) << t.id;
    EXPECT_EQ(findTopic(t.id), &t);
  }
  EXPECT_EQ(findTopic("no-such-topic"), nullptr);
}

TEST(HomeworkTopics, TwoHundredSeedsGiveWellPosedVariants) {
  for (const Topic& t : topicTable())
    for (int seed = 1; seed <= 200; ++seed) {
      const Exercise e = generateExercise(t, static_cast<std::uint64_t>(seed), 1 + seed % 7);
      const auto problems = exerciseProblems(e);
      EXPECT_TRUE(problems.empty()) << t.id << " seed " << seed << ": " << problems.front();
      EXPECT_EQ(e.topic, t.id);
      for (const Question& q : e.questions)
        for (const Mistake& m : q.mistakes)  // a named slip is always distinguishable from the answer
          EXPECT_GT(std::abs(m.value - q.answer), q.tolerance) << t.id << " " << q.id << " " << m.name;
    }
}

TEST(HomeworkTopics, SameSeedSameVariantOtherStudentOtherNumbers) {
  for (const Topic& t : topicTable()) {
    const Exercise a = generateExercise(t, 7, 3), b = generateExercise(t, 7, 3);
    ASSERT_EQ(a.questions.size(), b.questions.size()) << t.id;
    EXPECT_EQ(a.statement, b.statement) << t.id;
    for (std::size_t k = 0; k < a.questions.size(); ++k)
      EXPECT_EQ(a.questions[k].answer, b.questions[k].answer);
    // Among 30 students, the statements (their numbers) are almost all different.
    std::set<std::string> statements;
    for (int s = 1; s <= 30; ++s) statements.insert(generateExercise(t, 7, s).statement);
    EXPECT_GE(statements.size(), 27u) << t.id;
  }
}

TEST(HomeworkTopics, TableMarkdownListsEveryTopicAndTheDocsHoldIt) {
  const std::string md = topicTableMarkdown();
  for (const Topic& t : topicTable()) EXPECT_NE(md.find(std::string("`") + t.id + "`"), std::string::npos);
  std::ifstream in(test::sourcePath("docs/homework.md"));
  std::stringstream docs;
  docs << in.rdbuf();
  EXPECT_NE(docs.str().find(md), std::string::npos)
      << "docs/homework.md should hold the output of `radiosity homework topics`:\n"
      << md;
}

}  // namespace
}  // namespace rt::homework
