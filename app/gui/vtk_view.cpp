#include "vtk_view.h"

#include "course/palette.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

namespace raystep::gui {

namespace {
/// One actor drawing coloured line segments (the rays; the voxels, boxes, planes and hits).
vtkSmartPointer<vtkActor> linesActor(vtkPoints* points, vtkCellArray* lines,
                                     vtkUnsignedCharArray* colours, double width) {
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetLines(lines);
    poly->GetCellData()->SetScalars(colours);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetLineWidth(width);
    return actor;
}

/// A palette colour (course/palette.h, the one table) as VTK's cell colour.
struct Rgb {
    unsigned char c[3];
    explicit Rgb(const PaletteColour& p) : c{p.r, p.g, p.b} {}
    operator const unsigned char*() const { return c; }
};
}  // namespace

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
    connect(&session_, &Session::sceneChanged, this, [this] {
        rebuildScene();
        rebuildRays();
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
    rebuildScene();
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

void VtkView::rebuildScene() {
    renderer_->RemoveAllViewProps();
    raysActor_ = nullptr;
    markersActor_ = nullptr;
    const Scene* s = session_.scene3D();
    if (!s) {
        dirty_ = true;
        update();
        return;
    }
    for (const Sphere& sp : s->spheres) {
        vtkNew<vtkSphereSource> src;
        src->SetCenter(sp.center.x, sp.center.y, sp.center.z);
        src->SetRadius(sp.radius);
        src->SetThetaResolution(32);
        src->SetPhiResolution(16);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(src->GetOutputPort());
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        const Color kd = s->materials[sp.material].kd;
        actor->GetProperty()->SetColor(kd.x, kd.y, kd.z);
        actor->GetProperty()->SetOpacity(isBlack(s->materials[sp.material].transparency) ? 1.0
                                                                                         : 0.45);
        renderer_->AddActor(actor);
    }
    if (!s->triangles.empty()) {
        vtkNew<vtkPoints> points;
        vtkNew<vtkCellArray> cells;
        vtkNew<vtkUnsignedCharArray> colours;
        colours->SetNumberOfComponents(3);
        for (const Triangle& t : s->triangles) {
            vtkIdType ids[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3& p = k == 0 ? t.a : (k == 1 ? t.b : t.c);
                ids[k] = points->InsertNextPoint(p.x, p.y, p.z);
            }
            cells->InsertNextCell(3, ids);
            const Color kd = glm::clamp(s->materials[t.material].kd, 0.0, 1.0) * 255.0;
            const unsigned char c[3] = {static_cast<unsigned char>(kd.x),
                                        static_cast<unsigned char>(kd.y),
                                        static_cast<unsigned char>(kd.z)};
            colours->InsertNextTypedTuple(c);
        }
        vtkNew<vtkPolyData> mesh;
        mesh->SetPoints(points);
        mesh->SetPolys(cells);
        mesh->GetCellData()->SetScalars(colours);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(mesh);
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        renderer_->AddActor(actor);
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
    dirty_ = true;
    update();
}

void VtkView::orbit(double azimuth, double elevation, double zoom) {
    resetCamera();
    vtkCamera* cam = renderer_->GetActiveCamera();
    cam->Azimuth(azimuth);
    cam->Elevation(elevation);
    cam->OrthogonalizeViewUp();
    cam->Dolly(zoom);
    renderer_->ResetCameraClippingRange();
    dirty_ = true;
    update();
}

void VtkView::rebuildRays() {
    if (raysActor_) renderer_->RemoveActor(raysActor_);
    if (markersActor_) renderer_->RemoveActor(markersActor_);
    raysActor_ = markersActor_ = nullptr;
    const Scene* s = session_.scene3D();
    const EventLog& log = session_.log();
    // A build has no rays but has boxes and planes to show.
    if (!s || (log.rays().empty() && !session_.showingBuild())) {
        dirty_ = true;
        update();
        return;
    }
    // Each ray that has begun by the cursor, from its origin to its hit (or a scene's length).
    const ReplayState& st = session_.state();
    std::vector<double> ends(log.rays().size(), -1.0);
    std::vector<bool> begun(log.rays().size(), false);
    for (std::size_t i = 0; i < st.cursor; ++i) {
        const Event& e = log.events()[i];
        if (const auto* b = std::get_if<RayBegin>(&e)) begun[b->ray] = true;
        if (const auto* h = std::get_if<RayHit>(&e)) ends[h->ray] = h->t;
    }
    const double sceneSize = glm::length(s->bounds().diagonal());
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    for (std::size_t r = 0; r < log.rays().size(); ++r) {
        if (!begun[r]) continue;
        const RayRecord& ray = log.rays()[r];
        double t = ends[r];
        if (!(t >= 0) || !std::isfinite(t))
            t = std::isfinite(ray.tMax) ? ray.tMax : sceneSize / glm::length(ray.dir);
        const Vec3 a = ray.origin, b = ray.origin + t * ray.dir;
        const vtkIdType ids[2] = {points->InsertNextPoint(a.x, a.y, a.z),
                                  points->InsertNextPoint(b.x, b.y, b.z)};
        lines->InsertNextCell(2, ids);
        colours->InsertNextTypedTuple(Rgb(rayColour(ray.kind)));
    }
    raysActor_ = linesActor(points, lines, colours, 2.5);
    renderer_->AddActor(raysActor_);

    // The current ray's structure: visited voxels (grid) or the node being entered (kd-tree),
    // as wireframe boxes, and the hit points found so far.
    vtkNew<vtkPoints> mp;
    vtkNew<vtkCellArray> ml;
    vtkNew<vtkUnsignedCharArray> mc;
    mc->SetNumberOfComponents(3);
    // Segments between points already inserted, `edges` as pairs of indices into `id`.
    const auto addEdges = [&](const vtkIdType* id, const auto& edges, const unsigned char* colour) {
        for (const auto& e : edges) {
            const vtkIdType pair[2] = {id[e[0]], id[e[1]]};
            ml->InsertNextCell(2, pair);
            mc->InsertNextTypedTuple(colour);
        }
    };
    const auto box = [&](const Vec3& lo, const Vec3& hi, const unsigned char* colour) {
        vtkIdType id[8];
        for (int k = 0; k < 8; ++k)
            id[k] =
                mp->InsertNextPoint(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        static const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                         {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        addEdges(id, edges, colour);
    };
    // A split plane: its outline in the box and the two diagonals, so it reads as a plane.
    const auto plane = [&](const Vec3& lo, const Vec3& hi, int axis, double at,
                           const unsigned char* colour) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        Vec3 c[4];
        for (int k = 0; k < 4; ++k) {
            c[k][axis] = at;
            c[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
            c[k][v] = (k >= 2) ? hi[v] : lo[v];
        }
        vtkIdType id[4];
        for (int k = 0; k < 4; ++k) id[k] = mp->InsertNextPoint(c[k].x, c[k].y, c[k].z);
        static const int edges[6][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}};
        addEdges(id, edges, colour);
    };
    // The 2D view's roles, from the one palette: visited voxels, the current node, hits, the
    // build's candidate and chosen planes.
    const Rgb kVoxel(roleColour(PaletteRole::Visited)), kNode(roleColour(PaletteRole::Current)),
        kHitMark(roleColour(PaletteRole::Hit)), kCandidate(roleColour(PaletteRole::Candidate)),
        kChosen(roleColour(PaletteRole::Chosen));
    const Accelerator* accel = session_.accel3D();
    if (const auto* grid = accel ? std::get_if<UniformGrid>(accel) : nullptr) {
        const auto& spec = grid->spec();
        const Vec3 size(spec.cellSize(0), spec.cellSize(1), spec.cellSize(2));
        for (const auto& c : st.visitedCells) {
            const Vec3 lo = spec.lo + Vec3(c[0], c[1], c[2]) * size;
            box(lo, lo + size, kVoxel);
        }
    } else if (const auto* kd = accel ? std::get_if<KdTree3>(accel) : nullptr;
               kd && st.node && st.node->node < kd->nodes().size()) {
        // The entered node's box, from the walk over the tree that carries every node's box.
        const std::uint32_t entered = st.node->node;
        std::optional<std::pair<KdNode, BoxN<3>>> found;
        kd->forEachNode([&](std::uint32_t id, const KdNode& n, const BoxN<3>& b) {
            if (id == entered) found.emplace(n, b);
        });
        if (found) {
            const auto& [n, b] = *found;
            box(b.lo, b.hi, kNode);
            if (!n.leaf()) plane(b.lo, b.hi, n.axis, n.split, kChosen);
        }
    } else if (const auto* bvh = accel ? std::get_if<Bvh3>(accel) : nullptr;
               bvh && !session_.showingBuild()) {
        // Object subdivision: every box the ray has entered (they may overlap), the current one
        // brighter.
        const Rgb kEntered(roleColour(PaletteRole::Visited));
        for (const std::uint32_t n : st.nodesEntered)
            if (n < bvh->nodes().size())
                box(bvh->nodes()[n].bounds.lo, bvh->nodes()[n].bounds.hi,
                    st.node && n == st.node->node ? kNode : kEntered);
    }
    // A build's replay: the node being split, the candidate plane of the sweep, the choice.
    if (session_.showingBuild() && st.buildNode && st.buildNode->node < log.nodes().size()) {
        const NodeRecord& n = log.nodes()[st.buildNode->node];
        const Vec3 lo(n.lo[0], n.lo[1], n.lo[2]), hi(n.hi[0], n.hi[1], n.hi[2]);
        box(lo, hi, kNode);
        if (!st.candidates.empty())
            plane(lo, hi, st.candidates.back().axis, st.candidates.back().position, kCandidate);
        if (st.chosen) plane(lo, hi, st.chosen->axis, st.chosen->position, kChosen);
    }
    for (std::size_t r = 0; r < log.rays().size(); ++r) {
        if (!begun[r] || !(ends[r] >= 0) || !std::isfinite(ends[r])) continue;
        const RayRecord& ray = log.rays()[r];
        const Vec3 p = ray.origin + ends[r] * ray.dir;
        const double m = 0.01 * sceneSize;
        box(p - Vec3(m), p + Vec3(m), kHitMark);
    }
    markersActor_ = linesActor(mp, ml, mc, 1.5);
    renderer_->AddActor(markersActor_);
    dirty_ = true;
    update();
}

void VtkView::resizeEvent(QResizeEvent*) {
    window_->SetSize(std::max(1, width()), std::max(1, height()));
    interactor_->SetSize(std::max(1, width()), std::max(1, height()));
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
    // Render only when something changed; read back RGB (RGBA would come out transparent).
    window_->SetSize(std::max(1, width()), std::max(1, height()));
    window_->Render();
    const int w = window_->GetSize()[0], h = window_->GetSize()[1];
    unsigned char* pixels = window_->GetPixelData(0, 0, w - 1, h - 1, /*front=*/0);
    QImage image(pixels, w, h, 3 * w, QImage::Format_RGB888);
    g.drawImage(rect(), image.mirrored(false, true));
    delete[] pixels;
    // The lecture's first slide: this view is rasterized, the image beside it ray traced.
    g.setPen(QColor(230, 230, 230));
    if (caption_)
        g.drawText(QRectF(8, 6, width() - 16, 20), Qt::AlignLeft,
                   tr("Rasterization (VTK, OpenGL): the scene and the recorded rays"));
    // Which colour is which kind of ray (the lessons name the same colours).
    if (legend_ && !session_.showingBuild())
        drawRayLegend(g, QPointF(8, caption_ ? 28 : 8), /*dark=*/true, lang_);
    dirty_ = false;
}

void VtkView::forward(QMouseEvent* e) {
    interactor_->SetEventInformationFlipY(int(e->position().x()), int(e->position().y()),
                                          e->modifiers() & Qt::ControlModifier,
                                          e->modifiers() & Qt::ShiftModifier);
}
void VtkView::mousePressEvent(QMouseEvent* e) {
    pressAt_.reset();
    if (e->button() == Qt::LeftButton) pressAt_ = e->position();
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
    if (e->angleDelta().y() > 0)
        interactor_->MouseWheelForwardEvent();
    else
        interactor_->MouseWheelBackwardEvent();
    update();
}

}  // namespace raystep::gui
