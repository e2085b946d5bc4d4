// Events as text: the lines the app's event list shows, written out by hand for a few events,
// and the log's dimension as the recorders set it.
#include "raystep/trace/event_text.h"
#include "raystep/accel/accel.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace raystep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(EventText, Numbers) {
    EXPECT_EQ(numberText(0.6), "0.6");
    EXPECT_EQ(numberText(4.0 / 3.0), "1.33333");
    EXPECT_EQ(numberText(-2.5), "-2.5");
    EXPECT_EQ(numberText(1e6), "1e+06");
    EXPECT_EQ(numberText(1e-5), "1e-05");
    EXPECT_EQ(numberText(kInf), "inf");
    EXPECT_EQ(numberText(-kInf), "-inf");
    EXPECT_EQ(numberText(-0.0), "0");
    // Exactly halfway at the sixth digit: printf's rounding, to even, as the CLI and the lessons'
    // explanations write it (one rule everywhere: formatNumber).
    EXPECT_EQ(numberText(34.28125), "34.2812");
    EXPECT_EQ(numberText(-0.6328125), "-0.632812");
    EXPECT_EQ(numberText(34.281249), "34.2812");
}

TEST(EventText, CellsTuplesAndAxes) {
    EXPECT_EQ(cellText({2, 1, 0}, 2), "(2, 1)");
    EXPECT_EQ(cellText({2, -1, 7}, 3), "(2, -1, 7)");
    EXPECT_EQ(tupleText({0.6, 0.8, 0.0}, 2), "(0.6, 0.8)");
    EXPECT_EQ(axesText(1), "X");
    EXPECT_EQ(axesText(2), "Y");
    EXPECT_EQ(axesText(3), "XY");
    EXPECT_EQ(axesText(4), "Z");
    EXPECT_EQ(axesText(0), "");
}

TEST(EventText, OneLinePerEvent) {
    EXPECT_EQ(eventText(RayBegin{0, kNoId, RayKind::Primary, 0}, 3),
              "ray 0 begins: primary, depth 0");
    EXPECT_EQ(eventText(DdaSetup{0, {1, 1, 0}, 2, {1.0, 4.0 / 3.0, 0.0}, 0.0, 5.0}, 2),
              "DDA set-up: step (1, 1), tDelta (1, 1.33333)");
    EXPECT_EQ(eventText(DdaSetup{3, {1, -1, 1}, 3, {0.5, 2.0, kInf}, 0.0, 5.0}, 3),
              "DDA set-up: step (1, -1, 1), tDelta (0.5, 2, inf)");
    // The slides' walk in 2D: the first cell, then a step in X; a 3D cell names Z too.
    EXPECT_EQ(eventText(DdaCell{0, 0, {0, 0, 0}, {0.6, 0.8, 0.0}}, 2),
              "cell (0, 0) (first cell), tMax (0.6, 0.8)");
    EXPECT_EQ(eventText(DdaCell{0, 1, {1, 0, 0}, {1.6, 0.8, 0.0}}, 2),
              "cell (1, 0) by X, tMax (1.6, 0.8)");
    EXPECT_EQ(eventText(DdaCell{2, 3, {4, 5, 0}, {1.5, 1.5, 0.0}}, 3),
              "cell (4, 5, 0) by XY, tMax (1.5, 1.5, 0)");
    EXPECT_EQ(eventText(MailboxSkip{0, 7}, 2), "mailbox: primitive 7 already tested");
    EXPECT_EQ(eventText(PrimitiveTest{0, 3, true, 2.25}, 2), "test primitive 3: hit at t = 2.25");
    EXPECT_EQ(eventText(PrimitiveTest{0, 4, false, kInf}, 2), "test primitive 4: miss");
    EXPECT_EQ(eventText(NodeEnter{0, 5, 0.5, kInf}, 3), "enter node 5 [0.5, inf]");
    EXPECT_EQ(eventText(NodeSkip{0, 6, 1.0, 2.0}, 3), "skip node 6");
    EXPECT_EQ(eventText(BuildNode{1, 0, 1, 12, 5.0, 60.0}, 2),
              "build node 1: 12 primitives, depth 1");
    EXPECT_EQ(eventText(SplitCandidate{1, 0, 4, 8, 2.5, 0.25, 0.75, 10.5}, 2),
              "candidate X = 2.5: NL 4, NR 8, cost 10.5");
    EXPECT_EQ(eventText(SplitChosen{1, 1, 3.2, 33.65625, 40.0}, 2),
              "split Y = 3.2 (cost 33.6562, leaf 40)");
    EXPECT_EQ(eventText(LeafMade{2, LeafReason::SahCheaper, 3, 2, 12.0}, 2),
              "leaf 2: 3 primitives (sah_cheaper)");
    EXPECT_EQ(eventText(RayHit{0, 3, 2.25, 0.0, 0.0}, 3), "ray 0 hits primitive 3 at t = 2.25");
    EXPECT_EQ(eventText(RayHit{1, kNoId, 1.0, 0.0, 0.0}, 3), "ray 1 hits primitive - at t = 1");
    EXPECT_EQ(eventText(RayMiss{2}, 3), "ray 2 misses");
    EXPECT_EQ(eventText(ShadingTerm{0, ShadingTermKind::Diffuse, 0, {0.5, 0.25, 0.0}}, 3),
              "diffuse term (0.5, 0.25, 0)");
    EXPECT_EQ(eventText(PixelResult{160, 120, 320, 240, {1.0, 0.5, 0.125}}, 3),
              "pixel (160, 120) = (1, 0.5, 0.125)");
    // A blocked shadow ray is its own event, naming what blocks it; one whose trace does not say
    // (a hand-written one) is still blocked, not "ray 2 hits primitive - at t = inf".
    EXPECT_EQ(eventText(RayBlocked{2, 4, 0.5}, 3),
              "shadow ray 2 blocked by primitive 4 at t = 0.5: the point is in shadow");
    EXPECT_EQ(eventText(RayBlocked{2, kNoId, kInf}, 3),
              "shadow ray 2 blocked: the point is in shadow");
}

