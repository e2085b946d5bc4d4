// A student's progress file: read (every error names file, line and key), written, folded
// together with what another window saved, and summed up as a report for the course.
#include "course/progress.h"

#include "raystep/base/json_reader.h"

#include "course/practice/practice.h"

#include <algorithm>
#include <sstream>

namespace raystep {

using detail::ifPresent;
using detail::json;
using Reader = detail::JsonReader<LessonError>;

namespace {
Progress readProgress(std::string_view text, const std::string& fileName) {
    auto parsed = detail::parseJsonFile<LessonError>(text, fileName);
    const json& root = parsed.root;
    const Reader r(fileName, std::move(parsed.lines));
    r.requireObject(root, "");
    r.checkKeys(root, "", {"format", "version", "lessons", "practice"});
    if (root.value("format", json()) != "raystep-progress")
        r.fail("format", "not a raystep progress file");
    Progress p;
    ifPresent(root, "", "lessons", [&](const json& v, const std::string& path) {
        r.requireObject(v, path);
        for (const auto& [id, lj] : v.items()) {
            const std::string lp = JsonLineMap::child(path, id);
            r.requireObject(lj, lp);
            r.checkKeys(lj, lp, {"step", "exercises"});
            LessonProgress& lesson = p.lessons[id];
            ifPresent(lj, lp, "step", [&](const json& s, const std::string& sp) {
                lesson.step = r.integer(s, sp, 0, 10'000);
            });
            ifPresent(lj, lp, "exercises", [&](const json& ej, const std::string& ep) {
                r.requireObject(ej, ep);
                for (const auto& [eid, rec] : ej.items()) {
                    const std::string rp = JsonLineMap::child(ep, eid);
                    r.requireObject(rec, rp);
                    r.checkKeys(rec, rp, {"correct", "attempts", "answer"});
                    LessonProgress::ExerciseRecord& e = lesson.exercises[eid];
                    ifPresent(rec, rp, "correct", [&](const json& x, const std::string& xp) {
                        if (!x.is_boolean()) r.fail(xp, "expected true or false");
                        e.correct = x.get<bool>();
                    });
                    ifPresent(rec, rp, "attempts", [&](const json& x, const std::string& xp) {
                        e.attempts = r.integer(x, xp, 0, 1'000'000);
                    });
                    ifPresent(rec, rp, "answer", [&](const json& x, const std::string& xp) {
                        e.answer = r.string(x, xp);
                    });
                }
            });
        }
    });
    ifPresent(root, "", "practice", [&](const json& v, const std::string& path) {
        r.requireObject(v, path);
        for (const auto& [key, rj] : v.items()) {
            const std::string kp = JsonLineMap::child(path, key);
            if (!rj.is_array()) r.fail(kp, "expected an array of instances [...]");
            PracticeRecord& rec = p.practice[key];
            for (std::size_t i = 0; i < rj.size(); ++i) {
                const std::string ip = JsonLineMap::element(kp, i);
                r.requireObject(rj[i], ip);
                r.checkKeys(rj[i], ip, {"seed", "result", "digest"});
                PracticeRecord::Instance in;
                ifPresent(rj[i], ip, "seed", [&](const json& x, const std::string& xp) {
                    if (!x.is_number_unsigned()) r.fail(xp, "expected a whole number from 0");
                    in.seed = x.get<std::uint64_t>();
                });
                ifPresent(rj[i], ip, "result", [&](const json& x, const std::string& xp) {
                    const std::string res = r.string(x, xp);
                    if (res == "right")
                        in.result = PracticeRecord::Result::Right;
                    else if (res == "missed")
                        in.result = PracticeRecord::Result::Missed;
                    else if (res == "open")
                        in.result = PracticeRecord::Result::Open;
                    else
                        r.fail(xp, "expected \"right\", \"missed\" or \"open\"");
                });
                ifPresent(rj[i], ip, "digest", [&](const json& x, const std::string& xp) {
                    in.digest = r.string(x, xp);
                });
                rec.instances.push_back(in);
            }
        }
    });
    return p;
}

const char* resultName(PracticeRecord::Result r) {
    switch (r) {
        case PracticeRecord::Result::Right:
            return "right";
        case PracticeRecord::Result::Missed:
            return "missed";
        case PracticeRecord::Result::Open:
            break;
    }
    return "open";
}
}  // namespace

int PracticeRecord::streak() const {
    int n = 0;
    for (auto it = instances.rbegin(); it != instances.rend(); ++it) {
        if (it->result == Result::Missed) break;
        n += it->result == Result::Right;
    }
    return n;
}

bool PracticeRecord::mastered() const {
    int run = 0;
    for (const Instance& in : instances) {
        if (in.result == Result::Missed) run = 0;
        if (in.result == Result::Right && ++run >= kMasteryStreak) return true;
    }
    return false;
}

int PracticeRecord::right() const {
    return static_cast<int>(
        std::count_if(instances.begin(), instances.end(),
                      [](const Instance& i) { return i.result == Result::Right; }));
}

bool PracticeRecord::drawn(std::uint64_t seed) const {
    return std::any_of(instances.begin(), instances.end(),
                       [&](const Instance& i) { return i.seed == seed; });
}

bool PracticeRecord::given(std::string_view digest) const {
    return !digest.empty() && std::any_of(instances.begin(), instances.end(),
                                          [&](const Instance& i) { return i.digest == digest; });
}

std::string practiceKey(std::string_view topic, std::string_view level) {
    return std::string(topic) + "/" + std::string(level);
}

PracticeRecord::Result practiceResult(const Lesson& lesson, const LessonProgress& progress) {
    bool all = !lesson.exercises.empty();
    for (const Exercise& ex : lesson.exercises) {
        const auto e = progress.exercises.find(ex.id);
        if (e == progress.exercises.end() || e->second.attempts == 0) {
            all = false;
            continue;
        }
        // A first answer that was wrong: the record keeps counting until it is right.
        if (!e->second.correct || e->second.attempts > 1) return PracticeRecord::Result::Missed;
    }
    return all ? PracticeRecord::Result::Right : PracticeRecord::Result::Open;
}

void recordPractice(PracticeRecord& record, std::uint64_t seed, PracticeRecord::Result result,
                    const std::string& digest) {
    for (PracticeRecord::Instance& in : record.instances)
        if (in.seed == seed) {
            if (in.result == PracticeRecord::Result::Open) in.result = result;
            if (in.digest.empty()) in.digest = digest;
            return;
        }
    record.instances.push_back({seed, result, digest});
}

Progress parseProgress(std::string_view text, const std::string& fileName) {
    return detail::guarded<LessonError>(fileName, [&] { return readProgress(text, fileName); });
}

std::optional<Progress> loadProgressFile(const std::string& path) {
    std::string text;
    try {
        text = detail::readRegularFile(path, detail::kMaxJsonFileBytes);
    } catch (const detail::ReadFailure& f) {
        if (f.missing()) return std::nullopt;
        throw LessonError(path, 0, "", std::string("cannot read the progress file: ") + f.what());
    }
    return parseProgress(text, path);
}

std::string progressToJson(const Progress& p) {
    json lessons = json::object();
    for (const auto& [id, l] : p.lessons) {
        json ex = json::object();
        for (const auto& [eid, e] : l.exercises)
            ex[eid] = {{"correct", e.correct}, {"attempts", e.attempts}, {"answer", e.answer}};
        lessons[id] = {{"step", l.step}, {"exercises", ex}};
    }
    json root = {{"format", "raystep-progress"}, {"version", 1}, {"lessons", lessons}};
    if (!p.practice.empty()) {
        json practice = json::object();
        for (const auto& [key, rec] : p.practice) {
            json list = json::array();
            for (const PracticeRecord::Instance& in : rec.instances) {
                json entry = {{"seed", in.seed}, {"result", resultName(in.result)}};
                if (!in.digest.empty()) entry["digest"] = in.digest;
                list.push_back(entry);
            }
            practice[key] = list;
        }
        root["practice"] = practice;
    }
    return root.dump(2) + "\n";
}

void mergeProgress(Progress& into, const Progress& saved) {
    for (const auto& [id, theirs] : saved.lessons) {
        const auto [it, added] = into.lessons.try_emplace(id, theirs);
        if (added) continue;
        for (const auto& [ex, rec] : theirs.exercises) {
            const auto [mine, fresh] = it->second.exercises.try_emplace(ex, rec);
            if (fresh) continue;
            if (rec.attempts > mine->second.attempts) {
                mine->second.attempts = rec.attempts;
                mine->second.answer = rec.answer;
            }
            mine->second.correct = mine->second.correct || rec.correct;
        }
    }
    for (const auto& [key, theirs] : saved.practice) {
        PracticeRecord& mine = into.practice[key];
        for (const PracticeRecord::Instance& in : theirs.instances)
            recordPractice(mine, in.seed, in.result, in.digest);
    }
}

bool recordAnswer(LessonProgress& lesson, const std::string& exerciseId, const std::string& answer,
                  bool correct) {
    LessonProgress::ExerciseRecord& rec = lesson.exercises[exerciseId];
    if (rec.correct) return true;
    ++rec.attempts;
    rec.correct = correct;
    rec.answer = answer;
    return false;
}

namespace {
/// A student's text inside a Markdown table cell: one line, no cell break.
std::string markdownCell(const std::string& text) {
    std::string out;
    for (const char c : printable(text, 80)) {
        if (c == '|' || c == '*' || c == '_' || c == '`' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}
}  // namespace

std::string progressReport(const Progress& p, const std::vector<Lesson>& lessons, Language lang,
                           const ReportHeader& header) {
    std::ostringstream s;
    s << "# " << tr(lang, "raystep: progress") << "\n\n";
    if (!header.student.empty())
        s << trf(lang, "Student: %1", {markdownCell(header.student)}) << "  \n";
    if (!header.date.empty()) s << trf(lang, "Date: %1", {markdownCell(header.date)}) << "\n";
    if (!header.student.empty() || !header.date.empty()) s << "\n";
    s << "| " << tr(lang, "Lesson") << " | " << tr(lang, "Exercises") << " | " << tr(lang, "Done")
      << " | " << tr(lang, "Right") << " | " << tr(lang, "Attempts") << " |\n";
    s << "|---|---:|---:|---:|---:|\n";
    int total = 0, done = 0, right = 0;
    for (const Lesson& l : lessons) {
        int d = 0, r = 0, attempts = 0;
        if (const auto lp = p.lessons.find(l.id); lp != p.lessons.end())
            for (const Exercise& ex : l.exercises)
                if (const auto e = lp->second.exercises.find(ex.id);
                    e != lp->second.exercises.end()) {
                    d += e->second.attempts > 0;
                    r += e->second.correct;
                    attempts += e->second.attempts;
                }
        total += static_cast<int>(l.exercises.size());
        done += d;
        right += r;
        s << "| " << l.number << ". " << l.title.in(lang) << " | " << l.exercises.size() << " | "
          << d << " | " << r << " | " << attempts << " |\n";
    }
    s << "\n"
      << trf(lang, "Total: %1 / %2 exercises right, %3 attempted.",
             {std::to_string(right), std::to_string(total), std::to_string(done)})
      << "\n";
    // Per exercise, for the lessons worked on: the lecturer sees where each student stopped.
    for (const Lesson& l : lessons) {
        const auto lp = p.lessons.find(l.id);
        if (lp == p.lessons.end() || lp->second.exercises.empty()) continue;
        s << "\n## " << l.number << ". " << l.title.in(lang) << "\n\n";
        s << "| " << tr(lang, "Exercise") << " | " << tr(lang, "Result") << " | "
          << tr(lang, "Attempts") << " | " << tr(lang, "Last answer") << " |\n";
        s << "|---|---|---:|---|\n";
        for (std::size_t i = 0; i < l.exercises.size(); ++i) {
            const Exercise& ex = l.exercises[i];
            const auto e = lp->second.exercises.find(ex.id);
            const bool tried = e != lp->second.exercises.end() && e->second.attempts > 0;
            const std::string result = !tried              ? tr(lang, "not attempted")
                                       : e->second.correct ? tr(lang, "solved")
                                                           : tr(lang, "not solved yet");
            s << "| " << i + 1 << ". " << ex.id << " | " << result << " | "
              << (tried ? std::to_string(e->second.attempts) : "") << " | "
              << (tried ? markdownCell(e->second.answer) : "") << " |\n";
        }
    }
    // Practice (docs/practice.md): per topic and level worked on, in the lecture's order.
    bool any = false;
    for (const PracticeTopic& topic : practiceTopics())
        for (const PracticeLevel level :
             {PracticeLevel::Easy, PracticeLevel::Medium, PracticeLevel::Hard}) {
            const auto it = p.practice.find(practiceKey(topic.name, practiceLevelName(level)));
            if (it == p.practice.end() || it->second.instances.empty()) continue;
            if (!any) {
                s << "\n## " << tr(lang, "Practice") << "\n\n| " << tr(lang, "Topic") << " | "
                  << tr(lang, "Level") << " | " << tr(lang, "Instances") << " | "
                  << tr(lang, "Right") << " | " << tr(lang, "Right in a row") << " | "
                  << tr(lang, "Mastered") << " |\n|---|---|---:|---:|---:|---|\n";
                any = true;
            }
            const PracticeRecord& rec = it->second;
            s << "| " << topic.title.in(lang) << " | " << practiceLevelLabel(level, lang) << " | "
              << rec.instances.size() << " | " << rec.right() << " | " << rec.streak() << " | "
              << (rec.mastered() ? tr(lang, "yes") : tr(lang, "not yet")) << " |\n";
        }
    if (any)
        s << "\n"
          << trf(lang,
                 "A topic is mastered at a level by %1 instances in a row, each right at "
                 "every first answer.",
                 {std::to_string(kMasteryStreak)})
          << "\n";
    return s.str();
}

}  // namespace raystep
