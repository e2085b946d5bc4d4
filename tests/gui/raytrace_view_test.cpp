// Ray trace this view: the image follows the 3D view's camera and size, progressively, honours
// the render settings (lesson 4's colour bleeding), re-renders when they change, and a click in
// the 3D view traces the pixel under it. Reference images come from the core's render().
#include "image_view.h"
#include "main_window.h"
#include "vtk_view.h"

#include "raystep/render/image.h"
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QSpinBox>
#include <QTest>

namespace raystep::gui {
namespace {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.lookAt == b.lookAt && a.up == b.up && a.fovDeg == b.fovDeg;
}

/// Waits until the image is finished and made as `ok` wants (never a fixed sleep).
template <typename Ok>
bool waitForImage(MainWindow& w, Ok ok, int timeoutMs = 120000) {
    return QTest::qWaitFor(
        [&] {
            const auto& f = w.imageFrame();
            return f && !w.tasks().busy(TaskKind::Render) &&
                   w.imageView()->state() == ImageView::State::Done && ok(*f);
        },
        timeoutMs);
}

bool openScene(MainWindow& w, const QString& scene, AccelKind kind) {
    w.openScene(scene, kind, /*quiet=*/true);
    return QTest::qWaitFor([&] { return w.lastOpenOk().has_value(); }, 120000) && *w.lastOpenOk();
}

/// The core's image of `scene` seen by `frame`'s camera, size and settings, as sRGB bytes.
std::vector<std::uint8_t> coreImage(Scene scene, AccelKind kind,
                                    const MainWindow::ImageFrame& frame) {
    scene.camera = frame.camera;
    const Accelerator accel = buildAccelerator(scene, kind);
    RenderOptions o;
    o.width = frame.width;
    o.height = frame.height;
    o.spp = frame.spp;
    o.trace = frame.trace;
    return toSrgb8(render(scene, accel, o).image);
}

/// Pixels of a 5x5 lattice over the image that differ from `rgb` (RGB bytes, same size).
int differingSamples(const QImage& image, const std::vector<std::uint8_t>& rgb) {
    int differ = 0;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            const int x = (2 * i + 1) * image.width() / 10, y = (2 * j + 1) * image.height() / 10;
            const QColor c = image.pixelColor(x, y);
            const std::size_t k = (std::size_t(y) * image.width() + x) * 3;
            if (c.red() != rgb[k] || c.green() != rgb[k + 1] || c.blue() != rgb[k + 2]) ++differ;
        }
    return differ;
}

struct Window {
    MainWindow w;
    Window() {
        w.resize(1500, 900);
        w.show();
    }
};

TEST(RayTraceView, TurningTheCameraRendersThisViewLikeTheCore) {
    Window win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openScene(w, "whitted", AccelKind::KdTree));
    // Off by default: the image is the scene camera's, as the lessons' text and pixels are.
    ASSERT_FALSE(w.rayTraceViewAction()->isChecked());
    ASSERT_TRUE(waitForImage(w, [](const auto& f) { return !f.ofView; }));
    const Scene scene = loadBuiltinScene("whitted");
    EXPECT_TRUE(sameCamera(w.imageFrame()->camera, scene.camera));

    w.rayTraceViewAction()->setChecked(true);
    w.view3D()->orbit(40, 25, 1.3);
    const Camera turned = w.view3D()->currentCamera();
    ASSERT_FALSE(sameCamera(turned, scene.camera));
    // The render of the turned view has started (the move is handled once events settle).
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const auto& f = w.imageFrame();
            return f && f->ofView && sameCamera(f->camera, turned);
        },
        10000));
    // Progressively: a picture of blocks comes first, while the render goes on.
    int firstBlock = 0;
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            ImageView* v = w.imageView();
            if (v->state() == ImageView::State::Rendering && !v->image().isNull() &&
                v->frame().block > 1 && w.imageFrame()->ofView)
                firstBlock = v->frame().block;
            return firstBlock > 0 || v->state() == ImageView::State::Done;
        },
        60000));
    EXPECT_GT(firstBlock, 1);
    ASSERT_TRUE(
        waitForImage(w, [&](const auto& f) { return f.ofView && sameCamera(f.camera, turned); }));
    const MainWindow::ImageFrame f = *w.imageFrame();
    const QImage image = w.imageView()->image();
    ASSERT_EQ(image.size(), QSize(f.width, f.height));
    // The scene's own settings (spp 4, 6 bounces) unless the control changes them.
    EXPECT_EQ(f.spp, scene.settings.spp);
    EXPECT_EQ(f.trace.bounces, scene.settings.bounces);
    // The same pixels as an independent render() of that camera...
    EXPECT_EQ(differingSamples(image, coreImage(scene, AccelKind::KdTree, f)), 0);
    // ...and not the scene camera's picture.
    MainWindow::ImageFrame sceneView = f;
    sceneView.camera = scene.camera;
    EXPECT_GT(differingSamples(image, coreImage(scene, AccelKind::KdTree, sceneView)), 8);

    // The heat map has a colour bar with its scale: the primitive tests per pixel, min and max.
    w.imageView()->setHeatmap(true);
    QApplication::processEvents();
    EXPECT_FALSE(w.imageView()->colourBarRect().isEmpty());
    Scene viewed = scene;
    viewed.camera = f.camera;
    const Accelerator accel = buildAccelerator(viewed, AccelKind::KdTree);
    RenderOptions o;
    o.width = f.width;
    o.height = f.height;
    o.spp = f.spp;
    o.trace = f.trace;
    const RenderResult r = render(viewed, accel, o);
    const auto [lo, hi] = std::minmax_element(r.costPerPixel.begin(), r.costPerPixel.end());
    EXPECT_EQ(w.imageView()->frame().minTests, *lo);
    EXPECT_EQ(w.imageView()->frame().maxTests, *hi);
    const QImage shot = w.imageView()->grab().toImage();
    const QRectF bar = w.imageView()->colourBarRect();
    const QColor left = shot.pixelColor(QPoint(int(bar.left()) + 1, int(bar.center().y())));
    const QColor right = shot.pixelColor(QPoint(int(bar.right()) - 1, int(bar.center().y())));
    EXPECT_LT(left.lightness() + 100, right.lightness());  // dark (few tests) to bright (many)
}

