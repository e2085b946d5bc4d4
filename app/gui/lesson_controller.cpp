// The lesson controller: a lesson's steps, exercises, progress and sweep, and the help texts.
#include "lesson_controller.h"
#include "file_dialogs.h"

#include "course/palette.h"

#include "event_list.h"
#include "language.h"
#include "lesson_panel.h"
#include "vtk_view.h"

#include <QDate>
#include <QFile>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>

namespace raystep::gui {

LessonController::Opened LessonController::prepare(const Lesson& lesson,
                                                   const ProgressFn& progress) {
    AccelOptions options = lesson.options;
    options.setProgress(progress);
    Opened o;
    if (lesson.sceneText.empty()) {
        o.scene = Session::prepare(lessonScenePath(lesson), lesson.accel, options);
    } else {
        // An inline scene (a practice's): loaded from the lesson, prepared as a file's would be,
        // named by the lesson's id (which `practice make` takes back) rather than a file's name.
        o.scene = std::visit(
            [&](auto s) {
                s.name = lesson.id;
                return Session::prepare(std::move(s), lesson.accel, options);
            },
            loadLessonScene(lesson));
    }
    // A lesson that traces a 2D ray of its own shows its scene with that ray as the example ray:
    // the handles, a live edit, a live control, R and compare all start from the ray replayed.
    if (const Scene2D* s2 = std::get_if<Scene2D>(&o.scene->scene);
        s2 && lesson.trace.kind == LessonTrace::Kind::Ray2D) {
        Scene2D withRay = *s2;
        withRay.exampleRay = lesson.trace.ray;
        withRay.name = o.scene->name;
        o.scene = Session::prepare(std::move(withRay), lesson.accel, options);
    }
    o.trace = recordLessonTrace(lesson, o.scene->scene,
                                o.scene->structure.in3D ? &*o.scene->structure.in3D : nullptr,
                                o.scene->structure.in2D ? &*o.scene->structure.in2D : nullptr);
    o.lesson = lesson;
    addStepNotes(o.lesson, o.scene->scene,
                 o.scene->structure.in2D ? &*o.scene->structure.in2D : nullptr);
    // Every other structure a step or an exercise names, built here in the background over the
    // same scene (as the structure chooser rebuilds), with the lesson's trace through it.
    const std::vector<LessonSetup> setups = lesson.setups();
    for (std::size_t i = 1; i < setups.size(); ++i) {
        AccelOptions so = setups[i].options;
        so.setProgress(progress);
        Structure st;
        st.scene = Session::rebuild(o.scene, setups[i].accel, so);
        st.trace =
            recordLessonTrace(lesson, setups[i], st.scene->scene,
                              st.scene->structure.in3D ? &*st.scene->structure.in3D : nullptr,
                              st.scene->structure.in2D ? &*st.scene->structure.in2D : nullptr);
        o.others[setups[i].key()] = std::move(st);
    }
    return o;
}

LogKind LessonController::logKind(const Lesson& lesson) {
    return lesson.trace.kind == LessonTrace::Kind::Build ? LogKind::Build : LogKind::Lesson;
}

LessonController::LessonController(QMainWindow& window, Session& session, TaskRunner& runner,
                                   const std::uint64_t& generation, LessonPanel* panel,
                                   EventList* events, VtkView* view3D)
    : QObject(&window),
      window_(window),
      session_(session),
      runner_(runner),
      generation_(generation),
      lesson_(panel),
      events_(events),
      view3D_(view3D) {
    // The student's progress: one JSON file under the user's data folder, replaced atomically;
    // one that cannot be read is kept aside, never written over (progress_store.h).
    progressPath_ =
        QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/progress.json";
    store_ = ProgressStore(progressPath_);
    ProgressStore::Unreadable unreadable;
    studentProgress_ = store_.open(unreadable);
    saveNote_ = new QLabel;
    saveNote_->setObjectName("progressNote");
    saveNote_->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold"));
    saveNote_->setWordWrap(false);
    saveNote_->hide();
    window_.statusBar()->addPermanentWidget(saveNote_);
    if (!unreadable.why.isEmpty()) {
        tellUnreadable(unreadable);
        if (unreadable.keptAs.isEmpty())
            showSaveProblem(tr("%1 could not be read and cannot be moved aside (%2); it is not "
                               "written over")
                                .arg(progressPath_, unreadable.moveProblem));
    }

    // The lesson panel asks; the controller moves the replay and saves the progress.
    connect(lesson_, &LessonPanel::stepShown, this, [this](int i) { applyStep(i); });
    connect(lesson_, &LessonPanel::lessonTraceRequested, this, [this] { backToLesson(); });
    connect(lesson_, &LessonPanel::exerciseShown, this, [this](int i) {
        // While exploring the exercise waits: only "Back to the lesson" returns to its trace.
        if (lesson_->exploring()) return;
        // An exercise on its own structure shows it: its answer is read from that trace.
        const Exercise& ex = lesson_->lesson().exercises[std::size_t(i)];
        showLessonTrace(ex.setup);
        updateQuizLimit();
        const auto at = resolvePosition(ex.at, session_.log());
        if (at) session_.setCursor(*at);
    });
    connect(lesson_, &LessonPanel::compareRequested, this, &LessonController::compareRequested);
    connect(lesson_, &LessonPanel::quizChanged, this, [this] { updateQuizLimit(); });
    connect(lesson_, &LessonPanel::answered, this, [this] {
        if (lesson_->hasLesson()) emit answerRecorded(lesson_->lesson());
        saveProgress();
    });
    connect(lesson_, &LessonPanel::sweepRequested, this, [this] { runSweep(); });
    connect(&session_, &Session::logChanged, this, [this] { showReplayText(); });
    // The exploring note says whether a hold hides the explored trace: it follows the hold.
    connect(&session_, &Session::limitChanged, this, [this] { showReplayText(); });
}

void LessonController::replaceLesson() {
    replacing_ = true;
    session_.setLimit(nullptr, std::nullopt);
    session_.setHideAhead(false);
}

void LessonController::show(const Lesson& lesson, const LogRef& trace,
                            std::map<std::string, Structure> others) {
    // The panel records answers into this lesson's progress (std::map entries do not move) and
    // grades them against its own share of the trace.
    replacing_ = false;
    lessonScene_ = session_.sceneRef();
    others_ = std::move(others);
    currentKey_ = lesson.setup().key();
    std::map<std::string, LogRef> logs;
    for (const auto& [key, st] : others_) logs[key] = st.trace;
    lesson_->showLesson(lesson, trace, &studentProgress_.lessons[lesson.id], std::move(logs));
    if (trace)
        if (const auto kind = lessonEventKind(lesson, *trace)) emit jumpKindSuggested(*kind);
    applyStep(lesson_->step());
    emit lessonShown(lesson_->lesson());
}

std::optional<std::size_t> LessonController::lessonEventKind(const Lesson& lesson,
                                                             const EventLog& log) {
    std::vector<const ReplayPosition*> positions;
    for (const LessonStep& s : lesson.steps) positions.push_back(&s.at);
    for (const Exercise& e : lesson.exercises) positions.push_back(&e.at);
    for (const ReplayPosition* at : positions) {
        if (at->mode != ReplayPosition::Mode::AfterEvent &&
            at->mode != ReplayPosition::Mode::BeforeEvent)
            continue;
        // A kind the trace holds once (the DDA's set-up) is no place for N to jump between.
        int seen = 0;
        for (const Event& e : log.events())
            if (e.index() == at->eventKind && ++seen > 1) return at->eventKind;
    }
    return std::nullopt;
}

void LessonController::backToLesson() {
    if (!lesson_->hasLesson()) return;
    // Where the student was in the lesson: the open exercise's position, else the step's; each
    // on its own structure (the structure chooser's pick goes).
    if (lesson_->exerciseOpen()) {
        const Exercise& ex = lesson_->lesson().exercises[lesson_->exercise()];
        showLessonTrace(ex.setup);
        const auto at = resolvePosition(ex.at, session_.log());
        if (at) session_.setCursor(*at);
        updateQuizLimit();
        if (!lesson_->lesson().steps.empty())
            events_->setFilter(
                QString::fromStdString(lesson_->lesson().steps[lesson_->step()].filter));
    } else {
        applyStep(lesson_->step());
    }
}

void LessonController::updateQuizLimit() {
    // The hold is on the structure shown: its exercises' positions are in its trace.
    const LogRef& log = lesson_->hasLesson() && others_.count(currentKey_)
                            ? others_.at(currentKey_).trace
                            : lesson_->lessonLog();
    // Presenting: a question to the room lists and counts nothing past the cursor.
    session_.setHideAhead(lesson_->asksTheRoom());
    if (!lesson_->hasLesson() || !log) {
        session_.setLimit(nullptr, std::nullopt);
        return;
    }
    // Every unsolved exercise holds the replay at its own position, open or not: what lies
    // after it holds its answer (course/exercise.h; none for the kinds whose answer is not in
    // the trace). Otherwise a step, or the list, shows a later exercise's answer first.
    std::optional<std::size_t> limit;
    for (const int i : lesson_->heldExercises()) {
        const Exercise& ex = lesson_->lesson().exercises[std::size_t(i)];
        if (lesson_->lesson().setupOf(ex.setup).key() != currentKey_) continue;
        if (const auto at = quizLimit(ex, *log)) limit = limit ? std::min(*limit, *at) : *at;
    }
    session_.setLimit(log, limit);
}

void LessonController::applyStep(int index) {
    if (!lesson_->hasLesson() || lesson_->lesson().steps.empty()) {
        session_.setCursor(session_.size());
        return;
    }
    const LessonStep& step = lesson_->lesson().steps[index];
    // A step on its own structure shows it; one without goes back to the lesson's.
    showLessonTrace(step.setup);
    updateQuizLimit();
    if (const auto at = resolvePosition(step.at, session_.log())) session_.setCursor(*at);
    events_->setFilter(QString::fromStdString(step.filter));
    if (step.camera)
        view3D_->orbit(step.camera->azimuth, step.camera->elevation, step.camera->zoom);
    else
        view3D_->frameBesideEye();
    studentProgress_.lessons[lesson_->lesson().id].step = index;
    saveProgress();
}

SceneRef LessonController::sceneOf(const std::string& key) const {
    const auto it = others_.find(key);
    return it != others_.end() ? it->second.scene : lessonScene_;
}

bool LessonController::showsLessonScene() const {
    if (session_.sceneRef() == lessonScene_) return true;
    return std::any_of(others_.begin(), others_.end(),
                       [&](const auto& o) { return o.second.scene == session_.sceneRef(); });
}

void LessonController::showLessonTrace(const std::optional<LessonSetup>& setup) {
    if (!lesson_->hasLesson() || !lesson_->lessonLog()) return;
    currentKey_ = lesson_->lesson().setupOf(setup).key();
    // The structure first (as the structure chooser switches it; built when the lesson opened),
    // then its trace: the view draws the trace over the structure it was recorded through.
    const SceneRef scene = sceneOf(currentKey_);
    if (scene && session_.sceneRef() != scene) emit lessonSceneRequested(scene);
    const LogRef& log = lesson_->logOf(setup);
    if (session_.logRef() == log) return;
    session_.showLog(log, logKind(lesson_->lesson()));
}

void LessonController::saveProgress() {
    ProgressStore::Unreadable unreadable;
    const QString why = store_.save(studentProgress_, unreadable);
    if (!unreadable.why.isEmpty()) tellUnreadable(unreadable);
    // Unsaved answers stay in memory; the next answer tries again, and quitting asks.
    unsaved_ = !why.isEmpty();
    showSaveProblem(why);
}

void LessonController::showSaveProblem(const QString& why) {
    saveProblem_ = why;
    if (why.isEmpty()) {
        saveNote_->hide();
        return;
    }
    saveNote_->setText(tr("Progress not saved: %1").arg(why));
    saveNote_->setToolTip(
        tr("Your answers are kept while raystep is open; it tries to save them again at your "
           "next answer, and asks before quitting."));
    saveNote_->show();
}

void LessonController::tellUnreadable(const ProgressStore::Unreadable& u) {
    const QString text =
        u.keptAs.isEmpty()
            ? tr("Your progress file could not be read:\n\n%1\n\nIt could not be moved aside "
                 "either (%2), so raystep leaves it as it is and does not write over it. Your "
                 "answers in this window are kept in memory only.")
                  .arg(u.why, u.moveProblem)
            : tr("Your progress file could not be read:\n\n%1\n\nIt was kept as %2 (nothing "
                 "in it is lost); raystep starts a new progress file.")
                  .arg(u.why, u.keptAs);
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Progress file unreadable"), text,
                                QMessageBox::Ok, &window_);
    box->setObjectName("progressUnreadable");
    box->setAttribute(Qt::WA_DeleteOnClose);
    // Once the window is up (at start the controller is made before it is shown).
    QTimer::singleShot(0, box, [box] { box->open(); });
}

