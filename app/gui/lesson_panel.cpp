#include "lesson_panel.h"

#include "exercise_box.h"
#include "lesson_text.h"
#include "sweep_table.h"

#include "course/lesson_trace.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QResizeEvent>
#include <QShortcut>
#include <QVBoxLayout>

#include <algorithm>

namespace raystep::gui {

namespace {
QString q(const std::string& s) {
    return QString::fromStdString(s);
}
}  // namespace

LessonPanel::LessonPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    picker_ = new QComboBox;
    picker_->setObjectName("lessonPicker");
    picker_->setToolTip(tr("Open a lesson"));
    layout->addWidget(picker_);
    connect(picker_, &QComboBox::activated, this, [this](int i) {
        const QString id = picker_->itemData(i).toString();
        if (!id.isEmpty()) emit lessonRequested(id);
    });

    text_ = new LessonText;
    text_->installEventFilter(this);
    layout->addWidget(text_, 1);

    // Shown while the student explores (a pixel click, R, B): the one way back to the lesson.
    noteRow_ = new QWidget;
    noteRow_->setObjectName("replayNote");
    noteRow_->setStyleSheet(QStringLiteral("#replayNote { background: #fff4d6; }"));
    auto* nr = new QVBoxLayout(noteRow_);
    nr->setContentsMargins(6, 4, 6, 4);
    note_ = new QLabel;
    note_->setWordWrap(true);
    note_->setStyleSheet(QStringLiteral("color: #5a4300"));
    auto* back = new QPushButton(tr("Back to the lesson (Esc)"));
    back->setObjectName("backToLesson");
    back->setToolTip(tr("The lesson's own trace, its steps and its exercises"));
    nr->addWidget(note_);
    nr->addWidget(back, 0, Qt::AlignRight);
    connect(back, &QPushButton::clicked, this, &LessonPanel::lessonTraceRequested);
    noteRow_->hide();
    layout->addWidget(noteRow_);
    // An action refused while an exercise holds the replay: why, where the student looks.
    heldLabel_ = new QLabel;
    heldLabel_->setObjectName("heldNote");
    heldLabel_->setWordWrap(true);
    heldLabel_->setStyleSheet(
        QStringLiteral("#heldNote { background: #fff4d6; color: #5a4300; padding: 4px 6px; }"));
    heldLabel_->hide();
    layout->addWidget(heldLabel_);

    stepRow_ = new QWidget;
    auto* sr = new QHBoxLayout(stepRow_);
    sr->setContentsMargins(0, 0, 0, 0);
    prevStep_ = new QPushButton(tr("< Step"));
    nextStep_ = new QPushButton(tr("Step >"));
    prevStep_->setToolTip(tr("Previous step (Page Up)"));
    nextStep_->setToolTip(tr("Next step (Page Down)"));
    // Page Up/Down step wherever the focus is and do nothing at the ends: as the buttons' own
    // shortcuts they went dead with the button at the last step, and a focused lesson picker
    // then took the key and opened the next lesson.
    for (const auto& [key, delta] : {std::pair(Qt::Key_PageUp, -1), std::pair(Qt::Key_PageDown, 1)})
        connect(new QShortcut(QKeySequence(key), this), &QShortcut::activated, this,
                [this, delta = delta] {
                    QPushButton* b = delta < 0 ? prevStep_ : nextStep_;
                    if (b->isEnabled() && stepRow_->isEnabled() && !stepRow_->isHidden())
                        goToStep(step_ + delta);
                });
    stepLabel_ = new QLabel;
    stepLabel_->setAlignment(Qt::AlignCenter);
    sr->addWidget(prevStep_);
    sr->addWidget(stepLabel_, 1);
    sr->addWidget(nextStep_);
    connect(prevStep_, &QPushButton::clicked, this, [this] { goToStep(step_ - 1); });
    connect(nextStep_, &QPushButton::clicked, this, [this] { goToStep(step_ + 1); });
    // What the held exercises allow changes which step texts may be read.
    connect(this, &LessonPanel::quizChanged, this, [this] {
        if (hasLesson_) refreshText();
    });
    layout->addWidget(stepRow_);

