#include "exercise_box.h"

#include "presentation.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QResizeEvent>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace raystep::gui {

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

ExerciseBox::ExerciseBox(QWidget* parent) : QGroupBox(tr("Exercise"), parent) {
    setObjectName("exerciseBox");
    auto* el = new QVBoxLayout(this);
    header_ = new QWidget;
    auto* er = new QHBoxLayout(header_);
    er->setContentsMargins(0, 0, 0, 0);
    auto* prevEx = new QPushButton(QStringLiteral("<"));
    auto* nextEx = new QPushButton(QStringLiteral(">"));
    prevEx->setToolTip(tr("Previous exercise"));
    nextEx->setToolTip(tr("Next exercise"));
    prevEx->setMaximumWidth(30);
    nextEx->setMaximumWidth(30);
    label_ = new QLabel;
    label_->setAlignment(Qt::AlignCenter);
    // "Exercise 1 / 9 (solved)" wraps at the panel's least width rather than being cut.
    label_->setWordWrap(true);
    // An exercise is open while the student works on it: the replay then stops at its position.
    openButton_ = new QPushButton;
    openButton_->setObjectName("openExercise");
    er->addWidget(prevEx);
    er->addWidget(label_, 1);
    er->addWidget(nextEx);
    er->addWidget(openButton_);
    el->addWidget(header_);
    connect(prevEx, &QPushButton::clicked, this, &ExerciseBox::previousRequested);
    connect(nextEx, &QPushButton::clicked, this, &ExerciseBox::nextRequested);
    connect(openButton_, &QPushButton::clicked, this, &ExerciseBox::openClicked);
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
    body_ = new QWidget;
    auto* body = new QVBoxLayout(body_);
    body->setContentsMargins(0, 0, 0, 0);
    scroll_ = new ExerciseScroll;
    scroll_->setObjectName("exerciseScroll");
    scroll_->setFrameShape(QFrame::NoFrame);
    scroll_->setWidgetResizable(true);
    scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll_->setWidget(body_);
    el->addWidget(scroll_);
    // The prompt, the answer and the feedback go in the body.
    prompt_ = new QLabel;
    prompt_->setObjectName("prompt");
    prompt_->setWordWrap(true);
    prompt_->setTextFormat(Qt::RichText);  // markdownForLabel: its code follows the zoom
    body->addWidget(prompt_);
    inputs_ = std::make_unique<AnswerInputs>(body);
    for (AnswerInput* input : inputs_->all()) {
        connect(input, &AnswerInput::submitted, this, &ExerciseBox::checkRequested);
        connect(input, &AnswerInput::cellsChanged, this, &ExerciseBox::cellsChanged);
    }
    auto* br = new QHBoxLayout;
    checkButton_ = new QPushButton(tr("Check"));
    hintButton_ = new QPushButton(tr("Hint"));
    revealButton_ = new QPushButton(tr("Show answer"));
    br->addWidget(checkButton_);
    br->addWidget(hintButton_);
    br->addWidget(revealButton_);
    connect(checkButton_, &QPushButton::clicked, this, &ExerciseBox::checkRequested);
    connect(hintButton_, &QPushButton::clicked, this, &ExerciseBox::hintRequested);
    connect(revealButton_, &QPushButton::clicked, this, &ExerciseBox::revealRequested);
    hints_ = new QLabel;
    hints_->setObjectName("hints");
    hints_->setWordWrap(true);
    hints_->setTextFormat(Qt::RichText);
    hints_->setStyleSheet(QStringLiteral("color: #1f4e99"));
    body->addWidget(hints_);
    feedback_ = new QLabel;
    feedback_->setObjectName("feedback");
    feedback_->setWordWrap(true);
    feedback_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    body->addWidget(feedback_);
    // The buttons last, under the scrolled part: the box grows upwards as hints and feedback
    // come, and the buttons stay where the student's mouse is (Hint pressed again reveals the
    // next one).
    buttonRow_ = new QWidget;
    buttonRow_->setLayout(br);
    br->setContentsMargins(0, 0, 0, 0);
    el->addWidget(buttonRow_);
}