// A colour below what six digits of a unit value hold is 0 (the specular term of a shininess
// of 1000 at a wide angle is cos^1000 of it, 2e-230: "2,08528e-230" on the board); a t stays
// exact, however small (lesson 13's shadow acne is a t of 1e-12).
TEST(EventText, TinyColoursAreZeroTinyTsAreNot) {
    EXPECT_EQ(eventText(ShadingTerm{0, ShadingTermKind::Specular, 0, {2.08528e-230, 4e-7, 0.5}}, 3),
              "specular term (0, 0, 0.5)");
    EXPECT_EQ(
        eventText(ShadingTerm{0, ShadingTermKind::Specular, 0, {6e-7, 0, 0}}, 3, Language::It),
        "termine speculare (6e-07; 0; 0)");
    EXPECT_EQ(eventText(PixelResult{1, 2, 4, 4, {1e-300, 0.25, 1}}, 3),
              "pixel (1, 2) = (0, 0.25, 1)");
    EXPECT_EQ(eventText(PrimitiveTest{0, 3, true, 1e-12}, 3), "test primitive 3: hit at t = 1e-12");
}

TEST(EventText, ItalianUsesTheSlidesTermsAndDecimalCommas) {
    constexpr Language it = Language::It;
    EXPECT_EQ(numberText(4.0 / 3.0, it), "1,33333");
    EXPECT_EQ(numberText(-0.0, it), "0");
    // A comma is the decimal sign, so a tuple's items are parted by semicolons.
    EXPECT_EQ(tupleText({0.6, 0.8, 0.0}, 2, it), "(0,6; 0,8)");
    EXPECT_EQ(eventText(RayBegin{4, 0, RayKind::Shadow, 1}, 3, it),
              "inizia il raggio 4: raggio d'ombra, profondità 1");
    EXPECT_EQ(eventText(RayBegin{5, 0, RayKind::Refraction, 1}, 3, it),
              "inizia il raggio 5: raggio di trasparenza, profondità 1");
    EXPECT_EQ(eventText(DdaSetup{0, {1, 1, 0}, 2, {1.0, 4.0 / 3.0, 0.0}, 0.0, 5.0}, 2, it),
              "inizializzazione del DDA: step (1, 1), tDelta (1; 1,33333)");
    EXPECT_EQ(eventText(DdaCell{0, 0, {0, 0, 0}, {0.6, 0.8, 0.0}}, 2, it),
              "cella (0, 0) (prima cella), tMax (0,6; 0,8)");
    EXPECT_EQ(eventText(DdaCell{0, 1, {1, 0, 0}, {1.6, 0.8, 0.0}}, 2, it),
              "cella (1, 0) (passo lungo X), tMax (1,6; 0,8)");
    EXPECT_EQ(eventText(PrimitiveTest{0, 3, true, 2.25}, 2, it),
              "test della primitiva 3: intersezione a t = 2,25");
    EXPECT_EQ(eventText(PrimitiveTest{0, 4, false, kInf}, 2, it),
              "test della primitiva 4: nessuna intersezione");
    EXPECT_EQ(eventText(MailboxSkip{0, 7}, 2, it),
              "mailboxing: primitiva 7 già testata, test saltato");
    EXPECT_EQ(eventText(NodeEnter{0, 5, 0.5, kInf}, 3, it), "entra nel nodo 5 [0,5; inf]");
    EXPECT_EQ(eventText(SplitCandidate{1, 0, 4, 8, 2.5, 0.25, 0.75, 10.5}, 2, it),
              "piano candidato X = 2,5: NL 4, NR 8; costo 10,5");
    EXPECT_EQ(eventText(SplitChosen{1, 1, 3.2, 33.65625, 40.0}, 2, it),
              "piano di taglio scelto Y = 3,2 (costo 33,6562; foglia 40)");
    EXPECT_EQ(eventText(RayHit{0, 3, 2.25, 0.0, 0.0}, 3, it),
              "raggio 0: intersezione con la primitiva 3 a t = 2,25");
    EXPECT_EQ(eventText(RayMiss{2}, 3, it), "raggio 2: nessuna intersezione");
    EXPECT_EQ(eventText(RayBlocked{2, 4, 0.5}, 3, it),
              "raggio d'ombra 2 bloccato dalla primitiva 4 a t = 0,5: il punto è in ombra");
    EXPECT_EQ(eventText(RayBlocked{2, kNoId, kInf}, 3, it),
              "raggio d'ombra 2 bloccato: il punto è in ombra");
    EXPECT_EQ(eventText(ShadingTerm{0, ShadingTermKind::Diffuse, 0, {0.5, 0.25, 0.0}}, 3, it),
              "termine diffuso (0,5; 0,25; 0)");
    // No internal name (sah_cheaper, diffuse_bounce) reaches an Italian line.
    for (auto reason : {LeafReason::FewPrimitives, LeafReason::MaxDepth, LeafReason::SahCheaper,
                        LeafReason::NoSplit, LeafReason::NoProgress}) {
        const std::string line = eventText(LeafMade{2, reason, 3, 2, 12.0}, 2, it);
        // "primitive 1" reads right for any count, as "1 primitive" would not.
        EXPECT_EQ(line.rfind("foglia 2: 3 primitive (", 0), 0u) << line;
        EXPECT_EQ(line.find('_'), std::string::npos) << line;
    }
    EXPECT_EQ(eventText(ShadingTerm{0, ShadingTermKind::DiffuseBounce, kNoId, {}}, 3, it),
              "termine dei rimbalzi diffusi (0; 0; 0)");
}

