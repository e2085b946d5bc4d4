// The 3D view a lecturer projects, checked on its pixels under Xvfb: glass and mirrors are not
// black balls, the checker floor is a checker, the Cornell box's green wall is green (the scene's
// own lights), the primary ray is seen side-on beside the eye, the legend is drawn, the grid's
// box and voxels show, and the overlay's controls work. Positions on screen are computed here by
// hand from the scene's pinhole camera, never asked of the view.
#include "compare_window.h"
#include "gui_testing.h"
#include "lesson_panel.h"
#include "main_window.h"
#include "vtk_view.h"

#include "course/palette.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QImage>
#include <QTest>
#include <QToolButton>

#include <cmath>
#include <numbers>

namespace raystep::gui {
namespace {

QImage grab(QWidget* w) {
    QApplication::processEvents();
    return w->grab().toImage().convertToFormat(QImage::Format_RGB32);
}

bool open(MainWindow& w, const QString& scene, AccelKind kind) {
    w.openScene(scene, kind, /*quiet=*/true, {}, /*render=*/false);
    return w.waitUntilIdle() && w.lastOpenOk().value_or(false);
}

void putAwayAll(LessonPanel* p) {
    for (int i = 0; i < static_cast<int>(p->lesson().exercises.size()); ++i) {
        p->selectExercise(i);
        p->closeExercise();
    }
}

/// Where the pinhole camera `c` puts world point `p` on an image of `size` (the VTK view, looking
/// from the eye, draws what the ray tracer sees), and how many pixels a length `r` there spans.
struct Projected {
    QPointF at;
    double scale;  // pixels per world unit at p's depth
};
Projected project(const Camera& c, const Vec3& p, QSize size) {
    const Vec3 f = glm::normalize(c.lookAt - c.eye), r = glm::normalize(glm::cross(f, c.up)),
               u = glm::cross(r, f);
    const Vec3 q = p - c.eye;
    const double depth = glm::dot(q, f);
    const double t = std::tan(c.fovDeg * std::numbers::pi / 360.0);
    const double aspect = double(size.width()) / size.height();
    const double x = glm::dot(q, r) / depth / (t * aspect), y = glm::dot(q, u) / depth / t;
    return {QPointF((x + 1) / 2 * size.width(), (1 - y) / 2 * size.height()),
            size.height() / 2.0 / (depth * t)};
}

/// Mean of (r + g + b) / 3 over a disc.
double meanBrightness(const QImage& image, QPointF centre, double radius) {
    double sum = 0;
    int n = 0;
    for (int y = int(centre.y() - radius); y <= int(centre.y() + radius); ++y)
        for (int x = int(centre.x() - radius); x <= int(centre.x() + radius); ++x) {
            if (!image.rect().contains(x, y) || std::hypot(x - centre.x(), y - centre.y()) > radius)
                continue;
            const QColor c = image.pixelColor(x, y);
            sum += (c.red() + c.green() + c.blue()) / 3.0;
            ++n;
        }
    return n ? sum / n : 0.0;
}

/// Pixels within `tolerance` (per channel) of a palette colour, outside `except`.
int countColour(const QImage& image, const PaletteColour& c, int tolerance, QRect except = {}) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (except.contains(x, y)) continue;
            const QColor p = image.pixelColor(x, y);
            n += std::abs(p.red() - c.r) <= tolerance && std::abs(p.green() - c.g) <= tolerance &&
                 std::abs(p.blue() - c.b) <= tolerance;
        }
    return n;
}

// The legend and caption in the top left corner (drawn with the palette's colours).
const QRect kLegend(0, 0, 340, 170);