ExerciseBox::~ExerciseBox() = default;

void ExerciseBox::showExercise(const Exercise& ex, const AnswerContext& ctx) {
    // An exercise that waits for a held one shows nothing of itself: no prompt, hint or choice.
    promptSource_ = ctx.waits ? QString() : QString::fromStdString(ex.prompt.in(ctx.lang));
    prompt_->setText(promptSource_.isEmpty() ? QString() : markdownForLabel(promptSource_));
    feedback_->clear();
    feedback_->setStyleSheet({});
    hints_->clear();
    hintsSource_.clear();
    hints_->hide();
    hintButton_->setEnabled(!ex.hints.empty());
    hintButton_->setText(tr("Hint"));
    inputs_->show(ex, ctx);
}

void ExerciseBox::showHints(const QString& markdown, bool more) {
    hintsSource_ = markdown;
    hints_->setText(markdownForLabel(hintsSource_));
    hints_->show();
    scroll_->ensureWidgetVisible(hints_);
    hintButton_->setEnabled(more);
    hintButton_->setText(more ? tr("Next hint") : tr("No more hints"));
}

void ExerciseBox::say(Tone tone, const QString& text) {
    static const char* const kColour[] = {"color: #b36b00", "color: #1a7f37", "color: #c62828",
                                          "color: #1f4e99"};
    feedback_->setStyleSheet(QLatin1String(kColour[static_cast<int>(tone)]));
    feedback_->setText(text);
}

void ExerciseBox::setCorrect(bool correct) {
    feedback_->setProperty("correct", correct);
}

bool ExerciseBox::correct() const {
    return feedback_->property("correct").toBool();
}

QString ExerciseBox::feedback() const {
    return feedback_->text();
}

void ExerciseBox::showFeedback() {
    scroll_->ensureWidgetVisible(feedback_);
}

QString ExerciseBox::exploreNote() const {
    return exploreNote_->text();
}

QString ExerciseBox::waitNote() const {
    return waitNote_->text();
}

void ExerciseBox::fitScroll(int cap) {
    scroll_->fit(cap);
}

void ExerciseBox::setState(const State& s) {
    setTitle(s.mode == LessonMode::Presenting ? tr("Question for the room")
             : s.mode == LessonMode::Lecturer ? tr("Exercise (answers shown)")
                                              : tr("Exercise"));
    label_->setText(tr("Exercise %1 / %2%3")
                        .arg(s.index + 1)
                        .arg(s.count)
                        .arg(s.solved ? tr(" (solved)") : QString()));
    openButton_->setText(s.open ? tr("Put away") : tr("Try it"));
    const bool quiz = s.mode == LessonMode::Quiz;
    openButton_->setToolTip(
        s.open ? (quiz ? tr("Put the exercise away: the replay may then go past its "
                            "position")
                       : tr("Put the exercise away"))
               : (quiz ? tr("Open the exercise: the replay stops at its position "
                            "until you answer")
                       : tr("Open the exercise: the replay goes to its position")));
    openButton_->setVisible(!s.waitsFor);
    if (s.waitsFor)
        waitNote_->setText(tr("Exercise %1 waits for exercise %2: answer that one, or put "
                              "it away, to read this one.")
                               .arg(s.index + 1)
                               .arg(*s.waitsFor + 1));
    // While exploring, the exercises wait: they are graded against the lesson's own trace,
    // and the open one's prompt is put aside (the explored trace may hold its answer); Back
    // to the lesson shows it again, with its limit.
    const bool working = s.open && !s.exploring && !s.waitsFor;
    header_->setEnabled(!s.exploring);
    exploreNote_->setVisible(s.exploring);
    waitNote_->setVisible(!s.exploring && s.waitsFor);
    scroll_->setVisible(working);
    buttonRow_->setVisible(working);
    revealButton_->setVisible(!quiz);
}

}  // namespace raystep::gui
