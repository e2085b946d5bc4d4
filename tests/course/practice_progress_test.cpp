// A student's practice in the progress file: what an instance's answers make of it, the streak
// and mastery, the file's "practice" key read, written, folded and reported.
#include "course/practice/practice.h"
#include "course/progress.h"

#include <gtest/gtest.h>

#include <string>

using namespace raystep;
using Result = PracticeRecord::Result;

namespace {
LessonProgress answers(std::initializer_list<std::tuple<const char*, bool, int>> records) {
    LessonProgress p;
    for (const auto& [id, correct, attempts] : records) p.exercises[id] = {correct, attempts, "x"};
    return p;
}
PracticeRecord record(std::initializer_list<Result> results) {
    PracticeRecord r;
    std::uint64_t seed = 100;
    for (const Result res : results) r.instances.push_back({seed++, res});
    return r;
}
}  // namespace

TEST(PracticeProgress, AnInstanceIsRightOnlyWhenEveryFirstAnswerIs) {
    const PracticeInstance inst = makePractice("ray-sphere", 5, PracticeLevel::Easy);
    ASSERT_GE(inst.lesson.exercises.size(), 2u);
    LessonProgress p;
    EXPECT_EQ(practiceResult(inst.lesson, p), Result::Open);
    // All but the last answered right at once: still open.
    for (std::size_t i = 0; i + 1 < inst.lesson.exercises.size(); ++i)
        p.exercises[inst.lesson.exercises[i].id] = {true, 1, "x"};
    EXPECT_EQ(practiceResult(inst.lesson, p), Result::Open);
    p.exercises[inst.lesson.exercises.back().id] = {true, 1, "x"};
    EXPECT_EQ(practiceResult(inst.lesson, p), Result::Right);
    // Right at the second answer, or a wrong one not yet mended: missed.
    p.exercises[inst.lesson.exercises.back().id] = {true, 2, "x"};
    EXPECT_EQ(practiceResult(inst.lesson, p), Result::Missed);
    p.exercises[inst.lesson.exercises.back().id] = {false, 1, "x"};
    EXPECT_EQ(practiceResult(inst.lesson, p), Result::Missed);
    // An exercise id the lesson does not have changes nothing.
    LessonProgress other = answers({{"not-an-exercise", false, 3}});
    EXPECT_EQ(practiceResult(inst.lesson, other), Result::Open);
}

TEST(PracticeProgress, StreakAndMasteryCountRightsInARow) {
    EXPECT_EQ(record({}).streak(), 0);
    EXPECT_FALSE(record({}).mastered());
    EXPECT_EQ(record({Result::Right, Result::Right}).streak(), 2);
    EXPECT_FALSE(record({Result::Right, Result::Right}).mastered());
    // An instance left open neither counts nor breaks the run; a miss breaks it.
    EXPECT_EQ(record({Result::Right, Result::Open, Result::Right}).streak(), 2);
    EXPECT_EQ(record({Result::Right, Result::Missed, Result::Right}).streak(), 1);
    EXPECT_FALSE(record({Result::Right, Result::Right, Result::Missed, Result::Right}).mastered());
    EXPECT_TRUE(record({Result::Missed, Result::Right, Result::Open, Result::Right, Result::Right})
                    .mastered());
    // Mastery once reached is kept after a later miss; the streak is not.
    const PracticeRecord later =
        record({Result::Right, Result::Right, Result::Right, Result::Missed});
    EXPECT_TRUE(later.mastered());
    EXPECT_EQ(later.streak(), 0);
    EXPECT_EQ(later.right(), 3);
    EXPECT_TRUE(later.drawn(102));
    EXPECT_FALSE(later.drawn(104));
}

TEST(PracticeProgress, ADecidedResultIsNeverChanged) {
    PracticeRecord r;
    recordPractice(r, 7, Result::Open);
    recordPractice(r, 7, Result::Missed);
    recordPractice(r, 7, Result::Right);  // mended later: still a miss
    recordPractice(r, 9, Result::Right);
    recordPractice(r, 9, Result::Open);
    ASSERT_EQ(r.instances.size(), 2u);
    EXPECT_EQ(r.instances[0].result, Result::Missed);
    EXPECT_EQ(r.instances[1].result, Result::Right);
}

TEST(PracticeProgress, TheFileKeepsThePracticeAndReadsItBack) {
    Progress p;
    p.practice[practiceKey("dda-2d", "easy")] =
        record({Result::Right, Result::Missed, Result::Open});
    p.practice["dda-2d/easy"].instances.push_back({9007199254740991ull, Result::Right});
    const std::string text = progressToJson(p);
    const Progress back = parseProgress(text, "progress.json");
    ASSERT_EQ(back.practice.count("dda-2d/easy"), 1u);
    const PracticeRecord& r = back.practice.at("dda-2d/easy");
    ASSERT_EQ(r.instances.size(), 4u);
    EXPECT_EQ(r.instances[1].result, Result::Missed);
    EXPECT_EQ(r.instances[2].result, Result::Open);
    EXPECT_EQ(r.instances[3].seed, 9007199254740991ull);
    EXPECT_EQ(progressToJson(back), text);
    // A file without practice has no "practice" key (as the app wrote before practice).
    EXPECT_EQ(progressToJson(Progress{}).find("practice"), std::string::npos);
}