TEST(View3D, GlassAndMirrorSpheresAreNotBlackFromTheEye) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "whitted", AccelKind::Grid));
    w.view3D()->resetCamera();
    const QImage image = grab(w.view3D());
    const Scene& s = *w.session().scene3D();
    int checked = 0;
    for (const Sphere& sp : s.spheres) {
        const Material& m = s.materials[sp.material];
        if (isBlack(m.transparency) && isBlack(m.reflect)) continue;
        const Projected p = project(s.camera, sp.center, image.size());
        ASSERT_TRUE(image.rect().contains(p.at.toPoint()));
        // Old view: the mirror drew solid black, the glass near-black (both under 40).
        EXPECT_GT(meanBrightness(image, p.at, 0.5 * sp.radius * p.scale), 70.0)
            << "sphere at " << sp.center.x << ", " << sp.center.y << ", " << sp.center.z;
        ++checked;
    }
    EXPECT_GE(checked, 2);  // whitted's glass and mirror
}

TEST(View3D, TheCheckerFloorIsDrawnAsAChecker) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "whitted", AccelKind::Grid));
    w.view3D()->resetCamera();
    const QImage image = grab(w.view3D());
    const Scene& s = *w.session().scene3D();
    // The floor's two colours, as chromaticities (lighting scales a colour, not its hue).
    const Material* floor = nullptr;
    for (const Triangle& t : s.triangles)
        if (s.materials[t.material].checker.enabled) floor = &s.materials[t.material];
    ASSERT_NE(floor, nullptr);
    const auto chroma = [](double r, double g, double b) {
        const double sum = std::max(r + g + b, 1e-9);
        return std::array<double, 2>{r / sum, g / sum};
    };
    const auto a = chroma(floor->kd.x, floor->kd.y, floor->kd.z);
    const auto b = chroma(floor->checker.color.x, floor->checker.color.y, floor->checker.color.z);
    ASSERT_GT(std::hypot(a[0] - b[0], a[1] - b[1]), 0.1);
    // The bottom tenth of the view is floor: both colours show there, each on a good share.
    int na = 0, nb = 0, n = 0;
    for (int y = image.height() * 9 / 10; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x, ++n) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() + c.green() + c.blue() < 60) continue;
            const auto k = chroma(c.red(), c.green(), c.blue());
            na += std::hypot(k[0] - a[0], k[1] - a[1]) < 0.06;
            nb += std::hypot(k[0] - b[0], k[1] - b[1]) < 0.06;
        }
    EXPECT_GT(na, n / 10);
    EXPECT_GT(nb, n / 10);
}

/// Points spread over the Cornell box's green triangles, away from their edges, as `cam` sees
/// them in `image` (outside `skip`): three in four of them are green.
void expectTheGreenWallGreen(const QImage& image, const Camera& cam, const Scene& s,
                             QRect skip = {}) {
    int samples = 0, green = 0;
    for (const Triangle& t : s.triangles) {
        const Color kd = s.materials[t.material].kd;
        if (!(kd.y > 2 * kd.x && kd.y > 2 * kd.z)) continue;
        for (int i = 1; i < 6; ++i)
            for (int j = 1; i + j < 6; ++j) {
                const Vec3 at = t.a + (t.b - t.a) * (i / 6.0) + (t.c - t.a) * (j / 6.0);
                const Projected p = project(cam, at, image.size());
                if (!image.rect().contains(p.at.toPoint()) || skip.contains(p.at.toPoint()))
                    continue;
                const QColor c = image.pixelColor(p.at.toPoint());
                ++samples;
                green += c.green() > 60 && c.green() > c.red() + 30 && c.green() > c.blue() + 30;
            }
    }
    ASSERT_GE(samples, 10);
    EXPECT_GT(green, samples * 3 / 4) << green << " of " << samples;
}

TEST(View3D, TheCornellBoxsGreenWallIsGreen) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "cornell", AccelKind::Grid));
    w.view3D()->resetCamera();
    const QImage image = grab(w.view3D());
    expectTheGreenWallGreen(image, w.session().scene3D()->camera, *w.session().scene3D());
}

// From beside the eye (the view's own framing, lessons 4 and 9) the camera is outside the box, on
// the green wall's far side: a one-sided wall lit from inside was drawn black there.
TEST(View3D, TheCornellBoxsGreenWallIsGreenFromBesideTheEyeToo) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "cornell", AccelKind::Grid));
    w.view3D()->frameBesideEye();
    const QImage image = grab(w.view3D());
    const Camera cam = w.view3D()->currentCamera();
    // The camera is on the wall's far side from the light (x = 1, the light at x = 0).
    ASSERT_GT(cam.eye.x, 1.0);
    expectTheGreenWallGreen(image, cam, *w.session().scene3D(), kLegend);
}

