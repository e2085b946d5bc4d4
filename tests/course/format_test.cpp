// The lesson format's additions of issue 17 (docs/lesson-format.md): slide errata, hints given one
// at a time, colour names from the one palette, and step filters that must show an event.
#include "lesson_test_util.h"

#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"
#include "course/palette.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

namespace raystep {
namespace {

using test::expectLessonError;
using test::lessonWith;

TEST(LessonFormat, ErrataOnTheLessonAndOnAStep) {
    const Lesson l = loadLessonText(
        lessonWith(
            ",\n\"errata\": [{\"slide\": \"C = ||dir - c||^2\",\n"
            "  \"correct\": \"C = |o - c|^2 - R^2\",\n"
            "  \"why\": {\"en\": \"The origin, not the direction.\", \"it\": \"L'origine.\"}}],\n"
            "\"steps\": [{\"text\": {\"en\": \"s\"}, \"errata\": [\n"
            "  {\"slide\": {\"en\": \"while (X,Y) outside\", \"it\": \"while((X,Y) fuori)\"},\n"
            "   \"correct\": \"while (X,Y) inside\", \"why\": {\"en\": \"w\", \"it\": \"p\"}}]}]"),
        "e.json");
    ASSERT_EQ(l.errata.size(), 1u);
    EXPECT_EQ(l.errata[0].slide.en, "C = ||dir - c||^2");
    EXPECT_EQ(l.errata[0].slide.in(Language::It), "C = ||dir - c||^2");  // quoted as written
    EXPECT_EQ(l.errata[0].correct.en, "C = |o - c|^2 - R^2");
    EXPECT_EQ(l.errata[0].why.in(Language::It), "L'origine.");
    EXPECT_EQ(l.errata[0].line, 11);
    ASSERT_EQ(l.steps.size(), 1u);
    ASSERT_EQ(l.steps[0].errata.size(), 1u);
    EXPECT_EQ(l.steps[0].errata[0].slide.in(Language::It), "while((X,Y) fuori)");
    EXPECT_EQ(l.steps[0].errata[0].line, 15);
    EXPECT_EQ(erratumHeading(Language::En), "Note on the slides");
    EXPECT_EQ(erratumHeading(Language::It), "Nota sulle slide");

    expectLessonError(lessonWith(",\n\"errata\": [{\"slide\": \"a\",\n \"why\": {\"en\": \"w\"}}]"),
                      11, "errata[0]", "\"correct\" is required");
    expectLessonError(lessonWith(",\n\"errata\": [{\"slide\": \"a\", \"correct\": \"b\",\n"
                                 " \"why\": {\"en\": \"w\"}, \"page\": 3}]"),
                      12, "errata[0].page", "unknown key");
    expectLessonError(lessonWith(",\n\"errata\": {\"slide\": \"a\"}"), 11, "errata",
                      "expected a list");
    // `why` explains, so it is a TEXT in both languages, not one quoted string.
    expectLessonError(lessonWith(",\n\"steps\": [{\"text\": {\"en\": \"s\"},\n \"errata\": "
                                 "[{\"slide\": \"a\", \"correct\": \"b\", \"why\": \"w\"}]}]"),
                      12, "steps[0].errata[0].why", "expected an object");
}

TEST(LessonFormat, AHintIsOneTextOrSeveralRevealedInTurn) {
    const std::string ex =
        ",\n\"exercises\": [{\"id\": \"a\", \"type\": \"count\", \"count\": "
        "\"dda_cell\", \"prompt\": {\"en\": \"?\"},\n \"hint\": ";
    const Lesson one =
        loadLessonText(lessonWith(ex + "{\"en\": \"nudge\", \"it\": \"spinta\"}}]"), "h.json");
    ASSERT_EQ(one.exercises[0].hints.size(), 1u);
    EXPECT_EQ(one.exercises[0].hints[0].in(Language::It), "spinta");
    const Lesson three = loadLessonText(
        lessonWith(ex +
                   "[{\"en\": \"nudge\"}, {\"en\": \"formula\"},\n {\"en\": \"first step\"}]}]"),
        "h.json");
    ASSERT_EQ(three.exercises[0].hints.size(), 3u);
    EXPECT_EQ(three.exercises[0].hints[0].en, "nudge");
    EXPECT_EQ(three.exercises[0].hints[2].en, "first step");
    expectLessonError(lessonWith(ex + "[{\"en\": \"a\"},\n 7]}]"), 13, "exercises[0].hint[1]",
                      "expected an object");
    expectLessonError(lessonWith(ex + "[]}]"), 12, "exercises[0].hint", "a list of them");
}

TEST(LessonFormat, ColourNamesComeFromThePalette) {
    const Lesson l = loadLessonText(
        lessonWith(
            ",\n\"steps\": [{\"text\": {\"en\": \"Primary rays are {colour:primary}, shadow "
            "rays {colour:shadow}.\",\n \"it\": [\"I raggi primari sono in {colour:primary},\","
            " \"quelli d'ombra in {colour:shadow}.\"]}}]"),
        "c.json");
    // The names as the palette's table gives them, written here by hand.
    EXPECT_EQ(l.steps[0].text.en, "Primary rays are orange-red, shadow rays yellow.");
    EXPECT_EQ(l.steps[0].text.in(Language::It),
              "I raggi primari sono in rosso arancio,\nquelli d'ombra in giallo.");
    expectLessonError(
        lessonWith(",\n\"steps\": [{\"text\": {\"en\": \"a\",\n \"it\": \"{colour:mauve}\"}}]"), 12,
        "steps[0].text.it", "unknown colour {colour:mauve}");
    expectLessonError(lessonWith(",\n\"steps\": [{\"text\": {\"en\": \"a {colour:primary\"}}]"), 11,
                      "steps[0].text.en", "unknown colour");
    // Every key the format names is in the palette; every ray kind has its entry.
    for (const char* key : {"primary", "shadow", "reflection", "refraction", "diffuse", "visited",
                            "current", "tested", "skipped", "hit", "candidate", "chosen"})
        EXPECT_TRUE(paletteColour(key).has_value()) << key;
    for (int k = 0; k < kRayKindCount; ++k)
        EXPECT_EQ(rayColour(static_cast<RayKind>(k)).key, kRayKindNames[k]);
    EXPECT_EQ(roleColour(PaletteRole::Chosen).key, "chosen");
    EXPECT_EQ(structureColour(StructureRole::HitPoint).key, "hit-point");
    EXPECT_EQ(paletteColours().size(), 20u);
}

// Within one view (the 3D view's rays; the 2D view's roles and its ray, drawn in the primary
// colour) no two entries share a colour or a name, in either language.
TEST(LessonFormat, ThePalettesColoursAreDistinctWithinAView) {
    const auto distinct = [](const std::vector<PaletteColour>& group) {
        std::set<std::tuple<int, int, int>> rgb;
        std::set<std::string_view> en, it;
        for (const PaletteColour& c : group) {
            EXPECT_TRUE(rgb.insert({c.r, c.g, c.b}).second) << c.key;
            EXPECT_TRUE(en.insert(c.en).second) << c.key;
            EXPECT_TRUE(it.insert(c.name(Language::It)).second) << c.key;
        }
    };
    std::vector<PaletteColour> rays, view2D{rayColour(RayKind::Primary)};
    for (int k = 0; k < kRayKindCount; ++k) rays.push_back(rayColour(static_cast<RayKind>(k)));
    for (int r = 0; r < kPaletteRoleCount; ++r)
        view2D.push_back(roleColour(static_cast<PaletteRole>(r)));
    distinct(rays);
    distinct(view2D);
    // The 3D view's structures (boxes, voxels, planes) never take a ray's colour or name.
    for (int r = 0; r < kStructureRoleCount; ++r) {
        const PaletteColour& s = structureColour(static_cast<StructureRole>(r));
        for (const PaletteColour& ray : rays) {
            EXPECT_NE(std::tie(s.r, s.g, s.b), std::tie(ray.r, ray.g, ray.b)) << s.key;
            EXPECT_NE(s.en, ray.en) << s.key;
            EXPECT_NE(s.name(Language::It), ray.name(Language::It)) << s.key;
        }
    }
}

TEST(LessonFormat, AFilterMatchesAKindNameOrTheEventsLine) {
    const Lesson l = loadLesson("grid-2d-dda");
    const LessonRun run = runLesson(l);
    const int dims = run.log->dims();
    const auto count = [&](const char* filter) {
        int n = 0;
        for (const Event& e : run.log->events()) n += eventMatchesFilter(e, dims, filter);
        return n;
    };
    int cells = 0;
    for (const Event& e : run.log->events()) cells += std::holds_alternative<DdaCell>(e);
    ASSERT_GT(cells, 0);
    EXPECT_EQ(count("dda_cell"), cells);
    EXPECT_EQ(count("DDA_CELL"), cells);  // case aside, as the event list filters
    EXPECT_EQ(count(""), static_cast<int>(run.log->events().size()));
    EXPECT_EQ(count("split_chosen"), 0);
    EXPECT_GT(count("ray_begin"), 0);
    // The line the app shows, in its language: the Italian word matches it, the kind name too.
    const Event& first = run.log->events().front();
    EXPECT_TRUE(eventMatchesFilter(first, "il raggio 0 inizia", "RAGGIO"));
    EXPECT_TRUE(eventMatchesFilter(first, "il raggio 0 inizia", "ray_begin"));
    EXPECT_FALSE(eventMatchesFilter(first, "il raggio 0 inizia", "cella"));
}

TEST(LessonFormat, ValidationRefusesAFilterThatShowsNothing) {
    Lesson l = loadLessonText(
        lessonWith(",\n\"steps\": [{\"text\": {\"en\": \"a\"}, \"filter\": \"dda_cell\"},\n"
                   "{\"text\": {\"en\": \"b\"},\n \"filter\": \"shading\"}]"),
        "f.json");
    try {
        validateLesson(l);
        ADD_FAILURE() << "a 2D ray's trace has no shading term, yet the filter was accepted";
    } catch (const LessonError& e) {
        EXPECT_EQ(e.line(), 12) << e.what();
        EXPECT_EQ(e.key(), "steps[1].filter") << e.what();
        EXPECT_NE(std::string(e.what()).find("matches no event"), std::string::npos);
    }
    l.steps[1].filter = "cell";
    EXPECT_NO_THROW(validateLesson(l));
}

TEST(LessonFormat, EveryBuiltinStepFilterShowsAnEvent) {
    for (const Lesson& l : builtinLessons()) {
        const LessonRun run = runLesson(l);
        for (const LessonStep& s : l.steps) {
            if (s.filter.empty()) continue;
            bool any = false;
            for (const Event& e : run.log->events())
                any = any || eventMatchesFilter(e, run.log->dims(), s.filter);
            EXPECT_TRUE(any) << l.file << ":" << s.line << ": filter '" << s.filter << "'";
        }
    }
}

}  // namespace
}  // namespace raystep