bool LessonController::allowClose() {
    if (!unsaved_ || quitUnsaved_) return true;
    saveProgress();  // one more try: the disk may have room now
    if (!unsaved_) return true;
    auto* box = new QMessageBox(
        QMessageBox::Warning, tr("Progress not saved"),
        tr("Your latest answers could not be saved: %1\n\nQuit anyway and lose them?")
            .arg(saveProblem_),
        QMessageBox::NoButton, &window_);
    box->setObjectName("unsavedProgress");
    QPushButton* quit = box->addButton(tr("Quit without saving"), QMessageBox::DestructiveRole);
    QPushButton* stay = box->addButton(tr("Keep raystep open"), QMessageBox::RejectRole);
    box->setDefaultButton(stay);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, quit] {
        if (box->clickedButton() != quit) return;
        quitUnsaved_ = true;
        window_.close();
    });
    box->open();
    return false;
}

void LessonController::exportProgressReport() {
    // The report names its student and its date (the name is remembered for the next export).
    QSettings settings;
    bool named = false;
    const QString student = QInputDialog::getText(
        &window_, tr("Export progress report"), tr("Your name, for the report:"), QLineEdit::Normal,
        settings.value(QStringLiteral("report/student")).toString(), &named);
    if (!named) return;
    settings.setValue(QStringLiteral("report/student"), student);
    const ReportHeader header{student.trimmed().toStdString(),
                              QDate::currentDate().toString(Qt::ISODate).toStdString()};
    const QString path = saveFileName(&window_, tr("Export progress report"), tr("Markdown (*.md)"),
                                      nullptr, QStringLiteral("raystep-progress.md"));
    if (path.isEmpty()) return;
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) ||
        f.write(QByteArray::fromStdString(
            progressReport(studentProgress_, builtinLessons(), lang_, header))) < 0 ||
        !f.commit())
        QMessageBox::warning(&window_, tr("Cannot save"), tr("Could not write %1").arg(path));
}

