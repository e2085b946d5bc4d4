#include "vtk_view.h"

#include "course/palette.h"
#include "presentation.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkProp.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <QMouseEvent>
#include <QPainter>
#include <QToolButton>
#include <QWheelEvent>

#include <numbers>

namespace raystep::gui {

QString rayKindName(RayKind kind);

QString rayKindLabel(RayKind kind, Language lang) {
    const std::string_view colour = rayColour(kind).name(lang);
    return QStringLiteral("%1 (%2)").arg(rayKindName(kind),
                                         QString::fromUtf8(colour.data(), colour.size()));
}

QString rayKindName(RayKind kind) {
    switch (kind) {
        case RayKind::Primary:
            return VtkView::tr("primary");
        case RayKind::Shadow:
            return VtkView::tr("shadow");
        case RayKind::Reflection:
            return VtkView::tr("reflection");
        case RayKind::Refraction:
            return VtkView::tr("refraction");
        case RayKind::Diffuse:
            return VtkView::tr("diffuse");
    }
    return {};
}

void drawRayLegend(QPainter& g, QPointF topLeft, bool dark, Language lang) {
    // One row a kind: a stroke in the ray's colour (the palette's) and its name.
    const QFontMetrics fm(g.font());
    const double row = fm.height() + 2, swatch = 22;
    double width = 0;
    for (int k = 0; k < kRayKindCount; ++k)
        width = std::max<double>(width, fm.horizontalAdvance(rayKindLabel(RayKind(k), lang)));
    const QRectF box(topLeft, QSizeF(swatch + 18 + width, row * kRayKindCount + 8));
    g.save();
    g.setRenderHint(QPainter::Antialiasing);
    g.setPen(Qt::NoPen);
    g.setBrush(dark ? QColor(20, 22, 28, 200) : QColor(255, 255, 255, 220));
    g.drawRoundedRect(box, 4, 4);
    for (int k = 0; k < kRayKindCount; ++k) {
        const PaletteColour& c = rayColour(RayKind(k));
        const double y = box.top() + 4 + row * k + row / 2;
        g.setPen(QPen(QColor(c.r, c.g, c.b), 3));
        g.drawLine(QPointF(box.left() + 6, y), QPointF(box.left() + 6 + swatch, y));
        g.setPen(dark ? QColor(235, 235, 235) : QColor(40, 40, 40));
        g.drawText(QRectF(box.left() + 12 + swatch, y - row / 2, width + 4, row),
                   Qt::AlignLeft | Qt::AlignVCenter, rayKindLabel(RayKind(k), lang));
    }
    g.restore();
}

VtkView::VtkView(Session& session, QWidget* parent) : QWidget(parent), session_(session) {
    // A click takes the keyboard from the answer box, so B, R and N reach the window.
    setFocusPolicy(Qt::ClickFocus);
    setMinimumSize(240, 180);
    setAttribute(Qt::WA_OpaquePaintEvent);
    window_->SetOffScreenRendering(1);
    window_->AddRenderer(renderer_);
    renderer_->SetBackground(0.12, 0.13, 0.16);
    interactor_->SetRenderWindow(window_);
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor_->SetInteractorStyle(style);
    interactor_->Initialize();
    // Over the view, where a lecturer looks: back to the eye, beside it again, the ids.
    const auto button = [this](const QString& text, const QString& tip) {
        auto* b = new QToolButton(this);
        b->setText(text);
        b->setToolTip(tip);
        b->setFocusPolicy(Qt::NoFocus);
        b->setStyleSheet(QStringLiteral(
            "QToolButton { color: #eee; background: rgba(20, 22, 28, 200); border: 1px solid "
            "#777; border-radius: 3px; padding: 2px 6px; } QToolButton:checked { background: "
            "rgba(0, 114, 178, 220); }"));
        return b;
    };
    eyeButton_ = button(tr("View from the eye"), tr("Look through the ray tracer's camera"));
    besideButton_ =
        button(tr("Beside the eye"), tr("Look from beside the eye: the primary ray side-on"));
    idsButton_ = button(tr("Primitive ids"), tr("Label each primitive with its id"));
    idsButton_->setCheckable(true);
    connect(eyeButton_, &QToolButton::clicked, this, &VtkView::viewFromEye);
    connect(besideButton_, &QToolButton::clicked, this, &VtkView::frameBesideEye);
    connect(idsButton_, &QToolButton::toggled, this, &VtkView::setShowPrimitiveIds);
    connect(&session_, &Session::sceneChanged, this, [this] {
        rebuildScene();
        rebuildRays();
        frameBesideEye();
    });
    // A new trace (a lesson's, a clicked pixel's) is framed from beside the eye, unless the user
    // placed the camera: a pixel clicked in "ray trace this view" keeps the view it came from.
    connect(&session_, &Session::logChanged, this, [this] {
        if (framing_ != Framing::User) frameBesideEye();
    });
    connect(&session_, &Session::cursorChanged, this, [this] { rebuildRays(); });
    // Every change of the camera, whoever made it; only a new view is announced (not, e.g., a
    // new clipping range).
    vtkNew<vtkCallbackCommand> onCamera;
    onCamera->SetClientData(this);
    onCamera->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
        auto* view = static_cast<VtkView*>(self);
        const Camera c = view->currentCamera();
        const Camera& a = view->announcedCamera_;
        if (c.eye == a.eye && c.lookAt == a.lookAt && c.up == a.up && c.fovDeg == a.fovDeg) return;
        view->announcedCamera_ = c;
        emit view->cameraMoved();
    });
    renderer_->GetActiveCamera()->AddObserver(vtkCommand::ModifiedEvent, onCamera);
    // An exercise answered shows more of the tree: the framing grows to hold it.
    connect(&session_, &Session::limitChanged, this, [this] {
        if (framing_ == Framing::Beside) frameBesideEye();
        if (framing_ == Framing::Orbit) orbit(orbit_[0], orbit_[1], orbit_[2]);
    });
    // Presenter mode (presentation.h): labels' font, line widths, and black for high contrast.
    const auto restyle = [this] {
        setFont(presentation().labelFont());
        if (presentation().highContrast())
            renderer_->SetBackground(0, 0, 0);
        else
            renderer_->SetBackground(0.12, 0.13, 0.16);
        placeButtons();
        rebuildRays();
    };
    restyle();
    connect(&presentation(), &Presentation::changed, this, restyle);
    rebuildScene();
    placeButtons();
    // Made for a session that already holds its trace (compare mode's views): framed at once,
    // not only on the next new trace.
    if (session_.scene3D()) frameBesideEye();
}

