#pragma once
// The 3D view: VTK renders off screen and the widget draws the pixels it reads back, with mouse
// events forwarded to a VTK interactor (DESIGN.md: the way that works with Qt6 and Debian's VTK
// under Xvfb). Shows the scene, the recorded rays up to the cursor coloured by kind, the hits,
// and the current ray's visited voxels (grid) or the kd-tree node it is in. By default it looks
// from beside the eye, so the primary ray is seen side-on (from the eye it is a point).
#include "session.h"
#include "vtk_actors.h"

#include "raystep/base/i18n.h"
#include "raystep/scene/camera.h"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <QWidget>

#include <optional>

class QPainter;
class QToolButton;
class vtkActor;
class vtkGenericRenderWindowInteractor;
class vtkRenderWindow;
class vtkRenderer;

namespace raystep::gui {

/// A kind of ray as the legend shows it, with its colour's name as the lessons write it:
/// "primary (red)".
QString rayKindLabel(RayKind kind, Language lang);
/// The legend of the ray colours (the palette's), with its top left corner at `topLeft`.
void drawRayLegend(QPainter& g, QPointF topLeft, bool dark, Language lang);

class VtkView : public QWidget {
    Q_OBJECT
  public:
    explicit VtkView(Session& session, QWidget* parent = nullptr);
    ~VtkView() override;
    QSize sizeHint() const override { return {480, 360}; }
    /// The legend's language (its colour names are the lessons').
    void setLanguage(Language lang) {
        lang_ = lang;
        update();
    }
    /// Whether the view draws its caption and its ray legend (compare mode shows them once).
    void setOverlays(bool caption, bool legend) {
        caption_ = caption;
        legend_ = legend;
        update();
    }
    /// The scene's camera turned about its focal point (degrees) and moved closer by `zoom`.
    void orbit(double azimuth, double elevation, double zoom);
    /// The camera the view shows, as the ray tracer's (eye, lookAt, up, vertical fov): pixel
    /// (x, y) of a width() x height() image is the ray under widget point (x + 0.5, y + 0.5).
    Camera currentCamera() const;
    bool showingPrimitiveIds() const { return showIds_; }
    /// Puts the camera where `c` says (compare mode's views all look as the one turned last).
    void setCamera(const Camera& c);
    /// Whether the view's own buttons are shown (compare mode has one row of them for all).
    void setButtonsShown(bool shown);

  public slots:
    /// Back to the scene's own camera: the view from the eye.
    void resetCamera();
    void viewFromEye() { resetCamera(); }
    /// From beside the eye, the scene's up kept: the eye, its image plane, the whole ray tree,
    /// the structure's boxes and the scene near them in view, the primary ray side-on.
    void frameBesideEye();
    /// Labels every primitive in view with its id (the exercises' "primitive 1").
    void setShowPrimitiveIds(bool show);

  signals:
    /// The camera changed (turned, moved or zoomed, by the user or by code).
    void cameraMoved();
    /// A left click without a drag at `widgetPos`: the pixel under it may be traced.
    void pointPicked(QPointF widgetPos);

  protected:
    void paintEvent(QPaintEvent*) override;
    void resizeEvent(QResizeEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;

  private:
    /// Hands the mouse position and modifiers to the VTK interactor (y flipped).
    void forward(QMouseEvent* e);
    void rebuildScene();
    void rebuildRays();
    /// The primitive ids at their centres' projections, over the rendered image.
    void drawPrimitiveIds(QPainter& g);
    void placeButtons();
    /// Looks along -toCamera (unit) at what matters, from the nearest distance showing all of it.
    void fit(const Vec3& toCamera, const Vec3& up, double fovDeg);

    Session& session_;
    vtkNew<vtkRenderWindow> window_;
    vtkNew<vtkRenderer> renderer_;
    vtkNew<vtkGenericRenderWindowInteractor> interactor_;
    PropSet sceneProps_;  // primitives, light glyphs
    PropSet traceProps_;  // rays, hits, the structure, tested primitives
    PropSet eyeProps_;    // the eye, its frustum, image plane and traced pixels
    QToolButton* eyeButton_ = nullptr;
    QToolButton* besideButton_ = nullptr;
    QToolButton* idsButton_ = nullptr;
    bool showIds_ = false;
    /// How the camera was last placed, so a resize can place it again for the new shape.
    enum class Framing { Eye, Beside, Orbit, User } framing_ = Framing::Eye;
    std::array<double, 3> orbit_{0, 0, 1};
    bool dirty_ = true;
    Language lang_ = Language::En;
    // Ray trace this view: the camera last announced, and the left press a click may end.
    Camera announcedCamera_;
    std::optional<QPointF> pressAt_;
    bool caption_ = true, legend_ = true;
};

}  // namespace raystep::gui