TEST(PracticeProgress, BadPracticeEntriesNameTheirKey) {
    const auto fails = [](const std::string& practice, const std::string& want) {
        const std::string text =
            "{\"format\": \"raystep-progress\", \"version\": 1,\n"
            "\"practice\": " +
            practice + "}";
        try {
            parseProgress(text, "p.json");
            ADD_FAILURE() << practice << " was accepted";
        } catch (const LessonError& e) {
            EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("p.json"), std::string::npos) << e.what();
        }
    };
    fails("[]", "practice");
    fails("{\"dda-2d/easy\": 3}", "practice.dda-2d/easy");
    fails("{\"dda-2d/easy\": [{\"seed\": -1, \"result\": \"right\"}]}", "seed");
    fails("{\"dda-2d/easy\": [{\"seed\": 1.5, \"result\": \"right\"}]}", "seed");
    fails("{\"dda-2d/easy\": [{\"seed\": 1, \"result\": \"won\"}]}", "result");
    fails("{\"dda-2d/easy\": [{\"seed\": 1, \"mark\": 3}]}", "mark");
}

TEST(PracticeProgress, MergingKeepsBothWindowsInstancesAndDecisions) {
    Progress mine, theirs;
    mine.practice["dda-2d/easy"] = record({Result::Right, Result::Open});  // seeds 100, 101
    theirs.practice["dda-2d/easy"] = record({Result::Right, Result::Missed, Result::Right});
    theirs.practice["ray-sphere/hard"] = record({Result::Right});
    mergeProgress(mine, theirs);
    const PracticeRecord& r = mine.practice.at("dda-2d/easy");
    ASSERT_EQ(r.instances.size(), 3u);
    EXPECT_EQ(r.instances[1].result, Result::Missed);  // decided there, open here
    EXPECT_EQ(r.instances[2].seed, 102u);
    EXPECT_EQ(mine.practice.count("ray-sphere/hard"), 1u);
}

TEST(PracticeProgress, TheReportShowsPracticePerTopicAndLevel) {
    Progress p;
    p.practice["dda-2d/medium"] = record({Result::Right, Result::Right, Result::Right});
    p.practice["ray-sphere/easy"] = record({Result::Missed, Result::Right});
    const std::string en = progressReport(p, {}, Language::En);
    EXPECT_NE(en.find("## Practice"), std::string::npos) << en;
    EXPECT_NE(en.find("| medium | 3 | 3 | 3 | yes |"), std::string::npos) << en;
    EXPECT_NE(en.find("| easy | 2 | 1 | 1 | not yet |"), std::string::npos) << en;
    // The lecture's order: the DDA before ray-sphere.
    EXPECT_LT(en.find("medium"), en.find("| easy"));
    const std::string it = progressReport(p, {}, Language::It);
    EXPECT_NE(it.find("## Esercitazione"), std::string::npos) << it;
    EXPECT_NE(it.find("| medio | 3 | 3 | 3 | sì |"), std::string::npos) << it;
    // No practice, no section.
    EXPECT_EQ(progressReport(Progress{}, {}, Language::En).find("Practice"), std::string::npos);
}

TEST(PracticeProgress, ANewInstanceIsNeverOneGivenBeforeEvenFromAnotherSeed) {
    // Seeds 27 and 84 draw the same easy 2D DDA instance (found by `practice make` over 200
    // seeds); the draw after 27 skips 84 and gives the next seed's instance.
    const PracticeInstance a = makePractice("dda-2d", 27, PracticeLevel::Easy);
    const PracticeInstance b = makePractice("dda-2d", 84, PracticeLevel::Easy);
    ASSERT_EQ(a.given.dump(), b.given.dump());
    EXPECT_EQ(practiceDigest(a), practiceDigest(b));
    EXPECT_EQ(practiceDigest(a).size(), 16u);
    PracticeRecord rec;
    recordPractice(rec, 27, Result::Right, practiceDigest(a));
    std::vector<std::uint64_t> draws = {27, 84, 85};
    std::size_t next = 0;
    const auto seen = [&](std::uint64_t s, const std::string& d) {
        return rec.drawn(s) || rec.given(d);
    };
    const PracticeInstance c = drawPractice(
        "dda-2d", PracticeLevel::Easy, [&] { return draws.at(next++); }, seen);
    EXPECT_EQ(c.seed, 85u);
    EXPECT_NE(practiceDigest(c), practiceDigest(a));
    // The digest is kept in the file and read back.
    Progress p;
    p.practice["dda-2d/easy"] = rec;
    EXPECT_EQ(parseProgress(progressToJson(p), "p").practice.at("dda-2d/easy").instances[0].digest,
              practiceDigest(a));
    // Every seed refused: one clear error, not a hang.
    EXPECT_THROW(drawPractice(
                     "dda-2d", PracticeLevel::Easy, [] { return std::uint64_t(27); }, seen),
                 PracticeError);
}
