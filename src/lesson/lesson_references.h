// References from one lesson to another. The text names a lesson by its id, never by its number:
// "@lesson:form-factor" becomes "[lesson 6](form-factor.html#top)" and "@Lesson:form-factor" (at the start
// of a sentence) "[Lesson 6](...)". The number is the other lesson's `order`, so adding a chapter renumbers
// every reference to the ones after it, in the app, the HTML book and the PDF alike.
#pragma once

#include <map>
#include <string>

namespace rt::lesson {

// The chapter number (`order`) of every lesson in a folder, by id. A lesson that does not parse is left out
// (it is reported where it is loaded); an empty folder gives an empty map.
using LessonNumbers = std::map<std::string, int>;
LessonNumbers lessonNumbers(const std::string& lessonsDir);

// The text with its lesson references resolved ("lesson 6", or `word` and its number: the book says
// "chapter 6"); an InputError at the reference's line when it names no lesson (listing the known ids).
std::string prepareLessonReferences(const std::string& markdown, int firstLine, const std::string& file,
                                    const LessonNumbers& numbers, const std::string& word = "lesson");

}  // namespace rt::lesson