void VtkView::placeButtons() {
    int x = width() - 8;
    for (QToolButton* b : {idsButton_, besideButton_, eyeButton_}) {
        const QSize size = b->sizeHint();
        x -= size.width();
        b->setGeometry(x, 6, size.width(), size.height());
        x -= 6;
    }
}

void VtkView::setShowPrimitiveIds(bool show) {
    showIds_ = show;
    if (idsButton_->isChecked() != show) idsButton_->setChecked(show);
    update();
}

Camera VtkView::currentCamera() const {
    vtkCamera* cam = renderer_->GetActiveCamera();
    double p[3], f[3], u[3];
    cam->GetPosition(p);
    cam->GetFocalPoint(f);
    cam->GetViewUp(u);
    Camera c;
    c.eye = Vec3(p[0], p[1], p[2]);
    c.lookAt = Vec3(f[0], f[1], f[2]);
    c.up = Vec3(u[0], u[1], u[2]);
    c.fovDeg = cam->GetViewAngle();  // vertical, as VTK's default (no horizontal view angle)
    return c;
}

VtkView::~VtkView() = default;

void VtkView::setCamera(const Camera& c) {
    vtkCamera* cam = renderer_->GetActiveCamera();
    cam->SetPosition(c.eye.x, c.eye.y, c.eye.z);
    cam->SetFocalPoint(c.lookAt.x, c.lookAt.y, c.lookAt.z);
    cam->SetViewUp(c.up.x, c.up.y, c.up.z);
    cam->SetViewAngle(c.fovDeg);
    renderer_->ResetCameraClippingRange();
    framing_ = Framing::User;  // a resize keeps it (it is another view's)
    dirty_ = true;
    update();
}

void VtkView::setButtonsShown(bool shown) {
    for (QToolButton* b : {idsButton_, besideButton_, eyeButton_}) b->setVisible(shown);
}

