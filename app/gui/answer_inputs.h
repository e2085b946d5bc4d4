#pragma once
// Which widget takes which answer input: one table (answer_inputs.cpp), keyed by the input the
// course asks for (course/exercise.h, answerInput), read by the exercise box. A new way of
// answering adds an AnswerInput (answer_input.{h,cpp}) and its row there.
#include "answer_input.h"

#include "course/exercise.h"

#include <QBoxLayout>

#include <vector>

namespace raystep::gui {

using AnswerInputMaker = AnswerInput* (*)();

/// How an answer input is taken: the widget that takes it (inputs with the same maker share one
/// widget), and whether a text box refuses letters.
struct AnswerInputRow {
    AnswerInputSpec::Widget widget;
    AnswerInputMaker make;
    bool number = false;
};

/// The row of `widget`.
const AnswerInputRow& answerInputRow(AnswerInputSpec::Widget widget);

/// The exercise box's inputs: one of each that the table names, made once in the table's order
/// (a student's focus, or a test, keeps hold of the text box across exercises), the one the
/// shown exercise takes visible.
class AnswerInputs {
  public:
    /// Makes the inputs into `layout`.
    explicit AnswerInputs(QBoxLayout* layout);
    /// Every input emptied, then the one `ex` takes made ready for it and shown, the others hidden.
    AnswerInput* show(const Exercise& ex, const AnswerContext& ctx);
    /// Every input emptied (their clicked cells too).
    void clear();
    /// The input the last shown exercise takes (the first made before any is shown).
    AnswerInput* current() const { return current_; }
    const std::vector<AnswerInput*>& all() const { return inputs_; }

  private:
    std::vector<std::pair<AnswerInputMaker, AnswerInput*>> made_;
    std::vector<AnswerInput*> inputs_;
    AnswerInput* current_ = nullptr;
};

}  // namespace raystep::gui
