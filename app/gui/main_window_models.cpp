// The window's structure chooser (brute force, grid, kd-tree, BVH; midpoint, median or SAH
// splits) and the status bar's structure: the structure a scene or model uses is always shown and
// chosen here, never inherited silently from a lesson. File > Save scene as writes the scene made
// around an opened model. The live controls build through here too.
#include "file_dialogs.h"
#include "main_window.h"

#include "image_render.h"
#include "image_view.h"
#include "language.h"
#include "scene_opener.h"

#include "raystep/base/file_error.h"
#include "raystep/render/image.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/model_import.h"

#include <QComboBox>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QToolBar>

#include <filesystem>

namespace raystep::gui {

void MainWindow::createStructureControls() {
    auto* bar = addToolBar(tr("Structure"));
    bar->setObjectName("structureToolBar");  // saveState/restoreState need a name
    structureBox_ = new QComboBox;
    structureBox_->setObjectName("structureChooser");
    for (const StructureInfo& s : structures())
        structureBox_->addItem(structureName(s.kind), static_cast<int>(s.kind));
    structureBox_->setToolTip(
        tr("The acceleration structure the scene is traced with; changing it builds it again"));
    splitBox_ = new QComboBox;
    splitBox_->setObjectName("splitChooser");
    for (const SplitMethod m : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah})
        splitBox_->addItem(splitName(m), static_cast<int>(m));
    splitBox_->setToolTip(tr("How the kd-tree or the BVH chooses its split planes"));
    bar->addWidget(new QLabel(tr("Structure:") + " "));
    bar->addWidget(structureBox_);
    bar->addSeparator();
    bar->addWidget(new QLabel(tr("Split:") + " "));
    bar->addWidget(splitBox_);
    // activated: the user's pick only (syncStructureControls sets them without it).
    const auto picked = [this] {
        changeStructure(static_cast<AccelKind>(structureBox_->currentData().toInt()),
                        static_cast<SplitMethod>(splitBox_->currentData().toInt()));
    };
    connect(structureBox_, &QComboBox::activated, this, picked);
    connect(splitBox_, &QComboBox::activated, this, picked);

    structureLabel_ = new QLabel;
    structureLabel_->setObjectName("structureStatus");
    statusBar()->insertPermanentWidget(0, structureLabel_);
    connect(&session_, &Session::sceneChanged, this, [this] { syncStructureControls(); });
    syncStructureControls();
}

void MainWindow::syncStructureControls() {
    const bool scene = session_.hasScene();
    const AccelKind kind = scene ? session_.kind() : openKind();
    const AccelOptions options = scene ? session_.options() : openOptions();
    const SplitMethod split = options.split(kind).value_or(options.kdtree.split);
    structureBox_->setCurrentIndex(structureBox_->findData(static_cast<int>(kind)));
    splitBox_->setCurrentIndex(splitBox_->findData(static_cast<int>(split)));
    splitBox_->setEnabled(hasSplit(kind));
    actions_.saveScene->setEnabled(scene && session_.scene3D() && isModelPath(session_.name()));
    if (!scene) {
        structureLabel_->clear();
        return;
    }
    const QString what = hasSplit(kind)
                             ? tr("%1, %2 splits").arg(structureName(kind), splitName(split))
                             : structureName(kind);
    const Scene* s3 = session_.scene3D();
    const std::size_t primitives = s3 ? s3->primitiveCount() : session_.scene2D()->primitiveCount();
    structureLabel_->setText(tr("Structure: %1 (%2 primitives)").arg(what).arg(primitives));
}

QString MainWindow::structureStatus() const {
    return structureLabel_->text();
}

AccelKind MainWindow::openKind() const {
    return chosenStructure_ ? chosenStructure_->first : AccelKind::KdTree;
}

AccelOptions MainWindow::openOptions() const {
    AccelOptions options;
    options.kdtree.split = options.bvh.split =
        chosenStructure_ ? chosenStructure_->second : SplitMethod::Sah;
    return options;
}

void MainWindow::changeStructure(AccelKind kind, SplitMethod split) {
    const Scene* scene = session_.scene3D();
    if (!testsEveryPrimitive(kind) || !scene || testsEveryPrimitive(session_.kind()) ||
        scene->primitiveCount() <= kBruteForceAsk)
        return buildChosenStructure(kind, split);
    // Asked first, without a nested event loop: the answer builds it, or keeps what is there.
    const std::size_t n = scene->primitiveCount();
    auto* box = new QMessageBox(
        QMessageBox::Warning, tr("Brute force on %1 primitives?").arg(n),
        tr("Brute force tests every ray against each of the %1 primitives: a pixel's trace "
           "records %2 tests or more, and the image takes a very long time (Cancel stops "
           "it). A grid, a kd-tree or a BVH tests a few dozen.")
            .arg(n)
            .arg(3 * n),
        QMessageBox::NoButton, this);
    box->setObjectName("bruteForceQuestion");
    QPushButton* go = box->addButton(tr("Use brute force"), QMessageBox::AcceptRole);
    QPushButton* keep = box->addButton(tr("Keep the %1").arg(structureName(session_.kind())),
                                       QMessageBox::RejectRole);
    box->setDefaultButton(keep);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, go, kind, split] {
        if (box->clickedButton() == go) {
            buildChosenStructure(kind, split);
            return;
        }
        syncStructureControls();  // back to what the scene uses
        statusBar()->showMessage(tr("Brute force not built: the structure stays as it was"));
        emit structureChanged(false, tr("brute force not chosen"));
    });
    box->open();
}

