#pragma once
// What a topic's generator writes (practice/<topic>.cpp) and the helpers they share: the
// seeded random numbers, numbers as a student writes them, and the lesson file's JSON.
#include "course/exercise.h"
#include "course/lesson_trace.h"
#include "course/practice/practice.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace raystep::practice {

using ojson = nlohmann::ordered_json;

/// splitmix64 (Steele, Lea and Flood 2014) and bounded draws by rejection: the standard
/// library's distributions differ between implementations, and an instance must not.
class Random {
  public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    /// A whole number in [lo, hi], each equally likely.
    int between(int lo, int hi);
    bool chance(int percent) { return between(1, 100) <= percent; }
    int sign() { return chance(50) ? 1 : -1; }
    template <typename T>
    const T& pick(const std::vector<T>& from) {
        return from[static_cast<std::size_t>(between(0, static_cast<int>(from.size()) - 1))];
    }

  private:
    std::uint64_t state_;
};

/// The answers of a generated lesson, by exercise id, as the engine reads them.
struct Reference {
    const Lesson& lesson;
    const LessonRun& run;
    std::map<std::string, Answer, std::less<>> byId;

    double number(std::string_view id) const;
    std::vector<int> cell(std::string_view id) const;                // next_cell
    std::vector<std::vector<int>> cells(std::string_view id) const;  // sequence of cells
    std::vector<int> nodes(std::string_view id) const;               // sequence of nodes
    int choice(std::string_view id) const;                           // 0-based option
    const EventLog& log() const { return *run.log; }
};

/// What a generator makes: the lesson (every key but format, version, id and number), the data
/// the prompts state, and how the answers are read off the reference. `accept` may refuse an
/// instance the trace shows is not one for its level (a ray that hits a corner marker, a walk
/// too long to do by hand); the driver then draws again from the same stream.
struct Draft {
    ojson lesson;
    ojson given;
    std::function<ojson(const Reference&)> answers;
    std::function<bool(const Reference&)> accept;
};

struct Generator {
    PracticeTopic topic;
    Draft (*make)(Random& random, PracticeLevel level);
};
/// Every generator, in the lecture's order (registry.cpp).
const std::vector<Generator>& generators();

// The topics' makers (one file each).
Draft makeDda2D(Random& random, PracticeLevel level);
Draft makeDda3D(Random& random, PracticeLevel level);
Draft makeMailbox(Random& random, PracticeLevel level);
Draft makeKdTree(Random& random, PracticeLevel level);
Draft makeBvh(Random& random, PracticeLevel level);
Draft makeRaySphere(Random& random, PracticeLevel level);
Draft makeRayTriangle(Random& random, PracticeLevel level);
Draft makePhong(Random& random, PracticeLevel level);
Draft makeRayTree(Random& random, PracticeLevel level);

// Writing the lesson.

/// A number as a student writes it: the shortest decimal that reads back to it ("0.5", "-2",
/// "1.25"); with `comma` the Italian decimal mark.
std::string num(double v, bool comma = false);
/// "(0.5, -2)": a vector, always with points (inside a code span in both languages).
std::string vec(const std::vector<double>& v);
ojson jsonVec(const std::vector<double>& v);
/// {"en": .., "it": ..}
ojson text(const std::string& en, const std::string& it);
/// An exercise with its id, type and prompt; the caller adds its own keys.
ojson exercise(const std::string& id, const std::string& type, const ojson& prompt);
/// A compute exercise: `quantity` of the data `given` (course/compute.h), asked by `prompt`.
ojson computeExercise(const std::string& id, const std::string& quantity, const ojson& given,
                      const ojson& prompt);
/// A hint list: each {"en", "it"}.
ojson hints(std::initializer_list<ojson> items);

}  // namespace raystep::practice