TEST(EventText, ABlockedShadowRayNamesWhatBlocksIt) {
    // A shadow ray of ray 0: it tests primitive 6 (miss), then 4, which blocks it at t = 0.5.
    EventLog log;
    const std::uint32_t primary = log.beginRay(Ray{}, RayKind::Primary, 0, kNoId);
    log(RayHit{primary, 2, 3.0, 0.0, 0.0});
    const std::uint32_t shadow = log.beginRay(Ray{}, RayKind::Shadow, 1, primary);
    log(PrimitiveTest{shadow, 6, false, kInf});
    log(PrimitiveTest{shadow, 4, true, 0.5});
    log(RayBlocked{shadow, 4, 0.5});
    const std::uint32_t lit = log.beginRay(Ray{}, RayKind::Shadow, 1, primary);
    log(PrimitiveTest{lit, 6, false, kInf});
    log(RayMiss{lit});
    ASSERT_EQ(log.events().size(), 9u);
    EXPECT_EQ(eventText(log, 5),
              "shadow ray 1 blocked by primitive 4 at t = 0.5: the point is in shadow");
    EXPECT_EQ(eventText(log, 5, Language::It),
              "raggio d'ombra 1 bloccato dalla primitiva 4 a t = 0,5: il punto è in ombra");
    EXPECT_EQ(eventText(log, 8),
              "shadow ray 2 misses: nothing lies between the point and the light");
    // Every other event reads as it does alone.
    EXPECT_EQ(eventText(log, 1), "ray 0 hits primitive 2 at t = 3");
    EXPECT_EQ(eventText(log, 4, Language::It), "test della primitiva 4: intersezione a t = 0,5");
}

