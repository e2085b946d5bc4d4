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
    EXPECT_EQ(eventText(BuildNode{1, 0, 1, 12}, 2), "build node 1: 12 primitives, depth 1");
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
    EXPECT_EQ(eventText(PixelResult{160, 120, {1.0, 0.5, 0.125}}, 3),
              "pixel (160, 120) = (1, 0.5, 0.125)");
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
