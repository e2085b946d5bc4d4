#include "lesson_panel.h"

#include "course/lesson_trace.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpressionValidator>
#include <QResizeEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextTable>
#include <QVBoxLayout>
#include "language.h"
#include "presentation.h"

namespace raystep::gui {

namespace {
QString q(const std::string& s) {
    return QString::fromStdString(s);
}
}  // namespace

namespace {
// The exercise's prompt, hints and feedback: as tall as they are, up to the room the lesson text
// leaves (then they scroll), so a long feedback never pushes the step's text out of sight. Its
// least height follows the content: the layout gives it all of it (up to the cap) before the text.
class ExerciseScroll : public QScrollArea {
  public:
    using QScrollArea::QScrollArea;
    /// The content's height at this width, capped at `cap`.
    void fit(int cap) {
        cap_ = cap;
        const QWidget* w = widget();
        if (!w) return;
        const int width = std::max(1, this->width() - 2 * frameWidth());
        const int content =
            w->hasHeightForWidth() ? w->heightForWidth(width) : w->sizeHint().height();
        const int h = std::min(content + 2 * frameWidth(), cap_);
        // As tall as its content (up to the cap), but never a floor under the window's least
        // height: a height fixed at a large window's size kept the window from shrinking.
        if (h != hint_ || h != maximumHeight()) {
            hint_ = h;
            setMinimumHeight(std::min(h, kLeast));
            setMaximumHeight(h);
            updateGeometry();
        }
    }
    QSize sizeHint() const override { return {QScrollArea::sizeHint().width(), hint_}; }
    bool eventFilter(QObject* o, QEvent* e) override {
        // The body's layout changed (a hint, the feedback): as tall as it now is.
        if (o == widget() && e->type() == QEvent::LayoutRequest) fit(cap_);
        return QScrollArea::eventFilter(o, e);
    }

  protected:
    void resizeEvent(QResizeEvent* e) override {
        QScrollArea::resizeEvent(e);
        if (e->size().width() != e->oldSize().width()) fit(cap_);  // the text wraps anew
    }

