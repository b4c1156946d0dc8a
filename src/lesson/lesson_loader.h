// Loading lessons from files and listing the lessons of a folder. A new file dropped into lessons/ is a new
// lesson: nothing is compiled in. Lesson ids are file names without the .md extension; the book's order comes
// from `order`.
#pragma once

#include <string>
#include <vector>

#include "lesson/lesson.h"

namespace rt::lesson {

// Where lessons and the scenes they name live (normally <repo>/lessons and <repo>/scenes).
struct LessonFolders {
  std::string lessons;
  std::string scenes;
};
// ./lessons and ./scenes when the working directory has them, otherwise the source tree this was built from.
LessonFolders defaultFolders();
// The folders under a repository root.
LessonFolders foldersUnder(const std::string& root);

// Parses the file and checks that every scene it names exists under scenesDir. Throws InputError (file:line).
Lesson loadLesson(const std::string& path, const std::string& scenesDir);
// The file of a lesson id in a folder; throws InputError listing the known ids when there is none.
std::string lessonPath(const LessonFolders& folders, const std::string& id);
// Every *.md in the folder, sorted by (order, id). Throws the first InputError met; see also lessonFiles().
std::vector<Lesson> loadCatalogue(const LessonFolders& folders);
// The lesson files of a folder, sorted by name (for checking them one by one).
std::vector<std::string> lessonFiles(const std::string& lessonsDir);

// The checks that need the scenes themselves: surface names in reflectance overrides, highlights and `from`
// exist, element ids are in range of the unsubdivided scene. Loads each scene once; throws InputError at the
// field's line.
void checkAgainstScenes(const Lesson& lesson, const std::string& scenesDir);

}  // namespace rt::lesson
