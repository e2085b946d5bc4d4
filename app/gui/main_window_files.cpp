// The window's File items of its own: File > Open scene, and exporting the trace and screenshots
// (the 2D scene's and the model scene's saves are live_edit.cpp's and main_window_models.cpp's).
#include "file_dialogs.h"
#include "main_window.h"

#include "raystep/base/file_error.h"
#include "raystep/trace/trace_io.h"

#include <QBuffer>
#include <QMessageBox>
#include <QStatusBar>

#include <exception>

namespace raystep::gui {

void MainWindow::openFileDialog() {
    // Models too: the scene is made around them (model_import.h). Not the lesson's structure
    // (brute force in lesson 1 would take minutes on a big mesh): the chooser's, else a kd-tree.
    const QString path = openFileName(
        this, tr("Open scene"),
        tr("Scenes and models (*.json *.obj *.ply *.stl *.gltf *.glb)") + ";;" +
            tr("Scenes (*.json)") + ";;" + tr("Models (*.obj *.ply *.stl *.gltf *.glb)"));
    if (!path.isEmpty()) openScene(path, openKind(), false, openOptions());
}

QString savePng(const QImage& image, const QString& path) {
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) return path + ": cannot encode the image as PNG";
    try {
        writeFileAtomic(path.toStdString(), png.toStdString());
    } catch (const std::exception& e) {
        return QString::fromStdString(printable(e.what(), 4096));
    }
    return {};
}

void MainWindow::exportScreenshot(QWidget* w, const QString& what) {
    // A hidden view would be saved as its placeholder ("The 3D view shows 3D scenes").
    if (!w->isVisible()) {
        statusBar()->showMessage(
            tr("The %1 is not shown with this scene: there is nothing of it to export").arg(what));
        return;
    }
    const QString path =
        saveFileName(this, tr("Screenshot of the %1").arg(what), tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    if (const QString problem = savePng(w->grab().toImage(), path); !problem.isEmpty())
        QMessageBox::warning(this, tr("Cannot save"), problem);
}

void MainWindow::exportTrace() {
    // The file holds the whole trace, past where an exercise holds the replay.
    if (refusedWhileHeld(tr("export the trace"))) return;
    const QString path = saveFileName(this, tr("Export trace"), tr("Trace files (*.json)"));
    if (path.isEmpty()) return;
    TraceInfo info;
    info.scene = session_.name();
    info.accel = std::string(accelKindName(session_.kind()));
    info.what = session_.is2D() ? "ray" : "pixel";
    try {
        writeFileAtomic(path.toStdString(), traceToJson(session_.log(), info));
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Cannot save"), QString::fromUtf8(e.what()));
    }
}

}  // namespace raystep::gui
