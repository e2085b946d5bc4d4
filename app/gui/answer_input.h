#pragma once
// One way of answering an exercise in the exercise box: a text box, the split picker, the
// option buttons, the sweep's resolutions. The panel asks the shown input for the answer as
// text and never which kind of exercise it holds; which input takes which kind is one table
// (answer_inputs.cpp).
#include "course/lesson.h"

#include "raystep/base/i18n.h"
#include "raystep/trace/events.h"

#include <QList>
#include <QPoint>
#include <QString>
#include <QWidget>

#include <vector>

namespace raystep::gui {

/// What an input needs to get ready for an exercise besides the exercise.
struct AnswerContext {
    Language lang = Language::En;
    const EventLog* log = nullptr;  // the exercise's trace (null: the lesson has none)
    int dims = 2;                   // the lesson's trace's dimensions: cells are X,Y or X,Y,Z
    const std::vector<int>* resolutions = nullptr;  // the lesson's sweep, if it has one
    bool waits = false;  // the exercise waits for a held one: none of its options is shown
};

/// What the text box does for one exercise (ignored by the other inputs).
enum class CellClick {
    None,    // a click in the 2D view does nothing
    Answer,  // the clicked cell is the answer, checked at once
    Append,  // the cells in the order clicked (not an order of nodes), checked when asked
};
struct TextBoxRule {
    /// The placeholder; null keeps the box's last one (another input is shown).
    QString (*placeholder)(const Exercise&, const AnswerContext&) = nullptr;
    bool number = false;  // a number box: a letter cannot be typed
    CellClick cells = CellClick::None;
};

class AnswerInput : public QWidget {
    Q_OBJECT
  public:
    using QWidget::QWidget;
    /// Made ready for `ex`, empty: its placeholder, candidates or options.
    virtual void prepare(const Exercise& ex, const AnswerContext& ctx, const TextBoxRule& rule) = 0;
    /// The answer as parseAnswer reads it ("" when nothing is typed or chosen yet).
    virtual QString text() const = 0;
    /// An answer as typed (LessonPanel::submit): the text, or the option or candidate it names.
    virtual void setAnswer(const QString& answer) = 0;
    /// Forgets the last exercise's answer, options and clicked cells.
    virtual void clear() = 0;
    /// A cell clicked in the 2D view; true when it is the whole answer (check it now).
    virtual bool fillCell(int /*x*/, int /*y*/) { return false; }
    /// The answer is one of a list of options: nothing chosen is no answer to read.
    virtual bool choosesAnOption() const { return false; }
    /// The answer is graded from the sweep's table, which must have run.
    virtual bool needsSweep() const { return false; }

  signals:
    /// Return pressed in a text box: check the answer.
    void submitted();
    /// The cells of a sequence answer so far (the 2D view numbers them); empty when none.
    void cellsChanged(const QList<QPoint>& cells);
};

// The inputs there are, each made by one function that the table of answer_inputs.cpp names
// (answer_input.cpp).

/// A line to type the answer in: its placeholder, a number box where the rule says, the cells
/// clicked in the 2D view (one answering at once, or several in order with Clear to start again).
AnswerInput* makeTextBox();
/// The split planes of the node a PickSplit exercise is about, without their cost.
AnswerInput* makeSplitPicker();
/// One radio button an option of a Choice, lettered as a student may also type them.
AnswerInput* makeOptionButtons();
/// The sweep's resolutions (SweepPick), graded from the sweep's table.
AnswerInput* makeSweepPicker();

}  // namespace raystep::gui
