#include "lesson/lesson_loader.h"
#include "core/camera_path.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/input_error.h"
#include "core/io/scene_loader.h"
#include "lesson/lesson_parser.h"
#include "lesson/value_parsing.h"

namespace fs = std::filesystem;

namespace rt::lesson {
namespace {

int lineOf(const Step& step, const std::string& key) {
  auto it = step.fields.find(key);
  return it == step.fields.end() ? step.line : it->second.line;
}

bool isNumber(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

LessonFolders foldersUnder(const std::string& root) {
  return {(fs::path(root) / "lessons").string(), (fs::path(root) / "scenes").string()};
}

LessonFolders defaultFolders() {
  if (fs::is_directory("lessons")) return foldersUnder(".");
#ifdef RT_LESSON_SOURCE_ROOT
  return foldersUnder(RT_LESSON_SOURCE_ROOT);
#else
  return foldersUnder(".");
#endif
}

Lesson loadLesson(const std::string& path, const std::string& scenesDir) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path}, "cannot read the lesson file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  Lesson lesson = parseLesson(buffer.str(), fs::path(path).stem().string(), path);
  for (const auto& step : lesson.steps) {
    for (const auto& listed : parseList(step.parameters.scenes))
      if (!fs::is_regular_file(fs::path(scenesDir) / listed))
        throw InputError({path, lineOf(step, "scenes")},
                         "scene file '" + listed + "' does not exist in " + scenesDir);
    if (step.scene.empty()) continue;
    const fs::path scene = fs::path(scenesDir) / step.scene;
    if (!fs::is_regular_file(scene))
      throw InputError({path, lineOf(step, "scene")},
                       "scene file '" + step.scene + "' does not exist in " + scenesDir);
  }
  return lesson;
}

std::vector<std::string> lessonFiles(const std::string& lessonsDir) {
  std::vector<std::string> files;
  if (!fs::is_directory(lessonsDir)) throw InputError({lessonsDir}, "the lessons folder does not exist");
  for (const auto& entry : fs::directory_iterator(lessonsDir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".md" &&
        entry.path().filename() != "README.md")
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string lessonPath(const LessonFolders& folders, const std::string& id) {
  const fs::path path = fs::path(folders.lessons) / (id + ".md");
  if (fs::is_regular_file(path)) return path.string();
  std::string known;
  for (const auto& f : lessonFiles(folders.lessons))
    known += (known.empty() ? "" : ", ") + fs::path(f).stem().string();
  throw InputError({folders.lessons}, "no lesson '" + id + "' (known: " + known + ")");
}

std::vector<Lesson> loadCatalogue(const LessonFolders& folders) {
  std::vector<Lesson> lessons;
  for (const auto& file : lessonFiles(folders.lessons)) lessons.push_back(loadLesson(file, folders.scenes));
  std::stable_sort(lessons.begin(), lessons.end(), [](const Lesson& a, const Lesson& b) {
    return a.order != b.order ? a.order < b.order : a.id < b.id;
  });
  return lessons;
}

void checkAgainstScenes(const Lesson& lesson, const std::string& scenesDir) {
  std::map<std::string, Scene> scenes;
  for (const auto& step : lesson.steps) {
    if (step.scene.empty()) continue;
    auto it = scenes.find(step.scene);
    if (it == scenes.end()) {
      try {
        it = scenes.emplace(step.scene, loadScene((fs::path(scenesDir) / step.scene).string())).first;
      } catch (const InputError& e) {
        throw InputError({lesson.file, lineOf(step, "scene")},
                         "scene '" + step.scene + "' does not load: " + e.what());
      }
    }
    const Scene& scene = it->second;
    std::vector<std::string> surfaces;
    for (const auto& s : scene.surfaces) surfaces.push_back(s.name);
    auto known = [&](const std::string& name) {
      return std::find(surfaces.begin(), surfaces.end(), name) != surfaces.end();
    };
    auto list = [&] {
      std::string out;
      for (const auto& s : surfaces) out += (out.empty() ? "" : ", ") + s;
      return out;
    };
    // Camera names: unknown ones are errors at the key's line, listing the scene's cameras.
    if (!step.camera.name.empty())
      namedCamera(scene, step.camera.name, {lesson.file, lineOf(step, "camera")});
    for (const auto& name : step.camera.path)
      namedCamera(scene, name, {lesson.file, lineOf(step, "camera-path")});
    for (const auto& [surface, rho] : step.parameters.reflectance) {
      if (!known(surface))
        throw InputError(
            {lesson.file, lineOf(step, "reflectance." + surface)},
            "scene '" + step.scene + "' has no surface '" + surface + "' (it has: " + list() + ")");
    }
    auto checkTarget = [&](const std::string& target, const std::string& key) {
      if (isNumber(target)) {
        if ((target.size() > 9 ? ~0ul : std::stoul(target)) >= scene.patches.size() &&
            !step.parameters.subdivide && !step.parameters.maxEdge)
          throw InputError({lesson.file, lineOf(step, key)},
                           "element " + target + " does not exist: scene '" + step.scene + "' has " +
                               std::to_string(scene.patches.size()) + " patches");
      } else if (!known(target)) {
        throw InputError({lesson.file, lineOf(step, key)}, "scene '" + step.scene + "' has no surface '" +
                                                               target + "' (it has: " + list() + ")");
      }
    };
    for (const auto& h : step.highlights) checkTarget(h, "highlight");
    if (!step.parameters.from.empty()) checkTarget(step.parameters.from, "from");
  }
}

}  // namespace rt::lesson
