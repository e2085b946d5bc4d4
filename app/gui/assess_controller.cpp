// File > Open student trace: the trace read and assessed, the failed ray replayed as raystep runs
// it, the student's walk over it (2D view), their rows beside raystep's (board), the verdict.
#include "assess_controller.h"

#include "board_table.h"
#include "file_dialogs.h"
#include "language.h"
#include "view2d.h"

#include "raystep/base/file_error.h"
#include "raystep/base/format.h"

#include <QAction>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

#include <algorithm>
#include <cmath>
#include <set>

namespace raystep::gui {

namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

/// The sign a differing cell of the student's carries on the board (and in its copies).
const std::string kDiffers = "\u2260 ";

std::string tupleText(const std::array<long long, 3>& c, int dims, Language lang) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i)
        s += (i ? std::string(listSeparator(lang)) : "") + std::to_string(c[i]);
    return s + ")";
}

std::string tMaxText(const std::array<double, 3>& t, int dims, Language lang) {
    std::string s = "(";
    for (int i = 0; i < dims; ++i)
        s += (i ? std::string(listSeparator(lang)) : "") + formatNumber(t[i]);
    return s + ")";
}

/// As the assessor compares a tMax: to a relative 1e-9, infinity (parallel) only to itself.
bool sameT(double a, double b) {
    if (std::isinf(a) || std::isinf(b)) return a == b;
    return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

std::string idsText(const std::vector<std::uint32_t>& ids) {
    std::string s;
    for (const std::uint32_t id : ids) s += (s.empty() ? "" : ", ") + std::to_string(id);
    return s;
}

/// One step of the student's walk: the cell or node logged, and what they logged with it.
struct StudentStep {
    const StudentRecord* walk = nullptr;
    std::vector<std::uint32_t> tests;
};

/// The board's columns of the student's ray beside raystep's run of it (reference).
BoardBeside besideOf(const StudentRay& ray, const ReferenceRay& ref, Language lang) {
    const auto walkKind = ref.cells ? StudentRecordKind::Cell : StudentRecordKind::Node;
    std::vector<StudentStep> steps;
    bool tMaxLogged = false, testsLogged = false;
    for (const StudentRecord& r : ray.records) {
        if (r.kind == walkKind) {
            steps.push_back({&r, {}});
            tMaxLogged = tMaxLogged || r.tMax.has_value();
        } else if (r.kind == StudentRecordKind::Test) {
            testsLogged = true;
            if (!steps.empty()) steps.back().tests.push_back(r.id);
        }
    }
    std::vector<const ReferenceUnit*> units;
    for (const ReferenceUnit& u : ref.units)
        if (u.kind != ReferenceUnit::Kind::None) units.push_back(&u);

    BoardBeside b;
    b.header.push_back(
        (ref.cells ? AssessController::tr("your cell") : AssessController::tr("your node"))
            .toStdString());
    if (tMaxLogged) b.header.push_back(AssessController::tr("your tMax").toStdString());
    if (testsLogged) b.header.push_back(AssessController::tr("your tests").toStdString());
    const int dims = ray.dims;
    const std::size_t n = std::max(steps.size(), units.size());
    for (std::size_t k = 0; k < n; ++k) {
        const StudentStep* s = k < steps.size() ? &steps[k] : nullptr;
        const ReferenceUnit* u = k < units.size() ? units[k] : nullptr;
        std::vector<std::string> cells;
        std::vector<bool> differs;
        const auto add = [&](std::string text, bool differ) {
            cells.push_back(differ ? kDiffers + (text.empty() ? "\u2014" : text) : std::move(text));
            differs.push_back(differ);
        };
        // The step itself: a student who stopped early has none where raystep goes on.
        if (!s) {
            add("", true);
        } else if (ref.cells) {
            bool same = u != nullptr;
            for (int i = 0; same && i < dims; ++i) same = s->walk->cell[i] == u->cell[i];
            add(tupleText(s->walk->cell, dims, lang), !same);
        } else {
            add(std::to_string(s->walk->id), !u || u->node != s->walk->id);
        }
        if (tMaxLogged) {
            if (s && s->walk->tMax) {
                bool same = u != nullptr;
                for (int i = 0; same && i < dims; ++i)
                    same = sameT((*s->walk->tMax)[i], u->tMax[i]);
                add(tMaxText(*s->walk->tMax, dims, lang), !same);
            } else {
                add("", false);  // not logged here: not checked
            }
        }
        if (testsLogged) {
            // A set per cell, as the assessor compares them (the order inside is the student's).
            const std::vector<std::uint32_t> theirs = s ? s->tests : std::vector<std::uint32_t>{};
            const std::set<std::uint32_t> yours(theirs.begin(), theirs.end());
            const std::set<std::uint32_t> raystep =
                u ? std::set<std::uint32_t>(u->tests.begin(), u->tests.end())
                  : std::set<std::uint32_t>{};
            add(idsText(theirs), s && yours != raystep);
        }
        b.rows.push_back(std::move(cells));
        b.differs.push_back(std::move(differs));
    }
    return b;
}

/// The walk as the 2D view draws it over raystep's.
StudentWalk walkOf(const StudentRay& ray, const ReferenceRay& ref) {
    StudentWalk w;
    for (const StudentRecord& r : ray.records) {
        if (ref.cells && r.kind == StudentRecordKind::Cell)
            w.cells.push_back(
                {std::int32_t(r.cell[0]), std::int32_t(r.cell[1]), std::int32_t(r.cell[2])});
        else if (!ref.cells && r.kind == StudentRecordKind::Node)
            w.nodes.push_back(r.id);
    }
    return w;
}

}  // namespace