TEST(EventText, EveryBlockedShadowRayOfARealTraceNamesAPrimitive) {
    // The Cornell box's floor under the tall block: its shadow rays are blocked by the block.
    const Scene s = std::get<Scene>(loadAnyScene("cornell"));
    const Accelerator grid = buildAccelerator(s, AccelKind::Grid);
    int blocked = 0;
    for (int y = 150; y < 240; y += 6)
        for (int x = 0; x < 320; x += 8) {
            EventLog log;
            tracePixelEvents(s, grid, x, y, 320, 240, log);
            for (std::size_t i = 0; i < log.events().size(); ++i) {
                const std::string line = eventText(log, i);
                EXPECT_EQ(line.find("inf:"), std::string::npos) << line;
                EXPECT_EQ(line.find("primitive -"), std::string::npos) << line;
                if (line.find("blocked by primitive") != std::string::npos) ++blocked;
                // A shadow ray ends blocked or missing, never with a hit; what blocks it is a
                // test of that ray that hit, inside the ray's interval towards the light.
                if (const auto* h = std::get_if<RayHit>(&log.events()[i])) {
                    EXPECT_NE(log.rays()[h->ray].kind, RayKind::Shadow) << line;
                }
                if (const auto* b = std::get_if<RayBlocked>(&log.events()[i])) {
                    EXPECT_EQ(log.rays()[b->ray].kind, RayKind::Shadow);
                    EXPECT_TRUE(b->t > 0 && b->t < log.rays()[b->ray].tMax) << line;
                    bool tested = false;
                    for (std::size_t k = 0; k < i; ++k)
                        if (const auto* t = std::get_if<PrimitiveTest>(&log.events()[k]))
                            tested |=
                                t->ray == b->ray && t->prim == b->prim && t->hit && t->t == b->t;
                    EXPECT_TRUE(tested) << line;
                }
            }
        }
    EXPECT_GT(blocked, 0);
}

TEST(EventText, TheRecorderSaysTheLogsDimension) {
    const Scene2D s2 = std::get<Scene2D>(loadAnyScene("lecture-grid"));
    EventLog build2, ray2;
    const Accelerator2D kd2 = buildAccelerator2D(s2, AccelKind::KdTree, {}, &build2);
    traceRay2D(kd2, *s2.exampleRay, ray2);
    EXPECT_EQ(build2.dims(), 2);
    EXPECT_EQ(ray2.dims(), 2);
    // The slides' first cell, as the event list shows it.
    EventLog walk;
    traceRay2D(buildAccelerator2D(s2, AccelKind::Grid), *s2.exampleRay, walk);
    for (const Event& e : walk.events())
        if (std::holds_alternative<DdaCell>(e)) {
            // By hand: (1 - 0.4) / 0.8 and (1 - 0.4) / 0.4.
            EXPECT_EQ(eventText(e, walk.dims()), "cell (0, 0) (first cell), tMax (0.75, 1.5)");
            break;
        }

    const Scene s3 = std::get<Scene>(loadAnyScene("default"));
    EventLog build3, pixel3;
    const Accelerator kd3 = buildAccelerator(s3, AccelKind::KdTree, {}, {}, build3);
    tracePixelEvents(s3, kd3, 160, 120, 320, 240, pixel3);
    EXPECT_EQ(build3.dims(), 3);
    EXPECT_EQ(pixel3.dims(), 3);
}

}  // namespace
}  // namespace raystep
