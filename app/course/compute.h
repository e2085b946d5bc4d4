#pragma once
// Compute exercises (docs/lesson-format.md, "compute"): a hand computation from data the prompt
// gives. The right answer comes from raystep's own kernels (geometry/intersect.h with its
// StepLog, the grid's Dda set-up, accel/sah.h), never from the lesson file; the feedback shows
// the formula with the given numbers and names the slip a student's number betrays.
#include "course/lesson.h"

#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// The right answer; throws LessonError naming the exercise's line when the data leave the
/// quantity undefined (the ray misses the sphere, is parallel to the plane, ...).
double computeAnswer(const Exercise& ex, const std::string& lessonFile);
/// How the answer is computed: the formula with the given numbers substituted, in `lang`.
std::string computeWorking(const Exercise& ex, Language lang);
/// The slip `given` betrays (the other root, a flipped sign, a missing abs, ...), in `lang`; empty
/// when the number is right or no known slip gives it.
std::string computeSlip(const Exercise& ex, double given, Language lang);

/// The numbers of `numbers` that `text` does not write (as "0.5", "-2", or in Italian "0,5").
std::vector<double> numbersNotInText(const std::vector<double>& numbers, std::string_view text,
                                     Language lang);
/// Every number written in `text` (Italian: the comma is the decimal mark).
std::vector<double> numbersInText(std::string_view text, Language lang);

}  // namespace raystep