AssessController::AssessController(QMainWindow& window, Session& session, View2D* view,
                                   BoardTable* board, Hooks hooks)
    : QObject(&window),
      window_(window),
      session_(session),
      view_(view),
      board_(board),
      hooks_(std::move(hooks)) {
    open_ = new QAction(tr("Open stu&dent trace..."), &window_);
    open_->setObjectName("openStudentTrace");
    open_->setStatusTip(
        tr("Check a student's own DDA or tree walk (JSON Lines) against raystep's, on the open "
           "scene's structure"));
    connect(open_, &QAction::triggered, this, [this] { dialog(); });

    // The bar over the views: which file, how it scored, which of its rays, and the verdict.
    bar_ = new QWidget;
    bar_->setObjectName("assessBar");
    bar_->setStyleSheet(QStringLiteral("#assessBar { background: #e8f1fb; }"));
    auto* grid = new QGridLayout(bar_);
    grid->setContentsMargins(6, 3, 6, 3);
    grid->setVerticalSpacing(2);
    title_ = new QLabel;
    title_->setObjectName("assessTitle");
    rays_ = new QComboBox;
    rays_->setObjectName("assessRay");
    rays_->setToolTip(tr("The ray of the student's trace shown"));
    closeButton_ = new QPushButton(tr("Close"));
    closeButton_->setObjectName("assessClose");
    closeButton_->setToolTip(tr("Close the student's trace (the replay stays)"));
    verdict_ = new QLabel;
    verdict_->setObjectName("assessVerdict");
    verdict_->setWordWrap(true);
    verdict_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    grid->addWidget(title_, 0, 0);
    grid->addWidget(rays_, 0, 1);
    grid->addWidget(closeButton_, 0, 2);
    grid->addWidget(verdict_, 1, 0, 1, 3);
    grid->setColumnStretch(0, 1);
    bar_->hide();
    connect(rays_, &QComboBox::activated, this, [this](int i) { showRay(i); });
    connect(closeButton_, &QPushButton::clicked, this, [this] { close(); });

    // What it was checked against is gone: another scene or structure (a live edit included).
    connect(&session_, &Session::sceneChanged, this, [this] {
        if (scene_ && session_.sceneRef() != scene_) close();
        syncEnabled();
    });
    // Another trace replayed (R, B, a pixel, back to the lesson): the student's walk is not of it.
    connect(&session_, &Session::logChanged, this, [this] {
        if (shownLog_ && session_.logRef() != shownLog_) close();
    });
    syncEnabled();
}

AssessController::~AssessController() = default;

void AssessController::addFileItems(QMenu* file) {
    file->addAction(open_);
}

void AssessController::syncEnabled() {
    // Every scene is shown with a structure built over it: its walk is what a trace is checked on.
    open_->setEnabled(session_.hasScene());
}

void AssessController::dialog() {
    const QString path =
        openFileName(&window_, tr("Open student trace"),
                     tr("Student traces (*.jsonl *.json *.txt)") + ";;" + tr("All files (*)"));
    if (!path.isEmpty()) open(path);
}

QString AssessController::open(const QString& path, bool quiet) {
    if (!session_.hasScene()) return tr("No scene is open.");
    if (hooks_.refusedWhileHeld && hooks_.refusedWhileHeld(tr("open a student trace")))
        return tr("An exercise holds the replay.");
    const SceneRef scene = session_.sceneRef();
    std::optional<StudentTrace> trace;
    try {
        trace = loadStudentTrace(path.toStdString(), session_.is2D() ? 2 : 3);
    } catch (const std::exception& e) {
        // FileError names the file, the line and the key; nothing shown changes.
        const QString problem = q(printable(e.what(), 4096));
        if (!quiet) {
            // Window-modal, no nested event loop: the window goes on painting behind it.
            auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open the student trace"),
                                        problem, QMessageBox::Ok, &window_);
            box->setObjectName("assessError");
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->open();
        }
        window_.statusBar()->showMessage(problem, 10000);
        return problem;
    }
    // A few rays of a lecture's scene: assessed in milliseconds, so on the GUI thread.
    auto reference =
        std::make_unique<Reference>(Reference::structure(scene->structure, scene->kind));
    Assessment a = assess(*trace, *reference, interfaceLanguage());
    close();
    scene_ = scene;
    trace_ = std::move(trace);
    reference_ = std::move(reference);
    assessment_ = std::move(a);

    rays_->clear();
    for (const RayVerdict& v : assessment_->rays)
        rays_->addItem(
            v.passed
                ? tr("ray %1: passed").arg(v.ray)
                : tr("ray %1: failed at step %2").arg(v.ray).arg(std::max(v.divergence->index, 0)));
    rays_->setVisible(assessment_->rays.size() > 1);
    const QString file = QString::fromStdString(trace_->file).section(QLatin1Char('/'), -1);
    title_->setText(tr("Student trace %1: %2 of %3 rays passed")
                        .arg(file)
                        .arg(assessment_->passed())
                        .arg(assessment_->rays.size()));
    bar_->show();
    // The ray they got wrong first; all passed: the first.
    int first = 0;
    for (const RayVerdict& v : assessment_->rays)
        if (!v.passed) {
            first = v.ray;
            break;
        }
    showRay(first);
    return {};
}