void MainWindow::buildChosenStructure(AccelKind kind, SplitMethod split) {
    chosenStructure_ = {kind, split};
    splitBox_->setEnabled(hasSplit(kind));
    AccelOptions options = session_.options();
    options.setSplit(split);
    applyStructure(kind, options);
}

void MainWindow::applyStructure(AccelKind kind, const AccelOptions& options) {
    if (!session_.hasScene()) {
        emit structureChanged(false, tr("No scene is open."));
        return;
    }
    if (session_.is2D()) {
        // A 2D scene is small: rebuilt at once, so a live control answers as it is moved.
        showLiveBuild([&] { return Session::rebuild(session_.sceneRef(), kind, options); });
        return;
    }
    const std::uint64_t generation = opener_->generation();
    const bool render = !imageView_->isHidden();
    const SplitMethod split = options.split(kind).value_or(options.kdtree.split);
    const QString what = hasSplit(kind)
                             ? tr("%1, %2 splits").arg(structureName(kind), splitName(split))
                             : structureName(kind);
    runner_.start<SceneRef>(
        TaskKind::Structure, tr("Building the %1...").arg(what),
        [ref = session_.sceneRef(), kind, options](const ProgressFn& progress) {
            AccelOptions o = options;
            o.setProgress(progress);
            return Session::rebuild(ref, kind, o);
        },
        [this, generation, render](SceneRef&& scene, const TaskOutcome& outcome) {
            if (outcome.superseded) return;
            // Another scene was opened meanwhile: this structure was for the old one.
            if (generation != opener_->generation()) {
                emit structureChanged(false, tr("another scene was opened"));
                return;
            }
            if (!outcome.ok()) {
                const QString why = outcome.cancelled ? tr("cancelled") : outcome.errorText();
                statusBar()->showMessage(tr("The structure was not built: %1").arg(why));
                syncStructureControls();  // back to what the scene uses
                emit structureChanged(false, why);
                return;
            }
            opener_->showScene(std::move(scene), render);
            statusBar()->showMessage(structureStatus());
            emit structureChanged(true, {});
        });
}

void MainWindow::applyLive(AccelKind kind, const AccelOptions& options) {
    const Scene2D* s2 = session_.scene2D();
    if (s2 && s2->gridRes && readsOption(kind, AccelOption::GridRes) && !options.grid.res) {
        // Lambda's grid asked for: the scene's own grid would win over it (buildAccelerator2D),
        // so the scene is shown without it.
        Scene2D copy = *s2;
        copy.gridRes.reset();
        showLiveBuild([&] { return Session::prepare(std::move(copy), kind, options); });
        return;
    }
    applyStructure(kind, options);
}

void MainWindow::showLiveBuild(const std::function<SceneRef()>& build) {
    try {
        showLive(build());
    } catch (const std::exception& e) {
        const QString why = QString::fromStdString(e.what());
        statusBar()->showMessage(tr("The structure was not built: %1").arg(why));
        syncStructureControls();
        emit structureChanged(false, why);
        return;
    }
    statusBar()->showMessage(structureStatus());
    emit structureChanged(true, {});
}

QString MainWindow::saveModelScene(const QString& path) {
    const Scene* scene = session_.scene3D();
    // sceneAroundModel puts the model's triangles first and the floor's two last.
    if (!scene || !isModelPath(session_.name()) || scene->triangles.size() < 2)
        return tr(
            "Only the scene made around a model (File > Open of an .obj, .ply, .stl, .gltf "
            "or .glb) is saved as a scene file");
    const std::filesystem::path json = path.toStdString();
    if (!path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        return tr("%1: the scene is written as a scene file; name it *.json").arg(path);
    const std::string meshName = json.stem().string() + ".mesh.obj";
    const std::string mesh = (json.parent_path() / meshName).string();
    // Nor any file the model refers to (a glTF's buffer, an OBJ's .mtl or texture).
    for (const std::string& input : inputFilesOf(session_.name()))
        for (const std::string& out : {mesh, json.string()})
            if (std::error_code ec;
                std::filesystem::is_regular_file(input, ec) && sameFile(out, input))
                return input == session_.name()
                           ? tr("%1: it would write over the model itself").arg(path)
                           : tr("%1: it would write over %2, which the model refers to")
                                 .arg(QString::fromStdString(out), QString::fromStdString(input));
    try {
        const SceneFiles files = sceneFilesFor(*scene, scene->triangles.size() - 2, meshName);
        writeFilesAtomic({{json.string(), files.sceneJson}, {mesh, files.meshObj}});
    } catch (const std::exception& e) {
        return QString::fromStdString(printable(e.what(), 4096));
    }
    return {};
}

void MainWindow::saveSceneDialog() {
    const QString path = saveFileName(this, tr("Save scene as"), tr("Scenes (*.json)"));
    if (path.isEmpty()) return;
    if (const QString problem = saveModelScene(path); !problem.isEmpty())
        QMessageBox::warning(this, tr("Cannot save"), problem);
    else
        statusBar()->showMessage(tr("Saved %1 and its mesh beside it").arg(path));
}

}  // namespace raystep::gui