    box_ = new ExerciseBox;
    connect(box_, &ExerciseBox::previousRequested, this, [this] { selectExercise(exercise_ - 1); });
    connect(box_, &ExerciseBox::nextRequested, this, [this] { selectExercise(exercise_ + 1); });
    connect(box_, &ExerciseBox::openClicked, this, [this] {
        if (exerciseOpen_)
            closeExercise();
        else
            selectExercise(exercise_);
    });
    connect(box_, &ExerciseBox::checkRequested, this, [this] { check(); });
    connect(box_, &ExerciseBox::hintRequested, this, [this] { hint(); });
    connect(box_, &ExerciseBox::revealRequested, this, [this] { revealAnswer(); });
    connect(box_, &ExerciseBox::cellsChanged, this, &LessonPanel::sequenceChanged);
    layout->addWidget(box_);

    sweepButton_ = new QPushButton(tr("Run the sweep"));
    connect(sweepButton_, &QPushButton::clicked, this, &LessonPanel::sweepRequested);
    layout->addWidget(sweepButton_);
    // A step's structures side by side on its ray (the step's "compare" list).
    compareButton_ = new QPushButton(tr("Compare these structures on this ray"));
    compareButton_->setObjectName("compareStructures");
    connect(compareButton_, &QPushButton::clicked, this, [this] {
        if (hasLesson_ && !lesson_.steps.empty())
            emit compareRequested(lesson_.steps[std::size_t(step_)].compare);
    });
    layout->addWidget(compareButton_);
    sweepTable_ = new SweepTable;
    layout->addWidget(sweepTable_, 1);
    showText({});
}

void LessonPanel::setHeader(QWidget* header) {
    static_cast<QVBoxLayout*>(layout())->insertWidget(1, header);
}

void LessonPanel::setLessons(const std::vector<Lesson>& lessons) {
    picker_->clear();
    picker_->addItem(tr("Lessons..."), QString());
    for (const Lesson& l : lessons)
        picker_->addItem(QStringLiteral("%1. %2").arg(l.number).arg(q(l.title.in(lang_))), q(l.id));
}

void LessonPanel::syncPicker() {
    picker_->setCurrentIndex(hasLesson_ ? std::max(0, picker_->findData(q(lesson_.id))) : 0);
}

void LessonPanel::showText(const QString& markdown) {
    hasLesson_ = false;
    log_ = nullptr;
    others_.clear();
    exploring_ = exerciseOpen_ = false;
    heldNote_.clear();
    box_->clearAnswer();
    freeText_ = markdown;
    text_->showMarkdown(markdown);
    picker_->setCurrentIndex(0);
    updateWidgets();
    emit quizChanged();
}

const LogRef& LessonPanel::logOf(const std::optional<LessonSetup>& setup) const {
    if (setup)
        if (const auto it = others_.find(setup->key()); it != others_.end()) return it->second;
    return log_;
}

bool LessonPanel::isLessonLog(const LogRef& log) const {
    if (!log) return false;
    if (log == log_) return true;
    return std::any_of(others_.begin(), others_.end(),
                       [&](const auto& o) { return o.second == log; });
}

void LessonPanel::showLesson(const Lesson& lesson, LogRef log, LessonProgress* progress,
                             std::map<std::string, LogRef> others) {
    lesson_ = lesson;
    log_ = std::move(log);
    others_ = std::move(others);
    hasLesson_ = true;
    // A new lesson starts on its own trace: whatever the last one explored or was told ends.
    exploring_ = false;
    heldNote_.clear();
    ownProgress_ = {};
    sweepRows_.clear();
    progress_ = progress ? progress : &ownProgress_;
    picker_->setCurrentIndex(std::max(0, picker_->findData(q(lesson.id))));
    step_ = std::clamp(progress_->step, 0, std::max(0, int(lesson.steps.size()) - 1));
    // A lesson opens on its first unsolved exercise, open: the replay stops at its position,
    // so the steps cannot show its answer before the student predicts it ("Put away" frees it).
    exercise_ = 0;
    while (exercise_ + 1 < static_cast<int>(lesson.exercises.size()) && solved(exercise_))
        ++exercise_;
    // Presenting, it waits closed for the lecturer to ask it (Try it takes the replay to its
    // position): opened at once beside the step the lecture was at, the views could hold its
    // answer while the room reads the question.
    exerciseOpen_ =
        !lesson.exercises.empty() && !solved(exercise_) && mode_ != LessonMode::Presenting;
    putAway_.clear();
    refreshText();
    refreshExercise();
    updateWidgets();
    emit quizChanged();
}