void VtkView::rebuildScene() {
    renderer_->RemoveAllViewProps();
    sceneProps_.props.clear();
    traceProps_.props.clear();
    eyeProps_.props.clear();
    if (const Scene* s = session_.scene3D()) {
        sceneProps_ = sceneProps(renderer_, *s);
        sceneProps_.addTo(renderer_);
    }
    resetCamera();
}

void VtkView::resetCamera() {
    if (const Scene* s = session_.scene3D()) {
        vtkCamera* cam = renderer_->GetActiveCamera();
        cam->SetPosition(s->camera.eye.x, s->camera.eye.y, s->camera.eye.z);
        cam->SetFocalPoint(s->camera.lookAt.x, s->camera.lookAt.y, s->camera.lookAt.z);
        cam->SetViewUp(s->camera.up.x, s->camera.up.y, s->camera.up.z);
        cam->SetViewAngle(s->camera.fovDeg);
        renderer_->ResetCameraClippingRange();
    }
    framing_ = Framing::Eye;
    dirty_ = true;
    update();
}

void VtkView::orbit(double azimuth, double elevation, double zoom) {
    resetCamera();
    framing_ = Framing::Orbit;
    orbit_ = {azimuth, elevation, zoom};
    vtkCamera* cam = renderer_->GetActiveCamera();
    cam->Azimuth(azimuth);
    cam->Elevation(elevation);
    cam->OrthogonalizeViewUp();
    // The lesson's angle, at the distance that shows the eye, its rays and the structure (the
    // scene camera's own distance left the eye behind the view and the ray's start unseen).
    const double* p = cam->GetPosition();
    const double* f = cam->GetFocalPoint();
    const double* up = cam->GetViewUp();
    if (const Scene* s = session_.scene3D())
        fit(glm::normalize(Vec3(p[0] - f[0], p[1] - f[1], p[2] - f[2])), Vec3(up[0], up[1], up[2]),
            s->camera.fovDeg);
    cam->Dolly(zoom);
    renderer_->ResetCameraClippingRange();
    dirty_ = true;
    update();
}

void VtkView::frameBesideEye() {
    const Scene* s = session_.scene3D();
    if (!s) return resetCamera();
    const Camera& c = s->camera;
    const Vec3 f = glm::normalize(c.lookAt - c.eye), r = glm::normalize(glm::cross(f, c.up)),
               u = glm::cross(r, f);
    // To the eye's right, above and behind it: the ray runs left to right, nearly side-on,
    // and the image plane shows its face.
    fit(glm::normalize(0.8 * r + 0.4 * u - 0.5 * f), glm::normalize(c.up), 35.0);
    framing_ = Framing::Beside;
    dirty_ = true;
    update();
}