void AssessController::showRay(int ray) {
    if (!assessment_ || ray < 0 || ray >= int(assessment_->rays.size())) return;
    const RayVerdict& v = assessment_->rays[std::size_t(ray)];
    const StudentRay& sr = trace_->rays[std::size_t(ray)];
    const Language lang = interfaceLanguage();
    // raystep's own run of the student's ray, replayed as any recorded ray.
    auto log = std::make_shared<const EventLog>(reference_->record(sr));
    shownLog_ = log;
    shownRay_ = ray;
    StudentWalk walk = walkOf(sr, v.reference);
    walk.log = log;
    BoardBeside beside = besideOf(sr, v.reference, lang);
    beside.log = log;
    // The assessor's first divergence: the view, the board and the replay's jump show the same.
    if (v.divergence) {
        walk.divergent = std::size_t(std::max(v.divergence->index, 0));
        beside.divergent = walk.divergent;
    }
    beside.caption =
        v.passed ? tr("Ray %1 of the student's trace beside raystep's: they agree.").arg(ray)
                 : tr("Ray %1 of the student's trace beside raystep's: %2 marks where theirs "
                      "differs.")
                       .arg(ray)
                       .arg(QStringLiteral("\u2260"));
    view_->setStudentWalk(walk);
    board_->setBeside(std::move(beside));
    session_.showLog(log, LogKind::StudentRay);
    rays_->setCurrentIndex(ray);

    // The replay at the step where the walks part: raystep's event of the divergent cell or
    // node; past raystep's walk, or the ray's end (hit, miss), its end; a ray that passed, its end.
    std::size_t at = session_.size();
    if (v.divergence && v.divergence->record != "hit" && v.divergence->record != "miss") {
        const std::size_t want = std::size_t(std::max(v.divergence->index, 0));
        std::size_t seen = 0;
        const auto& events = log->events();
        for (std::size_t i = 0; i < events.size(); ++i) {
            const bool step = v.reference.cells ? std::holds_alternative<DdaCell>(events[i])
                                                : std::holds_alternative<NodeEnter>(events[i]);
            if (step && seen++ == want) {
                at = i + 1;
                break;
            }
        }
    }
    session_.setCursor(at);

    QString text;
    if (v.passed) {
        text = tr("Ray %1 passed: %2 steps, as raystep walks them.").arg(ray).arg(v.walkRecords);
    } else {
        const Divergence& d = *v.divergence;
        // The board's step (the walk's index, not a node's id), the line and the record there.
        text = tr("Ray %1 failed at step %2 (line %3, %4): %5")
                   .arg(ray)
                   .arg(std::max(d.index, 0))
                   .arg(d.line)
                   .arg(q(divergencePlace(d, lang)))
                   .arg(q(d.explanation));
        if (v.mistake) {
            const MistakeInfo& m = mistakeInfo(*v.mistake);
            // i18n: a mistake's description is marked where it is written (assess/mistakes.cpp).
            const std::string description = raystep::tr(lang, m.description);
            text += QStringLiteral(" ") +
                    tr("The known mistake \"%1\": %2.").arg(q(std::string(m.name)), q(description));
        }
    }
    verdict_->setText(text);
    verdict_->setToolTip(text);
    window_.statusBar()->showMessage(v.passed ? tr("Ray %1 of the student's trace passed").arg(ray)
                                              : tr("Ray %1 of the student's trace failed").arg(ray),
                                     10000);
    emit rayShown();
}

void AssessController::close() {
    bar_->hide();
    view_->setStudentWalk(std::nullopt);
    board_->setBeside(std::nullopt);
    assessment_.reset();
    trace_.reset();
    reference_.reset();
    scene_.reset();
    shownLog_.reset();
    shownRay_ = -1;
}

QString AssessController::verdictText() const {
    return verdict_->text();
}

}  // namespace raystep::gui
