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
                    if (b->isEnabled() && stepRow_->isEnabled() && stepRow_->isVisible())
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
    exerciseBody_ = new QWidget;
    auto* body = new QVBoxLayout(exerciseBody_);
    body->setContentsMargins(0, 0, 0, 0);
    el->addWidget(exerciseBody_);
    el = body;  // the prompt, the answer and the feedback go in the body
    prompt_ = new QLabel;
    prompt_->setObjectName("prompt");
    prompt_->setWordWrap(true);
    prompt_->setTextFormat(Qt::MarkdownText);
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
    hints_->setTextFormat(Qt::MarkdownText);
    hints_->setStyleSheet(QStringLiteral("color: #1f4e99"));
    el->addWidget(hints_);
    feedback_ = new QLabel;
    feedback_->setObjectName("feedback");
    feedback_->setWordWrap(true);
    feedback_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    el->addWidget(feedback_);
    // The buttons last: the box grows upwards as hints and feedback come, and the buttons stay
    // where the student's mouse is (Hint pressed again reveals the next one).
    el->addLayout(br);
    layout->addWidget(exerciseBox_);

    sweepButton_ = new QPushButton(tr("Run the sweep"));
    connect(sweepButton_, &QPushButton::clicked, this, &LessonPanel::sweepRequested);
    layout->addWidget(sweepButton_);
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
    exploring_ = exerciseOpen_ = false;
    noteRow_->hide();
    freeText_ = markdown;
    text_->setMarkdown(markdown);
    wrapLongLines(text_);
    stepRow_->hide();
    exerciseBox_->hide();
    sweepButton_->hide();
    sweepTable_->hide();
    picker_->setCurrentIndex(0);
    emit quizChanged();
}

void LessonPanel::showLesson(const Lesson& lesson, LogRef log, LessonProgress* progress) {
    lesson_ = lesson;
    log_ = std::move(log);
    noteRow_->hide();
    hasLesson_ = true;
    exploring_ = false;
    ownProgress_ = {};
    sweepRows_.clear();
    progress_ = progress ? progress : &ownProgress_;
    picker_->setCurrentIndex(std::max(0, picker_->findData(q(lesson.id))));
    stepRow_->setVisible(!lesson.steps.empty());
    exerciseBox_->setVisible(!lesson.exercises.empty());
    sweepButton_->setVisible(lesson.sweep.has_value());
    sweepTable_->hide();
    step_ = std::clamp(progress_->step, 0, std::max(0, int(lesson.steps.size()) - 1));
    // A lesson opens on its first unsolved exercise, open: the replay stops at its position,
    // so the steps cannot show its answer before the student predicts it ("Put away" frees it).
    exercise_ = 0;
    while (exercise_ + 1 < static_cast<int>(lesson.exercises.size()) && solved(exercise_))
        ++exercise_;
    exerciseOpen_ = !lesson.exercises.empty() && !solved(exercise_);
    putAway_.clear();
    refreshText();
    refreshExercise();
    emit quizChanged();
}

void LessonPanel::setReplayNote(const QString& what) {
    exploring_ = hasLesson_ && !what.isEmpty();
    if (exploring_)
        note_->setText(tr("You are exploring %1. The lesson's steps and exercises are about its "
                          "own trace: they wait until you go back.")
                           .arg(what));
    noteRow_->setVisible(exploring_);
    stepRow_->setEnabled(!exploring_);
    if (hasLesson_) updateExerciseBox();
}

QString LessonPanel::replayNote() const {
    return noteRow_->isHidden() ? QString() : note_->text();
}

void LessonPanel::setLecturerMode(bool on) {
    lecturer_ = on;
    if (hasLesson_) refreshExercise();
    emit quizChanged();
}

void LessonPanel::setShowErrata(bool on) {
    showErrata_ = on;
    if (hasLesson_) refreshText();
}

void LessonPanel::goToStep(int index) {
    if (!hasLesson_ || lesson_.steps.empty()) return;
    step_ = std::clamp(index, 0, static_cast<int>(lesson_.steps.size()) - 1);
    refreshText();
    emit stepShown(step_);
}

void LessonPanel::selectExercise(int index) {
    if (!hasLesson_ || lesson_.exercises.empty()) return;
    exercise_ = std::clamp(index, 0, static_cast<int>(lesson_.exercises.size()) - 1);
    exerciseOpen_ = true;
    putAway_.erase(exercise_);
    refreshExercise();
    emit quizChanged();
    emit exerciseShown(exercise_);
}