// Lesson 12's primary ray over the whitted floor's red and yellow checker: an outline keeps its
// edges (the orange-red ray vanished on the red squares).
TEST(View3D, ARayOverTheCheckerHasADarkOutline) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openLesson(w, "12"));
    putAwayAll(w.lessonPanel());
    w.session().setCursor(w.session().size());
    const QImage image = grab(w.view3D());
    const Camera cam = w.view3D()->currentCamera();
    const EventLog& log = w.session().log();
    ASSERT_FALSE(log.rays().empty());
    const RayRecord& ray = log.rays().front();
    ASSERT_EQ(ray.kind, RayKind::Primary);
    double tHit = -1;
    for (const Event& e : log.events())
        if (const auto* h = std::get_if<RayHit>(&e); h && h->ray == 0) tHit = h->t;
    ASSERT_GT(tHit, 0);
    const PaletteColour& primary = rayColour(RayKind::Primary);
    const auto isRay = [&](QColor c) {
        return std::abs(c.red() - primary.r) + std::abs(c.green() - primary.g) +
                   std::abs(c.blue() - primary.b) <
               90;
    };
    const auto isDark = [](QColor c) { return std::max({c.red(), c.green(), c.blue()}) < 60; };
    int samples = 0, outlined = 0;
    for (int k = 3; k <= 7; ++k) {
        const Vec3 at = ray.origin + ray.dir * (tHit * k / 10.0);
        const QPointF p = project(cam, at, image.size()).at,
                      q = project(cam, ray.origin + ray.dir * (tHit * (k + 1) / 10.0), image.size())
                              .at;
        const QPointF along = (q - p) / std::hypot(q.x() - p.x(), q.y() - p.y());
        const QPointF across(-along.y(), along.x());
        if (!isRay(image.pixelColor(p.toPoint()))) continue;  // hidden here (the frustum, a sphere)
        ++samples;
        // Out from the ray's core on each side: a dark pixel within 3 pixels of its edge (one
        // may blend the two).
        int sides = 0;
        for (const double sign : {-1.0, 1.0}) {
            int d = 1;
            while (d <= 14 && isRay(image.pixelColor((p + sign * d * across).toPoint()))) ++d;
            bool dark = false;
            for (int e = d; e < d + 3; ++e)
                dark = dark || isDark(image.pixelColor((p + sign * e * across).toPoint()));
            sides += dark;
        }
        outlined += sides == 2;
    }
    ASSERT_GE(samples, 3);
    EXPECT_GE(outlined, samples - 1) << outlined << " of " << samples;
}

// gui.md 15: in a 2D lesson the 3D items did nothing (the heat map could even be checked) and the
// 3D view's screenshot saved its hidden placeholder; in a 3D one the 2D view's did the same.
TEST(View3D, ItemsOfOneKindOfSceneAreOffWithTheOther) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    const auto enabled = [&](const char* name) {
        const auto* a = w.findChild<QAction*>(QString::fromLatin1(name));
        EXPECT_NE(a, nullptr) << name;
        return a && a->isEnabled();
    };
    const char* const threeD[] = {"heatmap",      "renderAgain",     "resetCamera",
                                  "screenshot3D", "screenshotImage", "rayTraceView"};
    ASSERT_TRUE(openLesson(w, "6"));  // 2D
    for (const char* name : threeD) EXPECT_FALSE(enabled(name)) << name;
    EXPECT_TRUE(enabled("screenshot2D"));
    EXPECT_TRUE(enabled("live2dFit"));
    ASSERT_TRUE(openLesson(w, "1"));  // 3D
    for (const char* name : threeD) EXPECT_TRUE(enabled(name)) << name;
    EXPECT_FALSE(enabled("screenshot2D"));
    EXPECT_FALSE(enabled("live2dFit"));
    w.tasks().cancel(TaskKind::Render);
}