void LessonController::runSweep() {
    if (!lesson_->hasLesson() || !lesson_->lesson().sweep || !session_.hasScene()) return;
    const GridSweepSpec spec = *lesson_->lesson().sweep;
    const std::uint64_t generation = generation_;
    const LogRef lessonLog = lesson_->lessonLog();
    runner_.start<std::vector<GridSweepRow>>(
        TaskKind::Sweep,
        tr("Tracing the same rays at %1 grid resolutions...").arg(spec.resolutions.size()),
        [ref = session_.sceneRef(), spec](const ProgressFn& progress) {
            return runGridSweep(ref->scene, spec, progress);
        },
        [this, generation, lessonLog](std::vector<GridSweepRow>&& rows,
                                      const TaskOutcome& outcome) {
            // Only for the lesson that asked.
            if (outcome.superseded || generation != generation_ ||
                lesson_->lessonLog() != lessonLog)
                return;
            if (outcome.ok())
                lesson_->showSweep(rows);
            else
                window_.statusBar()->showMessage(outcome.cancelled ? tr("Sweep cancelled")
                                                                   : tr("The sweep failed"));
        });
}

void LessonController::setLanguage(Language lang) {
    lang_ = lang;
    lesson_->setLanguage(lang);
    lesson_->setLessons(builtinLessons());
    fillLessonsMenu();
}

