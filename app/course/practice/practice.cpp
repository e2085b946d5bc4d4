// The practice driver: draws an instance from its topic's generator, reads it as a lesson,
// validates it as `lesson validate` does, and reads the answers off the engine.
#include "course/practice/generator.h"

#include "course/grading.h"
#include "raystep/base/i18n.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace raystep {

using practice::ojson;

std::string_view practiceLevelName(PracticeLevel l) {
    switch (l) {
        case PracticeLevel::Easy:
            return "easy";
        case PracticeLevel::Medium:
            return "medium";
        case PracticeLevel::Hard:
            return "hard";
    }
    return "easy";
}

std::string practiceLevelLabel(PracticeLevel l, Language lang) {
    switch (l) {
        case PracticeLevel::Easy:
            return tr(lang, "easy");
        case PracticeLevel::Medium:
            return tr(lang, "medium");
        case PracticeLevel::Hard:
            return tr(lang, "hard");
    }
    return tr(lang, "easy");
}

std::optional<PracticeLevel> parsePracticeLevel(std::string_view name) {
    for (PracticeLevel l : {PracticeLevel::Easy, PracticeLevel::Medium, PracticeLevel::Hard})
        if (practiceLevelName(l) == name) return l;
    return std::nullopt;
}

const std::vector<PracticeTopic>& practiceTopics() {
    static const std::vector<PracticeTopic> topics = [] {
        std::vector<PracticeTopic> out;
        for (const practice::Generator& g : practice::generators()) out.push_back(g.topic);
        return out;
    }();
    return topics;
}

const PracticeTopic* findPracticeTopic(std::string_view name) {
    for (const PracticeTopic& t : practiceTopics())
        if (t.name == name) return &t;
    return nullptr;
}

std::string practiceTopicList() {
    std::string out;
    for (const PracticeTopic& t : practiceTopics()) out += (out.empty() ? "" : ", ") + t.name;
    return out;
}

std::string practiceLessonId(std::string_view topic, PracticeLevel level, std::uint64_t seed) {
    return "practice-" + std::string(topic) + "-" + std::string(practiceLevelName(level)) + "-" +
           std::to_string(seed);
}

std::optional<PracticeKey> parsePracticeLessonId(std::string_view id) {
    constexpr std::string_view lead = "practice-";
    if (id.substr(0, lead.size()) != lead) return std::nullopt;
    id.remove_prefix(lead.size());
    const auto lastDash = id.rfind('-');
    if (lastDash == std::string_view::npos) return std::nullopt;
    PracticeKey k;
    const std::string_view seedText = id.substr(lastDash + 1);
    const auto [end, ec] =
        std::from_chars(seedText.data(), seedText.data() + seedText.size(), k.seed);
    if (ec != std::errc() || end != seedText.data() + seedText.size() || seedText.empty())
        return std::nullopt;
    id = id.substr(0, lastDash);
    const auto levelDash = id.rfind('-');
    if (levelDash == std::string_view::npos) return std::nullopt;
    const auto level = parsePracticeLevel(id.substr(levelDash + 1));
    if (!level || !findPracticeTopic(id.substr(0, levelDash))) return std::nullopt;
    k.level = *level;
    k.topic = std::string(id.substr(0, levelDash));
    return k;
}

ojson PracticeInstance::toJson() const {
    ojson out;
    out["format"] = "raystep-practice";
    out["version"] = 1;
    out["topic"] = topic;
    out["seed"] = seed;
    out["level"] = std::string(practiceLevelName(level));
    out["given"] = given;
    out["answers"] = answers;
    ojson list = ojson::array();
    for (std::size_t i = 0; i < lesson.exercises.size(); ++i) {
        const Exercise& ex = lesson.exercises[i];
        list.push_back({{"id", ex.id},
                        {"type", std::string(exerciseKindName(ex.kind))},
                        {"answer", formatAnswer(ex, key[i], Language::En)}});
    }
    out["exercises"] = list;
    return out;
}

namespace {

/// The seed, the topic and the level into one stream: two topics with one seed differ.
std::uint64_t streamSeed(std::string_view topic, PracticeLevel level, std::uint64_t seed) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the topic and level
    for (const char c : std::string(topic) + "/" + std::string(practiceLevelName(level))) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    return h ^ (seed * 0x9e3779b97f4a7c15ull);
}

// Draws that the level or validation refuse before the generator is called a bug.
constexpr int kAttempts = 400;

}  // namespace

std::string practiceDigest(const PracticeInstance& instance) {
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : instance.given.dump()) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

PracticeInstance drawPractice(std::string_view topic, PracticeLevel level,
                              const std::function<std::uint64_t()>& draw,
                              const std::function<bool(std::uint64_t, const std::string&)>& seen) {
    for (int tries = 0; tries < 1000; ++tries) {
        const std::uint64_t seed = draw();
        if (seen(seed, {})) continue;  // the seed alone: no need to make it
        PracticeInstance inst = makePractice(topic, seed, level);
        if (!seen(seed, practiceDigest(inst))) return inst;
    }
    throw PracticeError("no new instance of " + printable(topic) + " at " +
                        std::string(practiceLevelName(level)) + " in 1000 draws");
}