void LessonPanel::closeExercise() {
    if (!exerciseOpen_) return;
    exerciseOpen_ = false;
    putAway_.insert(exercise_);
    updateExerciseBox();
    emit quizChanged();
}

std::vector<int> LessonPanel::heldExercises() const {
    std::vector<int> held;
    if (!hasLesson_ || lecturer_) return held;
    for (int i = 0; i < static_cast<int>(lesson_.exercises.size()); ++i)
        if (!solved(i) && !putAway_.count(i)) held.push_back(i);
    return held;
}

std::optional<std::pair<int, std::size_t>> LessonPanel::heldBy() const {
    std::optional<std::pair<int, std::size_t>> held;
    if (!log_) return held;
    for (const int i : heldExercises())
        if (const auto at = quizLimit(lesson_.exercises[std::size_t(i)], *log_))
            if (!held || *at < held->second) held = std::pair(i, *at);
    return held;
}

std::optional<int> LessonPanel::quizExercise() const {
    if (!hasLesson_ || !exerciseOpen_ || lecturer_ || lesson_.exercises.empty() ||
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
    if (!lesson_.steps.empty()) {
        const LessonStep& step = lesson_.steps[step_];
        // A step past an unsolved exercise's position tells what comes after it: its text waits
        // with the replay (a step may name the next cell or the count the exercise asks for).
        const auto held = heldBy();
        const auto stepAt = log_ ? resolvePosition(step.at, *log_) : std::nullopt;
        const QString text =
            held && stepAt && *stepAt > held->second
                ? tr("This step comes after exercise %1: answer it, or put it away, to read it.")
                      .arg(held->first + 1)
                : q(step.text.in(lang_));
        QString md = QStringLiteral("\n---\n\n**%1 %2 / %3.** %4\n")
                         .arg(tr("Step"))
                         .arg(step_ + 1)
                         .arg(lesson_.steps.size())
                         .arg(text);
        // A computed note (the slides' DDA loop beside the exact walk), as a quote under the step.
        if (!step.note.en.empty()) md += QStringLiteral("\n> %1\n").arg(q(step.note.in(lang_)));
        at.movePosition(QTextCursor::End);
        // A plain block: one inserted after a text ending in a list would be an empty bullet.
        at.insertBlock(QTextBlockFormat(), QTextCharFormat());
        at.insertMarkdown(md);
        appendErrata(at, step.errata);
        stepLabel_->setText(tr("Step %1 / %2").arg(step_ + 1).arg(lesson_.steps.size()));
        prevStep_->setEnabled(step_ > 0);
        nextStep_->setEnabled(step_ + 1 < static_cast<int>(lesson_.steps.size()));
    }
    wrapLongLines(text_);
    // The step's text is what the lecturer points at: keep it in sight.
    text_->moveCursor(QTextCursor::End);
    text_->ensureCursorVisible();
}

void LessonPanel::updateExerciseBox() {
    if (lesson_.exercises.empty()) return;
    exerciseLabel_->setText(tr("Exercise %1 / %2%3")
                                .arg(exercise_ + 1)
                                .arg(lesson_.exercises.size())
                                .arg(solved(exercise_) ? tr(" (solved)") : QString()));
    openButton_->setText(exerciseOpen_ ? tr("Put away") : tr("Try it"));
    openButton_->setToolTip(
        exerciseOpen_ ? tr("Put the exercise away: the replay may then go past its position")
                      : tr("Open the exercise: the replay stops at its position "
                           "until you answer"));
    // While exploring, the exercises wait: they are graded against the lesson's own trace, and
    // the open one's prompt is put aside (the explored trace may hold its answer); Back to the
    // lesson shows it again, with its limit.
    exerciseBody_->setVisible(exerciseOpen_ && !exploring_);
    exerciseHeader_->setEnabled(!exploring_);
    exerciseBody_->setEnabled(!exploring_);
    exploreNote_->setVisible(exploring_);
}

void LessonPanel::refreshExercise() {
    if (lesson_.exercises.empty()) return;
    const Exercise& ex = lesson_.exercises[exercise_];
    updateExerciseBox();
    prompt_->setText(q(ex.prompt.in(lang_)));
    answer_->clear();
    feedback_->clear();
    feedback_->setStyleSheet({});
    hintsShown_ = 0;
    hints_->clear();
    hints_->hide();
    hintButton_->setEnabled(!ex.hints.empty());
    hintButton_->setText(tr("Hint"));
    revealButton_->setVisible(lecturer_);
    const bool split = ex.kind == ExerciseKind::PickSplit;
    candidates_->setVisible(split);
    answer_->setVisible(!split);
    answer_->setValidator(nullptr);
    candidates_->clear();
    choiceBox_->hide();
    sweepPicker_->hide();
    clearButton_->hide();
    if (!sequence_.isEmpty()) {
        sequence_.clear();
        emit sequenceChanged(sequence_);
    }
    if (split && log_) {
        // The candidates without their cost: computing it is the exercise.
        for (const SplitCandidate& c : splitCandidates(ex, *log_))
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
    if (ex.kind == ExerciseKind::Choice) {
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
            answer_->setPlaceholderText(tr("X,Y (or click the cell in the 2D view)"));
            break;
        case ExerciseKind::Sequence:
            answer_->setPlaceholderText(
                ex.ofNodes ? tr("node ids in order, e.g. 0 1 4")
                           : tr("cells in order, e.g. 0,0; 1,0 (or click them in the 2D view)"));
            clearButton_->setVisible(!ex.ofNodes);
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
    if (lecturer_ && log_) revealAnswer();
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
    return prompt_->text();
}
QString LessonPanel::hintsText() const {
    return hints_->text();
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
    if (!exerciseOpen_) {
        exerciseOpen_ = true;  // answering an exercise is working on it
        updateExerciseBox();
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
        v = checkAnswer(ex, *log_, *answer, lang_, lesson_.file, sweepRows());
    } catch (const LessonError& e) {
        // A lesson whose trace lacks what the exercise asks about: say so, grade nothing.
        feedback_->setProperty("correct", false);
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(q(e.what()));
        return;
    }
    LessonProgress::ExerciseRecord& rec = record(exercise_);
    const bool wasSolved = rec.correct;
    ++rec.attempts;
    rec.correct = rec.correct || v.correct;
    rec.answer = typed.toStdString();
    feedback_->setProperty("correct", v.correct);
    // Right: why, from the trace. Wrong: try again; the explanation after three tries.
    if (v.correct) {
        feedback_->setStyleSheet(QStringLiteral("color: #1a7f37"));
        feedback_->setText(tr("Right. %1").arg(q(v.feedback)));
    } else if (wasSolved) {
        // Solved before: the attempt is not counted against the student.
        feedback_->setStyleSheet(QStringLiteral("color: #c62828"));
        feedback_->setText(tr("Not right. The answer is %1: %2").arg(q(v.expected), q(v.feedback)));
    } else {
        feedback_->setStyleSheet(QStringLiteral("color: #c62828"));
        // A slip the answer betrays is named at once, with the student's own numbers.
        feedback_->setText(
            rec.attempts >= 3 || lecturer_
                ? tr("Not right. The answer is %1: %2").arg(q(v.expected), q(v.feedback))
            : v.slip.empty()
                ? tr("Not right yet (try %1 of 3). Step the replay and look at the "
                     "inspector, or ask for a hint.")
                      .arg(rec.attempts)
                : tr("Not right yet (try %1 of 3). %2").arg(rec.attempts).arg(q(v.slip)));
    }
    updateExerciseBox();
    emit answered(q(ex.id), v.correct, typed);
    // Answered right: the replay may go past the exercise now.
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
    hints_->setText(shown.join(QStringLiteral("\n\n")));
    hints_->show();
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

void LessonPanel::revealAnswer() {
    if (!log_) return;
    const Exercise& ex = lesson_.exercises[exercise_];
    if (ex.kind == ExerciseKind::SweepPick && !sweepRows()) {
        feedback_->setStyleSheet(QStringLiteral("color: #1f4e99"));
        feedback_->setText(tr("Run the sweep to see the answer: it is read from its table."));
        return;
    }
    Verdict v;
    try {
        v = checkAnswer(ex, *log_, Answer{}, lang_, lesson_.file, sweepRows());
    } catch (const LessonError& e) {
        feedback_->setStyleSheet(QStringLiteral("color: #b36b00"));
        feedback_->setText(q(e.what()));
        return;
    }
    feedback_->setStyleSheet(QStringLiteral("color: #1f4e99"));
    feedback_->setText(tr("Answer: %1. %2").arg(q(v.expected), q(v.feedback)));
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