void LessonController::setLessonsMenu(QMenu* menu) {
    lessonsMenu_ = menu;
    fillLessonsMenu();
}

void LessonController::fillLessonsMenu() {
    lessonsMenu_->clear();
    for (const Lesson& l : builtinLessons()) {
        const QString id = QString::fromStdString(l.id);
        lessonsMenu_->addAction(
            QStringLiteral("&%1. %2").arg(l.number).arg(QString::fromStdString(l.title.in(lang_))),
            this, [this, id] { emit lessonRequested(id); });
    }
}

void LessonController::showSceneIntro() {
    const bool twoD = session_.is2D();
    lesson_->showText(
        lectureText(twoD ? QStringLiteral("scene_2d") : QStringLiteral("scene_3d"))
            .arg(QString::fromStdString(session_.name()),
                 QString::fromStdString(sceneDescription(twoD ? session_.scene2D()->description
                                                              : session_.scene3D()->description))));
    emit lessonClosed();
}

void LessonController::showReplayText() {
    // The new lesson's scene and trace, not something the old lesson explores.
    if (replacing_) return;
    if (lesson_->hasLesson()) {
        const QString exploring = replayDescription();
        // The step's filter is about the lesson's trace: exploring shows every event (going
        // back to the lesson sets the step's filter again).
        if (!exploring.isEmpty() && !lesson_->exploring()) events_->setFilter({});
        lesson_->setReplayNote(exploring, session_.held());
    } else if (session_.showingBuild()) {
        lesson_->showText(
            lectureText(QStringLiteral("building")).arg(structureName(session_.kind())));
    }
}