void VtkView::fit(const Vec3& toCamera, const Vec3& up, double fovDeg) {
    const Vec3 sx = glm::normalize(glm::cross(-toCamera, up)), sy = glm::cross(sx, -toCamera);
    const double tv = std::tan(fovDeg * std::numbers::pi / 360.0);
    const double th = tv * std::max(1, width()) / std::max(1, height());
    // Centred on what matters as the camera sees it, at the nearest distance that shows all.
    const std::vector<Vec3> points = pointsThatMatter(session_);
    if (points.empty()) return;
    Vec3 lo(kInfinity), hi(-kInfinity);
    for (const Vec3& p : points) {
        const Vec3 q(glm::dot(p, sx), glm::dot(p, sy), glm::dot(p, toCamera));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    const Vec3 mid = 0.5 * (lo + hi);
    const Vec3 centre = mid.x * sx + mid.y * sy + mid.z * toCamera;
    // Margins keep the caption, legend and buttons (top left and right) off the content.
    double distance = 1e-6;
    for (const Vec3& p : points) {
        const Vec3 q = p - centre;
        const double z = glm::dot(q, toCamera);
        distance = std::max({distance, z + std::abs(glm::dot(q, sx)) / (0.82 * th),
                             z + std::abs(glm::dot(q, sy)) / (0.8 * tv)});
    }
    const Vec3 eye = centre + distance * toCamera;
    vtkCamera* cam = renderer_->GetActiveCamera();
    cam->SetFocalPoint(centre.x, centre.y, centre.z);
    cam->SetPosition(eye.x, eye.y, eye.z);
    cam->SetViewUp(sy.x, sy.y, sy.z);
    cam->SetViewAngle(fovDeg);
    renderer_->ResetCameraClippingRange();
}

void VtkView::rebuildRays() {
    traceProps_.removeFrom(renderer_);
    eyeProps_.removeFrom(renderer_);
    // Rays about 4 px wide in a 450 px high view, wider on a big one (a projector's back rows).
    traceProps(session_, std::clamp(height() / 110.0, 3.0, 8.0), traceProps_, eyeProps_);
    traceProps_.addTo(renderer_);
    eyeProps_.addTo(renderer_);
    dirty_ = true;
    update();
}

void VtkView::resizeEvent(QResizeEvent*) {
    placeButtons();
    window_->SetSize(std::max(1, width()), std::max(1, height()));
    interactor_->SetSize(std::max(1, width()), std::max(1, height()));
    // A framing fits the view's shape: made again for the new one, unless the user has moved.
    rebuildRays();
    if (framing_ == Framing::Beside) frameBesideEye();
    if (framing_ == Framing::Orbit) orbit(orbit_[0], orbit_[1], orbit_[2]);
    dirty_ = true;
}

void VtkView::paintEvent(QPaintEvent*) {
    QPainter g(this);
    if (!session_.scene3D()) {
        g.fillRect(rect(), QColor(30, 33, 40));
        g.setPen(Qt::white);
        g.drawText(rect(), Qt::AlignCenter, tr("The 3D view shows 3D scenes."));
        return;
    }
    // From the eye itself its glyph would fill the view: hidden there.
    if (const Scene* s = session_.scene3D()) {
        const double* p = renderer_->GetActiveCamera()->GetPosition();
        const bool atEye = glm::length(Vec3(p[0], p[1], p[2]) - s->camera.eye) <
                           0.05 * glm::length(s->camera.lookAt - s->camera.eye);
        for (const auto& prop : eyeProps_.props) prop->SetVisibility(!atEye);
        renderer_->ResetCameraClippingRange();
    }
    // Render only when something changed; read back RGB (RGBA would come out transparent).
    window_->SetSize(std::max(1, width()), std::max(1, height()));
    window_->Render();
    const int w = window_->GetSize()[0], h = window_->GetSize()[1];
    unsigned char* pixels = window_->GetPixelData(0, 0, w - 1, h - 1, /*front=*/0);
    QImage image(pixels, w, h, 3 * w, QImage::Format_RGB888);
    g.drawImage(rect(), image.mirrored(false, true));
    delete[] pixels;
    if (showIds_) drawPrimitiveIds(g);
    // The lecture's first slide: this view is rasterized, the image beside it ray traced. The
    // caption and the legend are the view's chrome: their zoom is capped (the scene's is not).
    g.setFont(presentation().captionFont());
    g.setPen(QColor(230, 230, 230));
    if (caption_) {
        // Elided left of the overlay buttons (at 1366x768 the whole caption ran under them).
        const int right = eyeButton_->isVisible() ? eyeButton_->x() - 8 : width() - 8;
        const QString caption = g.fontMetrics().elidedText(
            tr("Rasterization (VTK, OpenGL): the scene and the recorded rays"), Qt::ElideRight,
            std::max(0, right - 8));
        // As high as the label font (presenter mode's is larger): not cut at the top.
        g.drawText(QRectF(8, 6, std::max(0, right - 8), g.fontMetrics().height() + 2),
                   Qt::AlignLeft, caption);
    }
    // Which colour is which kind of ray (the lessons name the same colours).
    if (legend_ && !session_.showingBuild()) {
        // Under the overlay buttons when the view is too narrow for both side by side.
        double top = caption_ ? g.fontMetrics().height() + 12 : 8;
        if (eyeButton_->isVisible() && eyeButton_->x() < 280)
            top = std::max<double>(top, eyeButton_->geometry().bottom() + 6);
        drawRayLegend(g, QPointF(8, top), /*dark=*/true, lang_);
    }
    dirty_ = false;
}

void VtkView::drawPrimitiveIds(QPainter& g) {
    const Scene* s = session_.scene3D();
    if (!s) return;
    vtkCamera* cam = renderer_->GetActiveCamera();
    const double* p = cam->GetPosition();
    const double* d = cam->GetDirectionOfProjection();
    const Vec3 pos(p[0], p[1], p[2]), dir(d[0], d[1], d[2]);
    std::vector<bool> tested(s->primitiveCount(), false);
    if (!session_.showingBuild())
        for (const PrimitiveTest& t : session_.state().tests)
            if (t.prim < tested.size()) tested[t.prim] = true;
    const std::vector<Vec3> centres = primitiveCentres(*s);
    g.save();  // the bold font stays with the labels, not the legend drawn after
    QFont font = g.font();
    font.setBold(true);
    g.setFont(font);
    const QFontMetrics fm(font);
    g.setRenderHint(QPainter::Antialiasing);
    int drawn = 0;
    // Tested ones first, so a mesh's many labels never crowd them out.
    for (const bool pass : {true, false})
        for (std::size_t i = 0; i < centres.size() && drawn < 400; ++i) {
            if (tested[i] != pass || !(glm::dot(centres[i] - pos, dir) > 0)) continue;
            renderer_->SetWorldPoint(centres[i].x, centres[i].y, centres[i].z, 1.0);
            renderer_->WorldToDisplay();
            const double* at = renderer_->GetDisplayPoint();
            const QPointF c(at[0], height() - at[1]);
            if (!rect().contains(c.toPoint())) continue;
            const QString text = QString::number(i);
            const QRectF box(c.x() - fm.horizontalAdvance(text) / 2.0 - 4,
                             c.y() - fm.height() / 2.0 - 1, fm.horizontalAdvance(text) + 8,
                             fm.height() + 2);
            const PaletteColour& hi = structureColour(StructureRole::TestedPrimitive);
            g.setPen(Qt::NoPen);
            g.setBrush(tested[i] ? QColor(hi.r, hi.g, hi.b, 235) : QColor(20, 22, 28, 210));
            g.drawRoundedRect(box, 3, 3);
            g.setPen(tested[i] ? QColor(20, 22, 28) : QColor(240, 240, 240));
            g.drawText(box, Qt::AlignCenter, text);
            ++drawn;
        }
    g.restore();
}

void VtkView::forward(QMouseEvent* e) {
    interactor_->SetEventInformationFlipY(int(e->position().x()), int(e->position().y()),
                                          e->modifiers() & Qt::ControlModifier,
                                          e->modifiers() & Qt::ShiftModifier);
}
void VtkView::mousePressEvent(QMouseEvent* e) {
    pressAt_.reset();
    if (e->button() == Qt::LeftButton) pressAt_ = e->position();
    framing_ = Framing::User;
    forward(e);
    if (e->button() == Qt::LeftButton) interactor_->LeftButtonPressEvent();
    if (e->button() == Qt::RightButton) interactor_->RightButtonPressEvent();
    if (e->button() == Qt::MiddleButton) interactor_->MiddleButtonPressEvent();
    update();
}
void VtkView::mouseReleaseEvent(QMouseEvent* e) {
    forward(e);
    if (e->button() == Qt::LeftButton) interactor_->LeftButtonReleaseEvent();
    if (e->button() == Qt::RightButton) interactor_->RightButtonReleaseEvent();
    if (e->button() == Qt::MiddleButton) interactor_->MiddleButtonReleaseEvent();
    // A click without a drag picks the point (a drag turned the camera instead).
    if (e->button() == Qt::LeftButton && pressAt_ &&
        (e->position() - *pressAt_).manhattanLength() <= 3)
        emit pointPicked(e->position());
    pressAt_.reset();
    update();
}
void VtkView::mouseMoveEvent(QMouseEvent* e) {
    if (pressAt_ && (e->position() - *pressAt_).manhattanLength() > 3) pressAt_.reset();
    forward(e);
    interactor_->MouseMoveEvent();
    update();
}
void VtkView::wheelEvent(QWheelEvent* e) {
    framing_ = Framing::User;
    if (e->angleDelta().y() > 0)
        interactor_->MouseWheelForwardEvent();
    else
        interactor_->MouseWheelBackwardEvent();
    update();
}

}  // namespace raystep::gui
