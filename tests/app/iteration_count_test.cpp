// The player, the status line and the result count the bounces alike: record 0 of a bounces run is the
// emission (after 0 bounces), so the player's last position is after as many bounces as the status line says.
#include <gtest/gtest.h>

#include <QLabel>

#include "app/iteration_player.h"
#include "app/lesson_session.h"
#include "app/pipeline.h"
#include "app/wording.h"
#include "app_test_support.h"

using namespace rt::app;

TEST(IterationCount, ThePlayerTheStatusLineAndTheResultAgreeOnTheBounces) {
  RT_REQUIRE_DISPLAY();
  auto window = test::makeWindow();
  const int index = window->library()->indexOf("cornell-box");
  ASSERT_GE(index, 0);
  const auto& lesson = window->library()->lessons()[static_cast<std::size_t>(index)];
  int step = -1;
  for (const auto& s : lesson.steps)
    if (s.title == "Many bounces") step = s.index;
  ASSERT_GE(step, 0);
  ASSERT_TRUE(window->openLesson("cornell-box", step));
  ASSERT_TRUE(window->waitUntilIdle());
  const PipelineResult* result = window->result();
  ASSERT_NE(result, nullptr);
  ASSERT_EQ(result->solverName, "bounces");
  ASSERT_FALSE(result->history.empty());
  // The step asks for its bounces; the history holds B after 0, 1, ... of them.
  const int bounces = lesson.steps[static_cast<std::size_t>(step)].parameters.bounces;
  EXPECT_EQ(static_cast<int>(result->history.size()), bounces + 1);
  const QString count = counted(bounces, iterationUnit(result->solverName));  // "12 bounces"

  IterationPlayer* player = window->player();
  player->setCurrent(player->iterationCount() - 1);
  EXPECT_EQ(player->label(), QString("%1 / %2").arg(bounces).arg(count));
  player->setCurrent(0);
  EXPECT_EQ(player->label(), QString("0 / %1").arg(count)) << "the first record is the emission";

  auto* status = window->findChild<QLabel*>("statusMessage");
  ASSERT_NE(status, nullptr);
  EXPECT_TRUE(status->text().contains("after " + count)) << status->text().toStdString();
  EXPECT_EQ(solveSummary(*result), solveSummary("bounces", result->status, bounces, result->residual));
}