PracticeInstance makePractice(std::string_view topic, std::uint64_t seed, PracticeLevel level) {
    const auto& gens = practice::generators();
    const auto g = std::find_if(gens.begin(), gens.end(), [&](const practice::Generator& x) {
        return x.topic.name == topic;
    });
    if (g == gens.end())
        throw PracticeError("unknown practice topic '" + printable(topic) + "' (expected one of " +
                            practiceTopicList() + ")");
    practice::Random random(streamSeed(topic, level, seed));
    const std::string id = practiceLessonId(topic, level, seed);
    const std::string fileName = id + ".json";
    std::string lastRefusal;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        practice::Draft d = g->make(random, level);
        ojson file;
        file["format"] = "raystep-lesson";
        file["version"] = 1;
        file["id"] = id;
        file["number"] = 900 + static_cast<int>(g - gens.begin());
        for (auto& [key, value] : d.lesson.items()) file[key] = value;
        std::string text = file.dump(2) + "\n";
        Lesson lesson = loadLessonText(text, fileName);
        try {
            // A draw whose texts happen to write an answer ("2.5" as a given and as tDelta) is
            // drawn again: the instance the student gets passes `lesson validate`.
            validateLesson(lesson);
        } catch (const LessonError& e) {
            lastRefusal = e.what();
            continue;
        }
        const LessonRun run = runLesson(lesson);
        const LessonLogs logs = run.logs();
        practice::Reference ref{lesson, run, {}};
        for (const Exercise& ex : lesson.exercises)
            ref.byId.emplace(ex.id, referenceAnswer(ex, logs.of(ex.setup), lesson.file));
        if (d.accept && !d.accept(ref)) {
            lastRefusal = "refused by the level's rules";
            continue;
        }
        PracticeInstance out;
        out.topic = std::string(topic);
        out.seed = seed;
        out.level = level;
        out.given = std::move(d.given);
        out.answers = d.answers(ref);
        for (const Exercise& ex : lesson.exercises) out.key.push_back(ref.byId.at(ex.id));
        out.lessonText = std::move(text);
        out.lesson = std::move(lesson);
        return out;
    }
    throw std::logic_error("practice " + id + ": no valid instance in " +
                           std::to_string(kAttempts) + " draws; the last: " + lastRefusal);
}

namespace practice {

std::uint64_t Random::next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

int Random::between(int lo, int hi) {
    const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;  // rejection: no modulo bias
    std::uint64_t x = next();
    while (x >= limit) x = next();
    return lo + static_cast<int>(x % span);
}

namespace {
const Answer& answerOf(const Reference& r, std::string_view id) {
    const auto it = r.byId.find(id);
    if (it == r.byId.end()) throw std::logic_error("practice: no exercise " + std::string(id));
    return it->second;
}
}  // namespace

double Reference::number(std::string_view id) const {
    return answerOf(*this, id).numbers.at(0);
}

std::vector<int> Reference::cell(std::string_view id) const {
    std::vector<int> out;
    for (double v : answerOf(*this, id).numbers) out.push_back(static_cast<int>(v));
    return out;
}

std::vector<std::vector<int>> Reference::cells(std::string_view id) const {
    const Answer& a = answerOf(*this, id);
    std::vector<std::vector<int>> out;
    const auto per = static_cast<std::size_t>(std::max(1, a.perItem));
    for (std::size_t i = 0; i + per <= a.numbers.size(); i += per) {
        std::vector<int> c;
        for (std::size_t k = 0; k < per; ++k) c.push_back(static_cast<int>(a.numbers[i + k]));
        out.push_back(c);
    }
    return out;
}

std::vector<int> Reference::nodes(std::string_view id) const {
    return cell(id);
}

int Reference::choice(std::string_view id) const {
    return static_cast<int>(answerOf(*this, id).numbers.at(0));
}

ojson computeExercise(const std::string& id, const std::string& quantity, const ojson& given,
                      const ojson& prompt) {
    ojson e = exercise(id, "compute", prompt);
    e["given"] = given;
    e["quantity"] = quantity;
    return e;
}

std::string num(double v, bool comma) {
    std::string s;
    // The shortest that reads back, without an exponent ("10", not "1e+01") unless it needs one.
    for (int digits = 1; digits <= 17; ++digits) {
        s = formatNumber(v, digits);
        if (std::stod(s) == v && s.find('e') == std::string::npos) break;
    }
    if (s.find('e') != std::string::npos)
        for (int digits = 1; digits <= 17; ++digits) {
            s = formatNumber(v, digits);
            if (std::stod(s) == v) break;
        }
    if (s == "-0") s = "0";
    if (comma) std::replace(s.begin(), s.end(), '.', ',');
    return s;
}

std::string vec(const std::vector<double>& v) {
    std::string out = "(";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + num(v[i]);
    return out + ")";
}

ojson jsonVec(const std::vector<double>& v) {
    ojson out = ojson::array();
    for (double x : v) out.push_back(x);
    return out;
}

ojson text(const std::string& en, const std::string& it) {
    return {{"en", en}, {"it", it}};
}

ojson exercise(const std::string& id, const std::string& type, const ojson& prompt) {
    ojson e;
    e["id"] = id;
    e["type"] = type;
    e["prompt"] = prompt;
    return e;
}

ojson hints(std::initializer_list<ojson> items) {
    ojson out = ojson::array();
    for (const ojson& h : items) out.push_back(h);
    return out;
}

}  // namespace practice
}  // namespace raystep
