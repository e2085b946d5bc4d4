// Compare mode from the window (compare_launcher.h).
#include "compare_launcher.h"

#include "compare_chooser.h"
#include "compare_window.h"
#include "image_render.h"
#include "lesson_panel.h"

#include "course/lesson.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace raystep::gui {

CompareLauncher::CompareLauncher(QMainWindow& window, Session& session, TaskRunner& runner,
                                 const std::uint64_t& generation, LessonPanel* lesson, Hooks hooks)
    : QObject(&window),
      window_(window),
      session_(session),
      runner_(runner),
      generation_(generation),
      lesson_(lesson),
      hooks_(std::move(hooks)) {
    // C at once (a tree's splits, or the slides' grid, kd-tree and BVH); Shift+C asks which.
    compare_ = new QAction(tr("&Compare on this ray"), &window_);
    compare_->setShortcut(QKeySequence(Qt::Key_C));
    connect(compare_, &QAction::triggered, this, [this] { open(); });
    chooseCompare_ = new QAction(tr("Compare &structures..."), &window_);
    chooseCompare_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_C));
    connect(chooseCompare_, &QAction::triggered, this, [this] { choose(); });
    // The compare window replays whole traces: it closes when an exercise comes to hold the
    // replay (a lesson opened, a mode changed), and with its scene (close()).
    connect(&session_, &Session::limitChanged, this, [this] {
        if (compareWindow_ && (session_.held() || heldAmong(compareWindow_->choices())))
            compareWindow_->close();
        if (chooser_ && session_.held()) chooser_->reject();
    });
}

void CompareLauncher::addViewItems(QMenu* view) {
    view->addActions({compare_, chooseCompare_});
}

void CompareLauncher::close() {
    if (compareWindow_) compareWindow_->close();
}

void CompareLauncher::open() {
    open(defaultComparison(session_.kind()));
}

std::optional<std::pair<int, StructureChoice>> CompareLauncher::heldAmong(
    const std::vector<StructureChoice>& choices) const {
    // Each column replays its whole trace and counts it: not one that an unsolved exercise of
    // the lesson asks about (lesson 10 asks each structure's tests), whichever is shown now.
    for (const StructureChoice& c : choices) {
        LessonSetup setup{c.kind, session_.options()};
        if (c.split) setup.options.setSplit(*c.split);
        if (const auto held = lesson_->heldBy(setup.key())) return std::pair(held->first, c);
    }
    return std::nullopt;
}

bool CompareLauncher::refusedWhileAnyHeld(const std::vector<StructureChoice>& choices) {
    if (hooks_.refusedWhileHeld(tr("compare structures on the ray"))) return true;
    const auto held = heldAmong(choices);
    if (!held) return false;
    const QString why = tr("Exercise %1 asks about the %2: answer it first, or put it away, to "
                           "compare structures on the ray.")
                            .arg(held->first + 1)
                            .arg(choiceLabel(held->second));
    lesson_->showHeldNote(why);
    window_.statusBar()->showMessage(why, 10000);
    return true;
}

void CompareLauncher::choose() {
    if (!session_.hasScene()) {
        window_.statusBar()->showMessage(tr("No scene is open: nothing to compare."));
        return;
    }
    if (hooks_.refusedWhileHeld(tr("compare structures on the ray"))) return;
    if (chooser_) {
        chooser_->raise();
        return;
    }
    // Opened on what was compared last, else on the comparison made for the structure shown;
    // not modal by exec() (no nested event loop: architecture.md), window-modal by open().
    const auto last = CompareChooser::fromText(QSettings().value("compare/choice").toString());
    auto* chooser = new CompareChooser(last ? *last : defaultComparison(session_.kind()), &window_);
    chooser->setAttribute(Qt::WA_DeleteOnClose);
    connect(chooser, &QDialog::accepted, this, [this, chooser] {
        QSettings().setValue("compare/choice", CompareChooser::toText(chooser->choices()));
        open(chooser->choices());
    });
    chooser_ = chooser;
    chooser->open();
}

CompareChooser* CompareLauncher::chooser() const {
    return chooser_.data();
}

void CompareLauncher::open(const std::vector<StructureChoice>& choices) {
    if (!session_.hasScene()) {
        window_.statusBar()->showMessage(tr("No scene is open: nothing to compare."));
        return;
    }
    if (choices.empty()) return;
    // Compare mode replays whole traces: not while an exercise holds them (quiz mode).
    if (refusedWhileAnyHeld(choices)) return;
    // 3D: the pixel being replayed, in the image it is a pixel of (its event says: clicked on
    // the image, or a lesson's), else the image's centre.
    CompareWindow::Pixel pixel{ImageRender::kWidth / 2, ImageRender::kHeight / 2,
                               ImageRender::kWidth, ImageRender::kHeight};
    for (const Event& e : session_.log().events())
        if (const auto* p = std::get_if<PixelResult>(&e)) {
            pixel = {static_cast<int>(p->x), static_cast<int>(p->y), ImageRender::kWidth,
                     ImageRender::kHeight};
            if (p->width > 0 && p->height > 0)  // 0: a trace written before the frame was
                pixel.width = static_cast<int>(p->width),
                pixel.height = static_cast<int>(p->height);
        }
    QStringList names;
    for (const StructureChoice& c : choices) names << choiceLabel(c);
    // Several structures over a big mesh take seconds: built in the background, with Cancel.
    const std::uint64_t generation = generation_;
    runner_.start<CompareWindow::Prepared>(
        TaskKind::Compare, tr("Building %1...").arg(names.join(QStringLiteral(", "))),
        [scene = session_.sceneRef(), choices](const ProgressFn& progress) {
            return CompareWindow::prepare(scene, choices, progress);
        },
        [this, generation, pixel, choices](CompareWindow::Prepared&& prepared,
                                           const TaskOutcome& outcome) {
            if (outcome.superseded || generation != generation_) return;
            // An exercise may have come to hold the replay while the structures were built.
            if (refusedWhileAnyHeld(choices)) return;
            if (outcome.cancelled) {
                window_.statusBar()->showMessage(tr("Compare cancelled"));
                return;
            }
            if (outcome.error) {
                // Without a nested event loop: the window goes on.
                auto* box = new QMessageBox(QMessageBox::Warning, tr("Compare"),
                                            outcome.errorText(), QMessageBox::Ok, &window_);
                box->setAttribute(Qt::WA_DeleteOnClose);
                box->open();
                return;
            }
            // A window of its own that closes with this one.
            if (compareWindow_) compareWindow_->close();
            auto* compare = new CompareWindow(std::move(prepared), pixel, &window_);
            compare->setWindowFlag(Qt::Window);
            compare->setAttribute(Qt::WA_DeleteOnClose);
            compare->placeOnScreen(hooks_.fitToScreen(QSize(1400, 800)),
                                   hooks_.fitToScreen(QSize(1 << 16, 1 << 16)));
            // The window's own keys work there too: Quit, the zoom, the keyboard shortcuts.
            compare->addActions(hooks_.windowKeys);
            compare->show();
            compareWindow_ = compare;
        });
}

CompareWindow* CompareLauncher::window() const {
    return compareWindow_.data();
}

}  // namespace raystep::gui