void LessonPanel::setReplayNote(const QString& what, bool hidden) {
    exploring_ = hasLesson_ && !what.isEmpty();
    if (exploring_) {
        heldNote_.clear();
        note_->setText(
            tr("You are exploring %1. The lesson's steps and exercises are about its "
               "own trace: they wait until you go back.")
                .arg(what) +
            (hidden ? QStringLiteral(" ") +
                          tr("An exercise holds the replay: nothing of this trace is shown until "
                             "you go back and answer it or put it away.")
                    : QString()));
    }
    updateWidgets();
}

QString LessonPanel::replayNote() const {
    return noteRow_->isHidden() ? QString() : note_->text();
}

void LessonPanel::showHeldNote(const QString& text) {
    heldNote_ = text;
    updateWidgets();
}

QString LessonPanel::heldNote() const {
    return heldLabel_->isHidden() ? QString() : heldLabel_->text();
}

void LessonPanel::setMode(LessonMode mode) {
    if (mode == mode_) return;
    mode_ = mode;
    heldNote_.clear();
    if (hasLesson_) {
        // What the held exercises allow changes: the steps' texts and the prompts that wait.
        refreshText();
        refreshExercise();
        updateWidgets();
    }
    emit quizChanged();
}

void LessonPanel::setShowErrata(bool on) {
    showErrata_ = on;
    if (hasLesson_) refreshText();
}

void LessonPanel::goToStep(int index) {
    if (!hasLesson_ || lesson_.steps.empty()) return;
    step_ = std::clamp(index, 0, static_cast<int>(lesson_.steps.size()) - 1);
    heldNote_.clear();
    refreshText();
    updateWidgets();
    emit stepShown(step_);
}

void LessonPanel::selectExercise(int index) {
    if (!hasLesson_ || lesson_.exercises.empty()) return;
    exercise_ = std::clamp(index, 0, static_cast<int>(lesson_.exercises.size()) - 1);
    heldNote_.clear();
    // One after a held exercise waits, closed: its prompt may state the held one's answer.
    const bool waits = waitingFor(exercise_).has_value();
    exerciseOpen_ = !waits;
    if (!waits) putAway_.erase(exercise_);
    refreshExercise();
    updateWidgets();
    emit quizChanged();
    if (!waits) emit exerciseShown(exercise_);
}

void LessonPanel::closeExercise() {
    if (!exerciseOpen_) return;
    exerciseOpen_ = false;
    putAway_.insert(exercise_);
    heldNote_.clear();
    updateWidgets();
    emit quizChanged();
}

std::optional<int> LessonPanel::waitingFor(int index) const {
    for (const int i : heldExercises())
        if (i < index) return i;
    return std::nullopt;
}

std::vector<int> LessonPanel::heldExercises() const {
    std::vector<int> held;
    if (!hasLesson_ || mode_ != LessonMode::Quiz) return held;
    for (int i = 0; i < static_cast<int>(lesson_.exercises.size()); ++i)
        if (!solved(i) && !putAway_.count(i)) held.push_back(i);
    return held;
}

std::optional<std::pair<int, std::size_t>> LessonPanel::heldBy() const {
    if (auto own = heldBy(lesson_.setup().key())) return own;
    for (const auto& [key, log] : others_)
        if (auto held = heldBy(key)) return held;
    return std::nullopt;
}