TEST(RayTraceView, TheImageFollowsTheViewsSize) {
    Window win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openScene(w, "whitted", AccelKind::Bvh));
    {
        const QSignalBlocker quiet(w.findChild<QSpinBox*>("renderSpp"));
        w.findChild<QSpinBox*>("renderSpp")->setValue(1);  // quicker; the size is what is checked
    }
    w.rayTraceViewAction()->setChecked(true);
    const auto viewSized = [&](const MainWindow::ImageFrame& f) {
        return f.ofView && QSize(f.width, f.height) == w.imageView()->size();
    };
    ASSERT_TRUE(waitForImage(w, viewSized));
    const QSize before = w.imageView()->imageSize();
    EXPECT_EQ(w.imageView()->image().size(), before);
    w.resize(1100, 700);
    ASSERT_TRUE(QTest::qWaitFor([&] { return w.imageView()->size() != before; }, 10000));
    ASSERT_TRUE(waitForImage(w, viewSized));
    EXPECT_NE(w.imageView()->image().size(), before);
    EXPECT_EQ(w.imageView()->image().size(), w.imageView()->size());
}

TEST(RayTraceView, LessonFourShowsColourBleeding) {
    Window win;
    MainWindow& w = win.w;
    w.openLesson("phong-diffuse", /*quiet=*/true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return w.lastOpenOk().has_value(); }, 120000));
    ASSERT_TRUE(*w.lastOpenOk()) << w.lastOpenError().toStdString();
    // The lesson's square frame (256 x 256 where there is room), the scene's settings.
    ASSERT_TRUE(waitForImage(w, [](const auto& f) { return !f.ofView && f.width == f.height; }));
    const MainWindow::ImageFrame f = *w.imageFrame();
    Scene scene = loadBuiltinScene("cornell");
    EXPECT_EQ(f.trace.diffuseSamples, scene.settings.diffuseSamples);
    EXPECT_EQ(f.spp, scene.settings.spp);
    ASSERT_GT(f.trace.diffuseSamples, 0);
    // Without diffuse bounces, by the core: the reference with no bleeding.
    MainWindow::ImageFrame flat = f;
    flat.trace.diffuseSamples = 0;
    const std::vector<std::uint8_t> noBleeding = coreImage(scene, AccelKind::Bvh, flat);
    // The floor's pixels in the left fifth of the image, next to the red wall (x = -1): found
    // with the core's structure.
    const Accelerator accel = buildAccelerator(scene, AccelKind::Bvh);
    const QImage image = w.imageView()->image();
    int floor = 0, redder = 0;
    for (int y = f.height / 2; y < f.height; y += 3)
        for (int x = 0; x < f.width / 5; x += 3) {
            TraversalCounters c;
            const auto hit =
                intersect(accel, scene.camera.generateRay(x + 0.5, y + 0.5, f.width, f.height), c);
            if (!hit || hit->prim > 1) continue;  // triangles 0 and 1 are the floor
            ++floor;
            const QColor gui = image.pixelColor(x, y);
            const std::size_t k = (std::size_t(y) * f.width + x) * 3;
            const int redness = gui.red() - gui.green(),
                      flatRedness = noBleeding[k] - noBleeding[k + 1];
            if (redness > flatRedness + 8) ++redder;
        }
    ASSERT_GT(floor, 20);
    EXPECT_GT(redder, floor / 2) << redder << " of " << floor << " floor pixels";
}

