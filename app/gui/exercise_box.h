#pragma once
// The lesson panel's exercise box: its header (previous, next, Try it / Put away), the notes
// on why it waits, the prompt, the answer input, the hints and the feedback, and the Check,
// Hint and Show answer buttons. It shows what the panel tells it; the panel grades.
#include "answer_inputs.h"
#include "lesson_mode.h"

#include <QGroupBox>
#include <QList>
#include <QPoint>

#include <memory>
#include <optional>

class QLabel;
class QPushButton;

namespace raystep::gui {

class ExerciseScroll;

class ExerciseBox : public QGroupBox {
    Q_OBJECT
  public:
    explicit ExerciseBox(QWidget* parent = nullptr);
    ~ExerciseBox() override;

    /// Exercise `ex` afresh: its prompt (none while it waits for a held one), no hints, no
    /// feedback, its answer input ready and empty.
    void showExercise(const Exercise& ex, const AnswerContext& ctx);
    /// Every answer input emptied, their clicked cells too (no lesson).
    void clearAnswer() { inputs_->clear(); }
    /// The shown exercise's input.
    AnswerInput* input() const { return inputs_->current(); }
    /// The prompt and the hints so far, as the lesson's Markdown gives them.
    QString promptText() const { return promptSource_; }
    QString hintsText() const { return hintsSource_; }
    /// The hints revealed so far; `more`: Hint shows one more.
    void showHints(const QString& markdown, bool more);

    /// The feedback's colour: a note (not graded), right, wrong, an answer revealed.
    enum class Tone { Note, Right, Wrong, Answer };
    void say(Tone tone, const QString& text);
    /// Whether the last check was right (submit reads it).
    void setCorrect(bool correct);
    bool correct() const;
    QString feedback() const;
    /// The feedback scrolled into sight.
    void showFeedback();

    /// What the header and the notes show, from the panel's state.
    struct State {
        LessonMode mode = LessonMode::Quiz;
        int index = 0, count = 0;
        bool solved = false;
        bool open = false;            // the student works on it (the replay stops at its position)
        std::optional<int> waitsFor;  // the held exercise it waits for
        bool exploring = false;
    };
    void setState(const State& s);
    /// Why the exercises wait while the student explores, and why this one waits (check()
    /// says the same when called meanwhile).
    QString exploreNote() const;
    QString waitNote() const;
    /// The most the prompt, hints and feedback take before they scroll.
    void fitScroll(int cap);

  signals:
    void previousRequested();
    void nextRequested();
    /// Try it / Put away.
    void openClicked();
    void checkRequested();
    void hintRequested();
    void revealRequested();
    /// The cells of a sequence answer so far.
    void cellsChanged(const QList<QPoint>& cells);

  private:
    std::unique_ptr<AnswerInputs> inputs_;
    QWidget* header_ = nullptr;
    QLabel* label_ = nullptr;
    QPushButton* openButton_ = nullptr;
    QLabel* exploreNote_ = nullptr;
    QLabel* waitNote_ = nullptr;  // an exercise after a held one: what it waits for
    ExerciseScroll* scroll_ = nullptr;
    QWidget* body_ = nullptr;
    QWidget* buttonRow_ = nullptr;
    QLabel* prompt_ = nullptr;
    QLabel* hints_ = nullptr;
    QString promptSource_, hintsSource_;  // their Markdown, as the lesson gives it
    QPushButton* checkButton_ = nullptr;
    QPushButton* hintButton_ = nullptr;
    QPushButton* revealButton_ = nullptr;
    QLabel* feedback_ = nullptr;
};

}  // namespace raystep::gui
