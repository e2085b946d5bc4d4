#pragma once
// Practice (docs/practice.md): a seeded generator per topic makes a fresh instance (a scene, a
// ray, data) as a lesson of its own, and every answer of it is read from that lesson's recorded
// trace or computed by raystep's kernels, through the lesson engine that checks the built-in
// lessons. The same topic, seed and level give the same instance on every machine.
#include "course/exercise.h"
#include "course/lesson.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

enum class PracticeLevel { Easy, Medium, Hard };
std::string_view practiceLevelName(PracticeLevel l);  // "easy", "medium", "hard"
std::optional<PracticeLevel> parsePracticeLevel(std::string_view name);
/// The level's name for people ("facile"), in `lang`.
std::string practiceLevelLabel(PracticeLevel l, Language lang);

struct PracticeTopic {
    std::string name;  // "dda-2d"
    LocalText title;   // "The 2D DDA: tDelta, tMax and the walk"
    LocalText about;   // one line: what each level adds
};
/// Every topic, in the lecture's order.
const std::vector<PracticeTopic>& practiceTopics();
const PracticeTopic* findPracticeTopic(std::string_view name);
/// "dda-2d, dda-3d, ...", for messages.
std::string practiceTopicList();

/// One generated instance.
struct PracticeInstance {
    std::string topic;
    std::uint64_t seed = 0;
    PracticeLevel level = PracticeLevel::Easy;
    nlohmann::ordered_json given;    // the data the prompts state (docs/practice.md, per topic)
    nlohmann::ordered_json answers;  // read from the lesson's trace or raystep's kernels
    std::string lessonText;          // the lesson file (inline scene), as `-o` writes it
    Lesson lesson;                   // the same, loaded
    std::vector<Answer> key;         // each exercise's reference answer, in the lesson's order
    /// {"format": "raystep-practice", "version": 1, "topic", "seed", "level", "given",
    /// "answers", "exercises": [{"id", "type", "answer"}]}: `practice make --json`.
    nlohmann::ordered_json toJson() const;
};

/// A practice that cannot be made: an unknown topic (the message lists the topics).
class PracticeError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The instance of `topic` for `seed` at `level`. Every instance passes `lesson validate`
/// (trace positions, answers read from the trace, no answer in a text the student reads first).
PracticeInstance makePractice(std::string_view topic, std::uint64_t seed, PracticeLevel level);

/// A short fingerprint of an instance's data (16 hex digits of FNV-1a over `given`): two seeds
/// that draw the same instance have the same digest.
std::string practiceDigest(const PracticeInstance& instance);

/// A new instance of `topic` at `level` for a student: seeds from `draw` until one gives an
/// instance `seen` (its seed, its digest) refuses; PracticeError after 1000 draws, which only
/// a topic whose every instance the student was given comes to.
PracticeInstance drawPractice(std::string_view topic, PracticeLevel level,
                              const std::function<std::uint64_t()>& draw,
                              const std::function<bool(std::uint64_t, const std::string&)>& seen);

/// The lesson id a practice instance has ("practice-dda-2d-easy-42"), and back: the topic,
/// level and seed of a practice lesson id, nullopt for any other id.
std::string practiceLessonId(std::string_view topic, PracticeLevel level, std::uint64_t seed);
struct PracticeKey {
    std::string topic;
    PracticeLevel level = PracticeLevel::Easy;
    std::uint64_t seed = 0;
};
std::optional<PracticeKey> parsePracticeLessonId(std::string_view id);

}  // namespace raystep