TEST(RayTraceView, ChangingTheSettingsRendersAgain) {
    Window win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openScene(w, "whitted", AccelKind::KdTree));
    ASSERT_TRUE(waitForImage(w, [](const auto& f) { return f.trace.bounces == 6; }));
    const QImage before = w.imageView()->image();
    auto* bounces = w.findChild<QSpinBox*>("renderBounces");
    ASSERT_NE(bounces, nullptr);
    bounces->setValue(0);  // no reflection or refraction rays
    ASSERT_TRUE(waitForImage(w, [](const auto& f) { return f.trace.bounces == 0; }));
    const QImage after = w.imageView()->image();
    EXPECT_NE(after, before);
    const Scene scene = loadBuiltinScene("whitted");
    EXPECT_EQ(differingSamples(after, coreImage(scene, AccelKind::KdTree, *w.imageFrame())), 0);
    auto* spp = w.findChild<QSpinBox*>("renderSpp");
    ASSERT_NE(spp, nullptr);
    spp->setValue(1);
    ASSERT_TRUE(waitForImage(w, [](const auto& f) { return f.spp == 1 && f.trace.bounces == 0; }));
    EXPECT_EQ(differingSamples(w.imageView()->image(),
                               coreImage(scene, AccelKind::KdTree, *w.imageFrame())),
              0);
}

TEST(RayTraceView, AClickInThe3DViewTracesThePixelUnderIt) {
    Window win;
    MainWindow& w = win.w;
    ASSERT_TRUE(openScene(w, "whitted", AccelKind::Bvh));
    VtkView* view = w.view3D();
    view->orbit(-30, 15, 1.0);
    QApplication::processEvents();
    const QPoint at(view->width() / 2 + 37, view->height() / 2 + 41);
    const Camera camera = view->currentCamera();
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, at);
    ASSERT_TRUE(QTest::qWaitFor([&] { return w.session().logKind() == LogKind::Pixel; }, 10000));
    // A click turns nothing.
    EXPECT_TRUE(sameCamera(view->currentCamera(), camera));
    const EventLog& log = w.session().log();
    const auto* pixel = std::get_if<PixelResult>(&log.events().back());
    ASSERT_NE(pixel, nullptr);
    EXPECT_EQ(pixel->x, std::uint32_t(at.x()));
    EXPECT_EQ(pixel->y, std::uint32_t(at.y()));
    // Its primary ray is the one through that point of the view, and the colour is the core's.
    ASSERT_FALSE(log.rays().empty());
    const Ray expected =
        camera.generateRay(at.x() + 0.5, at.y() + 0.5, view->width(), view->height());
    EXPECT_NEAR(glm::length(glm::normalize(log.rays()[0].dir) - expected.dir), 0.0, 1e-9);
    Scene scene = loadBuiltinScene("whitted");
    scene.camera = camera;
    const Accelerator accel = buildAccelerator(scene, AccelKind::Bvh);
    EventLog reference;
    const Color c =
        tracePixelEvents(scene, accel, at.x(), at.y(), view->width(), view->height(), reference);
    EXPECT_DOUBLE_EQ(pixel->rgb[0], c.x);
    EXPECT_DOUBLE_EQ(pixel->rgb[1], c.y);
    EXPECT_DOUBLE_EQ(pixel->rgb[2], c.z);
    EXPECT_EQ(log.events().size(), reference.events().size());
    // A drag turns the camera and traces nothing.
    const LogRef traced = w.session().logRef();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, at);
    QTest::mouseMove(view, at + QPoint(60, 10));
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, at + QPoint(60, 10));
    EXPECT_EQ(w.session().logRef(), traced);
}

}  // namespace
}  // namespace raystep::gui