std::optional<std::pair<int, std::size_t>> LessonPanel::heldBy(const std::string& setupKey) const {
    std::optional<std::pair<int, std::size_t>> held;
    if (!log_) return held;
    for (const int i : heldExercises()) {
        const Exercise& ex = lesson_.exercises[std::size_t(i)];
        if (lesson_.setupOf(ex.setup).key() != setupKey) continue;
        if (const auto at = quizLimit(ex, *logOf(ex.setup)))
            if (!held || *at < held->second) held = std::pair(i, *at);
    }
    return held;
}

bool LessonPanel::asksTheRoom() const {
    return hasLesson_ && mode_ == LessonMode::Presenting && exerciseOpen_ && !revealed_ &&
           !lesson_.exercises.empty() && !solved(exercise_) && log_ &&
           quizLimit(lesson_.exercises[exercise_], *logOf(lesson_.exercises[exercise_].setup))
               .has_value();
}

std::optional<int> LessonPanel::quizExercise() const {
    if (!hasLesson_ || !exerciseOpen_ || mode_ != LessonMode::Quiz || lesson_.exercises.empty() ||
        solved(exercise_))
        return std::nullopt;
    return exercise_;
}

void LessonPanel::refreshText() {
    std::optional<int> waitsFor;
    if (!lesson_.steps.empty()) {
        const LessonStep& step = lesson_.steps[step_];
        // Only the exercises of the step's own structure hold it: theirs is the same trace.
        const auto held = heldBy(lesson_.setupOf(step.setup).key());
        const auto stepAt = log_ ? resolvePosition(step.at, *logOf(step.setup)) : std::nullopt;
        if (held && stepAt && *stepAt > held->second) waitsFor = held->first;
    }
    text_->showLesson(lesson_, step_, waitsFor, showErrata_, lang_);
    if (!lesson_.steps.empty())
        stepLabel_->setText(tr("Step %1 / %2").arg(step_ + 1).arg(lesson_.steps.size()));
}

void LessonPanel::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    // The exercise box scrolls before the lesson text loses its room: at most about 2/5 of the
    // panel for the prompt, hints and feedback.
    box_->fitScroll(std::max(60, height() * 3 / 10));
}

bool LessonPanel::eventFilter(QObject* o, QEvent* e) {
    // The text's room changed (the exercise box grew or shrank, the window was resized): the
    // step's text back in sight.
    if (o == text_ && e->type() == QEvent::Resize && hasLesson_) text_->keepStepInView();
    return QWidget::eventFilter(o, e);
}

void LessonPanel::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    if (hasLesson_) text_->keepStepInView();
}

void LessonPanel::updateWidgets() {
    // Every part's state from the panel's: whatever changed it (a lesson switch, exploring,
    // the mode, an answer), nothing is left as an earlier state set it.
    const bool steps = hasLesson_ && !lesson_.steps.empty();
    const bool exercises = hasLesson_ && !lesson_.exercises.empty();
    noteRow_->setVisible(hasLesson_ && exploring_);
    heldLabel_->setText(heldNote_);
    heldLabel_->setVisible(hasLesson_ && !exploring_ && !heldNote_.isEmpty());
    stepRow_->setVisible(steps);
    stepRow_->setEnabled(steps && !exploring_);
    prevStep_->setEnabled(steps && step_ > 0);
    nextStep_->setEnabled(steps && step_ + 1 < static_cast<int>(lesson_.steps.size()));
    sweepButton_->setVisible(hasLesson_ && lesson_.sweep.has_value());
    compareButton_->setVisible(steps && !lesson_.steps[std::size_t(step_)].compare.empty());
    compareButton_->setEnabled(!exploring_);
    sweepTable_->setVisible(hasLesson_ && lesson_.sweep.has_value() && !sweepRows_.empty());
    box_->setVisible(exercises);
    if (exercises)
        box_->setState({mode_, exercise_, static_cast<int>(lesson_.exercises.size()),
                        solved(exercise_), exerciseOpen_, waitingFor(exercise_), exploring_});
    if (exploringSaid_ != exploring_) {
        exploringSaid_ = exploring_;
        emit exploringChanged(exploring_);
    }
}

}  // namespace raystep::gui