  private:
    static constexpr int kLeast = 60;  // the prompt's first lines, scrolled
    int cap_ = 200;
    int hint_ = 0;
};

// Markdown's code blocks are laid out unbroken: in a narrow panel (a 1366x768 laptop) their
// lines ran off the side. Every line may wrap, at a word if it can, else anywhere.
void wrapLongLines(QTextBrowser* text) {
    text->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    QTextCursor c(text->document());
    for (QTextBlock b = text->document()->begin(); b.isValid(); b = b.next())
        if (b.blockFormat().nonBreakableLines()) {
            c.setPosition(b.position());
            QTextBlockFormat f;
            f.setNonBreakableLines(false);
            c.mergeBlockFormat(f);
        }
    codeFollowsTextSize(*text->document());  // the zoom enlarges code and formulas too
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

    text_ = new QTextBrowser;
    text_->setObjectName("lessonText");
    text_->setOpenExternalLinks(true);
    // A few lines of the step's text however tall the exercise box grows (1366x768).
    text_->setMinimumHeight(100);  // five lines: the window still fits 1024x600
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

    exerciseBox_ = new QGroupBox(tr("Exercise"));
    exerciseBox_->setObjectName("exerciseBox");
    auto* el = new QVBoxLayout(exerciseBox_);
    exerciseHeader_ = new QWidget;
    auto* er = new QHBoxLayout(exerciseHeader_);
    er->setContentsMargins(0, 0, 0, 0);
    auto* prevEx = new QPushButton(QStringLiteral("<"));
    auto* nextEx = new QPushButton(QStringLiteral(">"));
    prevEx->setToolTip(tr("Previous exercise"));
    nextEx->setToolTip(tr("Next exercise"));
    prevEx->setMaximumWidth(30);
    nextEx->setMaximumWidth(30);
    exerciseLabel_ = new QLabel;
    exerciseLabel_->setAlignment(Qt::AlignCenter);
    // "Exercise 1 / 9 (solved)" wraps at the panel's least width rather than being cut.
    exerciseLabel_->setWordWrap(true);
    // An exercise is open while the student works on it: the replay then stops at its position.
    openButton_ = new QPushButton;
    openButton_->setObjectName("openExercise");
    er->addWidget(prevEx);
    er->addWidget(exerciseLabel_, 1);
    er->addWidget(nextEx);
    er->addWidget(openButton_);
    el->addWidget(exerciseHeader_);
    connect(prevEx, &QPushButton::clicked, this, [this] { selectExercise(exercise_ - 1); });
    connect(nextEx, &QPushButton::clicked, this, [this] { selectExercise(exercise_ + 1); });
    connect(openButton_, &QPushButton::clicked, this, [this] {
        if (exerciseOpen_)
            closeExercise();
        else
            selectExercise(exercise_);
    });
    exploreNote_ = new QLabel(
        tr("The exercises are about the lesson's own trace, not what you are exploring: go "
           "back to the lesson to answer them."));
    exploreNote_->setObjectName("exploreNote");
    exploreNote_->setWordWrap(true);
    exploreNote_->setStyleSheet(QStringLiteral("color: #5a4300"));
    el->addWidget(exploreNote_);
    waitNote_ = new QLabel;
    waitNote_->setObjectName("waitNote");
    waitNote_->setWordWrap(true);
    waitNote_->setStyleSheet(QStringLiteral("color: #5a4300"));
    el->addWidget(waitNote_);
    exerciseBody_ = new QWidget;
    auto* body = new QVBoxLayout(exerciseBody_);
    body->setContentsMargins(0, 0, 0, 0);
    exerciseScroll_ = new ExerciseScroll;
    exerciseScroll_->setObjectName("exerciseScroll");
    exerciseScroll_->setFrameShape(QFrame::NoFrame);
    exerciseScroll_->setWidgetResizable(true);
    exerciseScroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    exerciseScroll_->setWidget(exerciseBody_);
    el->addWidget(exerciseScroll_);
    QVBoxLayout* box = el;
    el = body;  // the prompt, the answer and the feedback go in the body
    prompt_ = new QLabel;
    prompt_->setObjectName("prompt");
    prompt_->setWordWrap(true);
    prompt_->setTextFormat(Qt::RichText);  // markdownForLabel: its code follows the zoom
    el->addWidget(prompt_);
    answer_ = new QLineEdit;
    answer_->setObjectName("answer");
    candidates_ = new QComboBox;
    candidates_->setObjectName("candidates");
    el->addWidget(answer_);
    el->addWidget(candidates_);
    choiceBox_ = new QWidget;
    choiceBox_->setObjectName("choices");
    new QVBoxLayout(choiceBox_);
    choiceBox_->layout()->setContentsMargins(0, 0, 0, 0);
    choiceGroup_ = new QButtonGroup(this);
    el->addWidget(choiceBox_);
    sweepPicker_ = new QComboBox;
    sweepPicker_->setObjectName("sweepPicker");
    el->addWidget(sweepPicker_);
    clearButton_ = new QPushButton(tr("Clear the cells"));
    clearButton_->setObjectName("clearSequence");
    clearButton_->setToolTip(tr("Start the order again"));
    el->addWidget(clearButton_, 0, Qt::AlignRight);
    connect(clearButton_, &QPushButton::clicked, this, [this] {
        sequence_.clear();
        answer_->clear();
        emit sequenceChanged(sequence_);
    });
    // Typing a sequence replaces the clicked cells (the typed text is the answer).
    connect(answer_, &QLineEdit::textEdited, this, [this] {
        if (sequence_.isEmpty()) return;
        sequence_.clear();
        emit sequenceChanged(sequence_);
    });
    auto* br = new QHBoxLayout;
    checkButton_ = new QPushButton(tr("Check"));
    hintButton_ = new QPushButton(tr("Hint"));
    revealButton_ = new QPushButton(tr("Show answer"));
    br->addWidget(checkButton_);
    br->addWidget(hintButton_);
    br->addWidget(revealButton_);
    connect(checkButton_, &QPushButton::clicked, this, [this] { check(); });
    connect(answer_, &QLineEdit::returnPressed, this, [this] { check(); });
    connect(hintButton_, &QPushButton::clicked, this, [this] { hint(); });
    connect(revealButton_, &QPushButton::clicked, this, [this] { revealAnswer(); });
    hints_ = new QLabel;
    hints_->setObjectName("hints");
    hints_->setWordWrap(true);
    hints_->setTextFormat(Qt::RichText);
    hints_->setStyleSheet(QStringLiteral("color: #1f4e99"));
    el->addWidget(hints_);
    feedback_ = new QLabel;
    feedback_->setObjectName("feedback");
    feedback_->setWordWrap(true);
    feedback_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    el->addWidget(feedback_);
    // The buttons last, under the scrolled part: the box grows upwards as hints and feedback
    // come, and the buttons stay where the student's mouse is (Hint pressed again reveals the
    // next one).
    buttonRow_ = new QWidget;
    buttonRow_->setLayout(br);
    br->setContentsMargins(0, 0, 0, 0);
    box->addWidget(buttonRow_);
    layout->addWidget(exerciseBox_);

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
    sweepTable_ = new QTableWidget;
    sweepTable_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    sweepTable_->verticalHeader()->hide();
    layout->addWidget(sweepTable_, 1);
    showText({});
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
    stepAnchor_ = -1;
    clearSequence();
    freeText_ = markdown;
    text_->setMarkdown(markdown);
    wrapLongLines(text_);
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

void LessonPanel::appendErrata(QTextCursor& at, const std::vector<Erratum>& errata) {
    if (!showErrata_) return;
    for (const Erratum& e : errata) {
        // A marked box: what the slide says, what is right, and why.
        at.movePosition(QTextCursor::End);
        QTextTableFormat box;
        box.setBackground(QColor(0xff, 0xf4, 0xd6));
        box.setBorder(1);
        box.setBorderBrush(QColor(0xe0, 0xc0, 0x70));
        box.setBorderStyle(QTextFrameFormat::BorderStyle_Solid);
        box.setCellPadding(6);
        box.setCellSpacing(0);
        box.setTopMargin(6);
        box.setBottomMargin(6);
        box.setWidth(QTextLength(QTextLength::PercentageLength, 100));
        QTextTable* table = at.insertTable(1, 1, box);
        QTextCursor cell = table->cellAt(0, 0).firstCursorPosition();
        cell.insertMarkdown(QStringLiteral("**%1**\n\n%2 *%3*\n\n%4 %5\n\n%6")
                                .arg(q(erratumHeading(lang_)), tr("The slide:"),
                                     q(e.slide.in(lang_)), tr("Correct:"), q(e.correct.in(lang_)),
                                     q(e.why.in(lang_))));
        at.movePosition(QTextCursor::End);
    }
}

void LessonPanel::refreshText() {
    text_->setMarkdown(QStringLiteral("# %1. %2\n\n%3\n")
                           .arg(lesson_.number)
                           .arg(q(lesson_.title.in(lang_)), q(lesson_.text.in(lang_))));
    QTextCursor at(text_->document());
    at.movePosition(QTextCursor::End);
    appendErrata(at, lesson_.errata);
    stepAnchor_ = -1;
    if (!lesson_.steps.empty()) {
        const LessonStep& step = lesson_.steps[step_];
        // A step past an unsolved exercise's position tells what comes after it: its text, its
        // computed note and its notes on the slides wait with the replay (a step may name the
        // next cell or the count the exercise asks for).
        // Only the exercises of the step's own structure hold it: theirs is the same trace.
        const auto held = heldBy(lesson_.setupOf(step.setup).key());
        const auto stepAt = log_ ? resolvePosition(step.at, *logOf(step.setup)) : std::nullopt;
        const bool waits = held && stepAt && *stepAt > held->second;
        const QString text =
            waits ? tr("This step comes after exercise %1: answer it, or put it away, to read it.")
                        .arg(held->first + 1)
                  : q(step.text.in(lang_));
        QString md = QStringLiteral("\n---\n\n**%1 %2 / %3.** %4\n")
                         .arg(tr("Step"))
                         .arg(step_ + 1)
                         .arg(lesson_.steps.size())
                         .arg(text);
        // A computed note (the slides' DDA loop beside the exact walk), as a quote under the step.
        if (!waits && !step.note.en.empty())
            md += QStringLiteral("\n> %1\n").arg(q(step.note.in(lang_)));
        at.movePosition(QTextCursor::End);
        // A plain block: one inserted after a text ending in a list would be an empty bullet.
        at.insertBlock(QTextBlockFormat(), QTextCharFormat());
        stepAnchor_ = at.position();
        at.insertMarkdown(md);
        if (!waits) appendErrata(at, step.errata);
        stepLabel_->setText(tr("Step %1 / %2").arg(step_ + 1).arg(lesson_.steps.size()));
    }
    wrapLongLines(text_);
    keepStepInView();
}

void LessonPanel::keepStepInView() {
    if (stepAnchor_ < 0) {
        text_->moveCursor(QTextCursor::Start);
        return;
    }
    // The step's text is what the lecturer points at: in sight, from its heading down, however
    // long the notes on the slides under it are. From the end back to the heading: the
    // smallest scroll that shows it puts the heading at the top when the whole does not fit.
    text_->moveCursor(QTextCursor::End);
    text_->ensureCursorVisible();
    QTextCursor c(text_->document());
    // The rule (---) the markdown puts first: the step's own heading is the block after it.
    c.setPosition(std::min(stepAnchor_, text_->document()->characterCount() - 1));
    text_->setTextCursor(c);
    text_->ensureCursorVisible();
}

void LessonPanel::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    // The exercise box scrolls before the lesson text loses its room: at most about 2/5 of the
    // panel for the prompt, hints and feedback.
    static_cast<ExerciseScroll*>(exerciseScroll_)->fit(std::max(60, height() * 3 / 10));
}

bool LessonPanel::eventFilter(QObject* o, QEvent* e) {
    // The text's room changed (the exercise box grew or shrank, the window was resized): the
    // step's text back in sight.
    if (o == text_ && e->type() == QEvent::Resize && hasLesson_) keepStepInView();
    return QWidget::eventFilter(o, e);
}

void LessonPanel::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    if (hasLesson_) keepStepInView();
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
    exerciseBox_->setVisible(exercises);
    if (exercises) {
        exerciseBox_->setTitle(mode_ == LessonMode::Presenting ? tr("Question for the room")
                               : mode_ == LessonMode::Lecturer ? tr("Exercise (answers shown)")
                                                               : tr("Exercise"));
        exerciseLabel_->setText(tr("Exercise %1 / %2%3")
                                    .arg(exercise_ + 1)
                                    .arg(lesson_.exercises.size())
                                    .arg(solved(exercise_) ? tr(" (solved)") : QString()));
        const auto waits = waitingFor(exercise_);
        openButton_->setText(exerciseOpen_ ? tr("Put away") : tr("Try it"));
        const bool quiz = mode_ == LessonMode::Quiz;
        openButton_->setToolTip(
            exerciseOpen_ ? (quiz ? tr("Put the exercise away: the replay may then go past its "
                                       "position")
                                  : tr("Put the exercise away"))
                          : (quiz ? tr("Open the exercise: the replay stops at its position "
                                       "until you answer")
                                  : tr("Open the exercise: the replay goes to its position")));
        openButton_->setVisible(!waits);
        if (waits)
            waitNote_->setText(tr("Exercise %1 waits for exercise %2: answer that one, or put "
                                  "it away, to read this one.")
                                   .arg(exercise_ + 1)
                                   .arg(*waits + 1));
        // While exploring, the exercises wait: they are graded against the lesson's own trace,
        // and the open one's prompt is put aside (the explored trace may hold its answer); Back
        // to the lesson shows it again, with its limit.
        const bool working = exerciseOpen_ && !exploring_ && !waits;
        exerciseHeader_->setEnabled(!exploring_);
        exploreNote_->setVisible(exploring_);
        waitNote_->setVisible(!exploring_ && waits);
        exerciseScroll_->setVisible(working);
        buttonRow_->setVisible(working);
        revealButton_->setVisible(mode_ != LessonMode::Quiz);
    }
    if (exploringSaid_ != exploring_) {
        exploringSaid_ = exploring_;
        emit exploringChanged(exploring_);
    }
}

void LessonPanel::clearSequence() {
    // The cells a sequence answer clicked are drawn numbered on the grid: they go with it.
    if (sequence_.isEmpty()) return;
    sequence_.clear();
    emit sequenceChanged(sequence_);
}

void LessonPanel::refreshExercise() {
    clearSequence();
    if (lesson_.exercises.empty()) return;
    const Exercise& ex = lesson_.exercises[exercise_];
    // An exercise that waits for a held one shows nothing of itself: no prompt, hint or choice.
    const bool waits = waitingFor(exercise_).has_value();
    promptSource_ = waits ? QString() : q(ex.prompt.in(lang_));
    prompt_->setText(promptSource_.isEmpty() ? QString() : markdownForLabel(promptSource_));
    answer_->clear();
    feedback_->clear();
    feedback_->setStyleSheet({});
    hintsShown_ = 0;
    revealed_ = false;
    hints_->clear();
    hintsSource_.clear();
    hints_->hide();
    hintButton_->setEnabled(!ex.hints.empty());
    hintButton_->setText(tr("Hint"));
    const bool split = ex.kind == ExerciseKind::PickSplit;
    candidates_->setVisible(split);
    answer_->setVisible(!split);
    answer_->setValidator(nullptr);
    candidates_->clear();
    choiceBox_->hide();
    sweepPicker_->hide();
    clearButton_->hide();
    if (split && log_ && !waits) {
        // The candidates without their cost: computing it is the exercise.
        for (const SplitCandidate& c : splitCandidates(ex, *logOf(ex.setup)))
            candidates_->addItem(
                QStringLiteral("%1 = %2   (NL %3, NR %4, P(L|C) %5, P(R|C) %6)")
                    .arg(QChar("xyz"[c.axis]))
                    .arg(numberText(c.position, 'g', 6))
                    .arg(c.nl)
                    .arg(c.nr)
                    .arg(numberText(c.pl, 'g', 4), numberText(c.pr, 'g', 4)),
                QStringLiteral("%1=%2").arg(QChar("xyz"[c.axis])).arg(c.position, 0, 'g', 17));
    }
    // A choice: one radio button an option, lettered as the student may also type them.
    for (QAbstractButton* b : choiceGroup_->buttons()) {
        choiceGroup_->removeButton(b);
        delete b;
    }
    if (ex.kind == ExerciseKind::Choice && !waits) {
        for (std::size_t k = 0; k < ex.choices.size(); ++k) {
            auto* b = new QRadioButton(QStringLiteral("%1) %2")
                                           .arg(QChar('a' + static_cast<int>(k)))
                                           .arg(q(ex.choices[k].text.in(lang_))));
            b->setObjectName(QStringLiteral("choice%1").arg(k));
            choiceGroup_->addButton(b, static_cast<int>(k));
            choiceBox_->layout()->addWidget(b);
        }
        choiceBox_->show();
        answer_->hide();
    }
    if (ex.kind == ExerciseKind::SweepPick) {
        sweepPicker_->clear();
        if (lesson_.sweep)
            for (int r : lesson_.sweep->resolutions)
                sweepPicker_->addItem(tr("%1 cells per axis").arg(r), r);
        sweepPicker_->show();
        answer_->hide();
    }
    switch (ex.kind) {
        case ExerciseKind::NextCell:
            answer_->setPlaceholderText(q(answerPlaceholder(ex, log_ ? log_->dims() : 2, lang_)));
            break;
        case ExerciseKind::Sequence:
            answer_->setPlaceholderText(q(answerPlaceholder(ex, log_ ? log_->dims() : 2, lang_)));
            clearButton_->setVisible(!ex.ofNodes);
            break;
        case ExerciseKind::Overlap:
            answer_->setPlaceholderText(q(answerPlaceholder(ex, log_ ? log_->dims() : 2, lang_)));
            break;
        case ExerciseKind::Compute: {
            answer_->setPlaceholderText(tr("your result, a number (e.g. -2.5 or 0,75)"));
            // A number box: digits, one sign, a decimal point or comma, an exponent.
            static const QRegularExpression number(
                QStringLiteral("[-+]?[0-9]*([.,][0-9]*)?([eE][-+]?[0-9]*)?"));
            answer_->setValidator(new QRegularExpressionValidator(number, answer_));
            break;
        }
        case ExerciseKind::Choice:
        case ExerciseKind::SweepPick:
            break;
        case ExerciseKind::Value:
            answer_->setPlaceholderText(tr("a number, e.g. 1.25"));
            break;
        case ExerciseKind::Count:
            answer_->setPlaceholderText(tr("a whole number"));
            break;
        case ExerciseKind::HitOrMiss:
            answer_->setPlaceholderText(ex.withT ? tr("hit T, or miss") : tr("hit or miss"));
            break;
        case ExerciseKind::PickSplit:
            break;
    }
    if (mode_ == LessonMode::Lecturer && log_ && !waits) revealAnswer();
}

void LessonPanel::fillCell(int x, int y) {
    if (!hasLesson_ || exploring_ || !exerciseOpen_ || lesson_.exercises.empty() ||
        !answer_->isVisible())
        return;
    const Exercise& ex = lesson_.exercises[exercise_];
    if (ex.kind == ExerciseKind::Sequence && !ex.ofNodes) {
        // The cells in the order clicked; checked when the student says so.
        sequence_.append(QPoint(x, y));
        QStringList cells;
        for (const QPoint& c : sequence_) cells << QStringLiteral("%1,%2").arg(c.x()).arg(c.y());
        answer_->setText(cells.join(QStringLiteral("; ")));
        emit sequenceChanged(sequence_);
        return;
    }
    if (ex.kind != ExerciseKind::NextCell) return;
    answer_->setText(QStringLiteral("%1,%2").arg(x).arg(y));
    check();
}

bool LessonPanel::submit(const QString& answer) {
    if (!hasLesson_ || lesson_.exercises.empty()) return false;
    const ExerciseKind kind = lesson_.exercises[exercise_].kind;
    if (kind == ExerciseKind::PickSplit) {
        const int i = candidates_->findData(answer);
        if (i >= 0) candidates_->setCurrentIndex(i);
    } else if (kind == ExerciseKind::Choice) {
        // "b" or "2": the radio button a student would click.
        const QString a = answer.trimmed().toLower();
        bool number = false;
        const int n = a.toInt(&number);
        const int i = number ? n - 1 : (a.size() == 1 ? a[0].unicode() - 'a' : -1);
        if (QAbstractButton* b = choiceGroup_->button(i)) b->setChecked(true);
    } else if (kind == ExerciseKind::SweepPick) {
        const int i = sweepPicker_->findData(answer.trimmed().toInt());
        if (i >= 0) sweepPicker_->setCurrentIndex(i);
    } else {
        answer_->setText(answer);
    }
    feedback_->setProperty("correct", false);
    check();
    return feedback_->property("correct").toBool();
}

QString LessonPanel::feedback() const {
    return feedback_->text();
}
QString LessonPanel::exerciseText() const {
    return promptSource_;
}
QString LessonPanel::hintsText() const {
    return hintsSource_;
}

void LessonPanel::check() {
    if (!hasLesson_ || !log_ || lesson_.exercises.empty()) return;
    // While exploring, the exercises wait (their box is disabled; a script may still call).
    if (exploring_) {
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(exploreNote_->text());
        return;
    }
    // One after a held exercise waits (its prompt is not shown; a script may still call).
    if (waitingFor(exercise_)) {
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(waitNote_->text());
        return;
    }
    heldNote_.clear();
    if (!exerciseOpen_) {
        exerciseOpen_ = true;  // answering an exercise is working on it: it holds again
        putAway_.erase(exercise_);
        updateWidgets();
        emit quizChanged();
    }
    const Exercise& ex = lesson_.exercises[exercise_];
    const QString typed = typedAnswer();
    if (typed.isEmpty() &&
        (ex.kind == ExerciseKind::Choice || ex.kind == ExerciseKind::SweepPick)) {
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(tr("Pick one of the options first."));
        return;
    }
    if (ex.kind == ExerciseKind::SweepPick && !sweepRows()) {
        // Graded from the sweep's table: run it first (in the background).
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(
            tr("The answer is graded from the sweep's table: the sweep runs now; "
               "check again when its table is shown."));
        emit sweepRequested();
        return;
    }
    std::string why;
    const auto answer = parseAnswer(ex, typed.toStdString(), &why, lang_);
    if (!answer) {
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(tr("Cannot read that answer: %1.").arg(q(why)));
        return;
    }
    Verdict v;
    try {
        v = checkAnswer(ex, *logOf(ex.setup), *answer, lang_, lesson_.file, sweepRows());
    } catch (const LessonError& e) {
        // A lesson whose trace lacks what the exercise asks about: say so, grade nothing.
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(q(e.what()));
        return;
    }
    // The course's rule (recordAnswer): once solved, an answer is no attempt and is not kept.
    // Only a student's answers are the student's progress: the room's (presenting) and the
    // lecturer's are not recorded, and a right one there reveals that exercise's answer.
    const bool quiz = mode_ == LessonMode::Quiz;
    const bool wasSolved =
        quiz ? recordAnswer(*progress_, ex.id, typed.toStdString(), v.correct) : solved(exercise_);
    const int attempts = quiz ? record(exercise_).attempts : 0;
    if (!quiz && v.correct) revealed_ = true;
    feedback_->setProperty("correct", v.correct);
    // Right: why, from the trace. Wrong: try again; the explanation after three tries.
    if (v.correct) {
        feedback_->setStyleSheet(QStringLiteral("color: #1a7f37"));
        feedback_->setText(tr("Right. %1").arg(q(v.feedback)));
    } else if (wasSolved && mode_ != LessonMode::Presenting) {
        // Solved before: the attempt is not counted against the student.
        feedback_->setStyleSheet(QStringLiteral("color: #c62828"));
        feedback_->setText(tr("Not right. The answer is %1: %2").arg(q(v.expected), q(v.feedback)));
    } else {
        feedback_->setStyleSheet(QStringLiteral("color: #c62828"));
        // A slip the answer betrays is named at once, with the student's own numbers; else
        // where the answer can be worked out. The answer itself: after three tries in quiz
        // mode, at once in lecturer mode, never in front of the room (Show answer reveals it).
        const QString advice =
            v.slip.empty()
                ? q(raystep::retryAdvice(ex, replayHeldBeforeAnswer(),
                                         hintsShown_ < static_cast<int>(ex.hints.size()), lang_))
                : q(v.slip);
        feedback_->setText(
            mode_ == LessonMode::Presenting ? tr("Not right yet. %1").arg(advice)
            : attempts >= 3 || mode_ == LessonMode::Lecturer
                ? tr("Not right. The answer is %1: %2").arg(q(v.expected), q(v.feedback))
                : tr("Not right yet (try %1 of 3). %2").arg(attempts).arg(advice));
    }
    updateWidgets();
    exerciseScroll_->ensureWidgetVisible(feedback_);
    if (quiz) emit answered(q(ex.id), v.correct, typed);
    // Answered right: the replay may go past the exercise now (or the room's question ends).
    if (v.correct && !wasSolved) emit quizChanged();
}

LessonProgress::ExerciseRecord& LessonPanel::record(int exercise) {
    return progress_->exercises[lesson_.exercises[exercise].id];
}

bool LessonPanel::solved(int exercise) const {
    const auto it = progress_->exercises.find(lesson_.exercises[exercise].id);
    return it != progress_->exercises.end() && it->second.correct;
}

void LessonPanel::hint() {
    // One more hint each press: a nudge, then the formula, then the worked first step.
    const Exercise& ex = lesson_.exercises[exercise_];
    if (hintsShown_ >= static_cast<int>(ex.hints.size())) return;
    ++hintsShown_;
    QStringList shown;
    for (int k = 0; k < hintsShown_; ++k)
        shown << tr("**Hint %1 of %2.** %3")
                     .arg(k + 1)
                     .arg(ex.hints.size())
                     .arg(q(ex.hints[k].in(lang_)));
    hintsSource_ = shown.join(QStringLiteral("\n\n"));
    hints_->setText(markdownForLabel(hintsSource_));
    hints_->show();
    exerciseScroll_->ensureWidgetVisible(hints_);
    const bool more = hintsShown_ < static_cast<int>(ex.hints.size());
    hintButton_->setEnabled(more);
    hintButton_->setText(more ? tr("Next hint") : tr("No more hints"));
}

QString LessonPanel::typedAnswer() const {
    const Exercise& ex = lesson_.exercises[exercise_];
    switch (ex.kind) {
        case ExerciseKind::PickSplit:
            return candidates_->currentData().toString();
        case ExerciseKind::Choice:
            return choiceGroup_->checkedId() < 0 ? QString()
                                                 : QString::number(choiceGroup_->checkedId() + 1);
        case ExerciseKind::SweepPick:
            return sweepPicker_->currentIndex() < 0
                       ? QString()
                       : QString::number(sweepPicker_->currentData().toInt());
        default:
            return answer_->text();
    }
}

const std::vector<GridSweepRow>* LessonPanel::sweepRows() const {
    return sweepRows_.empty() ? nullptr : &sweepRows_;
}

bool LessonPanel::replayHeldBeforeAnswer() const {
    if (!log_ || mode_ != LessonMode::Quiz) return false;
    const Exercise& ex = lesson_.exercises[exercise_];
    const auto held = heldBy(lesson_.setupOf(ex.setup).key());
    const auto answerAt = answerEventIndex(ex, *logOf(ex.setup), lesson_.file);
    return held && answerAt && *answerAt >= held->second;
}

void LessonPanel::revealAnswer() {
    // Quiz mode: the answer comes after three tries, never from a button.
    if (!log_ || !hasLesson_ || lesson_.exercises.empty() || mode_ == LessonMode::Quiz ||
        waitingFor(exercise_))
        return;
    const Exercise& ex = lesson_.exercises[exercise_];
    if (ex.kind == ExerciseKind::SweepPick && !sweepRows()) {
        feedback_->setStyleSheet(QStringLiteral("color: #1f4e99"));
        feedback_->setText(tr("Run the sweep to see the answer: it is read from its table."));
        return;
    }
    Verdict v;
    try {
        v = checkAnswer(ex, *logOf(ex.setup), Answer{}, lang_, lesson_.file, sweepRows());
    } catch (const LessonError& e) {
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(q(e.what()));
        return;
    }
    feedback_->setStyleSheet(QStringLiteral("color: #1f4e99"));
    feedback_->setText(tr("Answer: %1. %2").arg(q(v.expected), q(v.feedback)));
    exerciseScroll_->ensureWidgetVisible(feedback_);
    if (!revealed_) {
        revealed_ = true;
        emit quizChanged();  // presenting: what lies past the cursor may show now
    }
}

void LessonPanel::showSweep(const std::vector<GridSweepRow>& rows) {
    sweepRows_ = rows;
    // What the lesson is about first (the panel is narrow): tests against cells against time.
    const QStringList headers = {tr("cells/axis"), tr("tests/ray"), tr("cells/ray"),
                                 tr("trace ms"),   tr("cells"),     tr("refs"),
                                 tr("build ms"),   tr("skips/ray")};
    sweepTable_->clear();
    sweepTable_->setColumnCount(headers.size());
    sweepTable_->setHorizontalHeaderLabels(headers);
    sweepTable_->setRowCount(static_cast<int>(rows.size()));
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
        const GridSweepRow& row = rows[r];
        const QStringList cells = {
            QString::number(row.resolution),     numberText(row.testsPerRay, 'f', 1),
            numberText(row.cellsPerRay, 'f', 1), numberText(row.traceMs, 'f', 1),
            QString::number(row.cells),          QString::number(row.references),
            numberText(row.buildMs, 'f', 1),     numberText(row.skipsPerRay, 'f', 1)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            sweepTable_->setItem(r, c, item);
        }
    }
    sweepTable_->resizeColumnsToContents();
    sweepTable_->show();
}

}  // namespace raystep::gui