QString LessonController::replayDescription() const {
    if (!lesson_->hasLesson()) return {};
    // The structure chooser's pick, or a live edit: the lesson's trace is about another scene.
    if (lessonScene_ && !showsLessonScene())
        return (session_.kind() != lessonScene_->kind
                    ? tr("the lesson's scene with another structure (%1)")
                    : tr("the lesson's scene, changed live (%1)"))
            .arg(structureName(session_.kind()));
    if (lesson_->isLessonLog(session_.logRef())) return {};
    switch (session_.logKind()) {
        case LogKind::Pixel:
            for (auto it = session_.log().events().rbegin(); it != session_.log().events().rend();
                 ++it)
                if (const auto* p = std::get_if<PixelResult>(&*it))
                    return tr("the ray tree of pixel (%1, %2)").arg(p->x).arg(p->y);
            return tr("a pixel's ray tree");
        case LogKind::ExampleRay:
            return tr("the scene's example ray");
        case LogKind::Build:
            return tr("the construction of the %1").arg(structureName(session_.kind()));
        default:
            return tr("another trace");
    }
}

QString LessonController::lectureText(const QString& name) const {
    // texts/<language>/<name>.md, compiled in as a Qt resource (CMakeLists.txt); a language
    // without its own pages shows the English ones.
    const std::string_view code = languageCode(lang_);
    QFile f(QStringLiteral(":/texts/%1/%2.md")
                .arg(QString::fromUtf8(code.data(), static_cast<int>(code.size())), name));
    if (!f.exists()) f.setFileName(QStringLiteral(":/texts/en/%1.md").arg(name));
    if (!f.open(QIODevice::ReadOnly)) return {};
    // Colours by their palette names ({colour:chosen}), as in the lessons: named once.
    const auto text = expandColourNames(f.readAll().toStdString(), lang_, nullptr);
    return text ? QString::fromStdString(*text).trimmed() : QString();
}

}  // namespace raystep::gui