TEST(View3D, ThePrimaryRayIsSeenSideOnBesideTheEye) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "default", AccelKind::BruteForce));
    // A clicked pixel's trace is framed from beside the eye (from the eye the ray is a point).
    w.session().tracePixel(160, 120, 320, 240);
    w.session().setCursor(w.session().size());  // as a click does: the whole tree
    const PaletteColour& primary = rayColour(RayKind::Primary);
    EXPECT_GT(countColour(grab(w.view3D()), primary, 30, kLegend), 400);
    // Lesson 2's first step ("the primary ray starts"), at the lesson's own camera.
    ASSERT_TRUE(openLesson(w, "algorithm-steps"));
    putAwayAll(w.lessonPanel());
    w.lessonPanel()->goToStep(0);
    EXPECT_GT(countColour(grab(w.view3D()), primary, 30, kLegend), 400);
    w.tasks().cancel(TaskKind::Render);
}

// Compare mode's three 3D views are made for sessions that already hold their trace: each is
// framed beside the eye at once, so each shows the primary ray (from the eye it was a point).
TEST(View3D, CompareModesViewsShowThePrimaryRay) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openLesson(w, "brute-force"));
    putAwayAll(w.lessonPanel());
    w.openCompare();
    ASSERT_TRUE(w.waitUntilIdle());
    CompareWindow* c = w.compareWindow();
    ASSERT_NE(c, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(c));
    const PaletteColour& primary = rayColour(RayKind::Primary);
    for (int i = 0; i < 3; ++i) {
        QWidget* v = c->view(i);
        ASSERT_NE(qobject_cast<VtkView*>(v), nullptr);
        // Only the first view has the legend; its corner is left out in all three.
        EXPECT_GT(countColour(grab(v), primary, 30, QRect(0, 0, 340, 220)), 150) << "view " << i;
    }
    c->close();
    w.tasks().cancel(TaskKind::Render);
}

TEST(View3D, TheLegendShowsEveryRayColour) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openLesson(w, "ray-tree"));
    const QImage legend = grab(w.view3D()).copy(kLegend);
    for (int k = 0; k < kRayKindCount; ++k)
        EXPECT_GT(countColour(legend, rayColour(RayKind(k)), 20), 30) << k;
    w.tasks().cancel(TaskKind::Render);
}

TEST(View3D, TheGridLessonShowsTheGridsBoxAndItsVoxels) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(openLesson(w, "dda-3d"));
    putAwayAll(w.lessonPanel());
    w.lessonPanel()->goToStep(2);  // some voxels visited
    const QImage image = grab(w.view3D());
    EXPECT_GT(countColour(image, structureColour(StructureRole::GridBox), 3, kLegend), 300);
    EXPECT_GT(countColour(image, structureColour(StructureRole::Voxel), 3, kLegend) +
                  countColour(image, structureColour(StructureRole::CurrentVoxel), 3, kLegend),
              200);
    w.tasks().cancel(TaskKind::Render);
}

TEST(View3D, TheOverlayReturnsToTheEyeAndLabelsPrimitives) {
    MainWindow w;
    w.resize(1400, 860);
    w.show();
    ASSERT_TRUE(open(w, "whitted", AccelKind::Grid));
    VtkView* v = w.view3D();
    w.session().tracePixel(150, 100, 320, 240);
    w.session().setCursor(w.session().size());
    const QImage beside = grab(v);
    QToolButton* eye = nullptr;
    for (QToolButton* b : v->findChildren<QToolButton*>())
        if (b->text() == "View from the eye") eye = b;
    ASSERT_NE(eye, nullptr);
    eye->click();
    const QImage fromEye = grab(v);
    EXPECT_NE(fromEye, beside);
    v->resetCamera();
    EXPECT_EQ(grab(v), fromEye);
    // The ids: drawn over the view, and gone again when switched off.
    v->setShowPrimitiveIds(true);
    EXPECT_TRUE(v->showingPrimitiveIds());
    EXPECT_NE(grab(v), fromEye);
    v->setShowPrimitiveIds(false);
    EXPECT_EQ(grab(v), fromEye);
}

}  // namespace
}  // namespace raystep::gui
