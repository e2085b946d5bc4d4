#pragma once
// Which input answers which exercise kind: one table (answer_inputs.cpp), read by the exercise
// box. A new exercise kind adds its row there; a new way of answering adds an AnswerInput
// (answer_input.{h,cpp}) that its row names.
#include "answer_input.h"

#include <QBoxLayout>

#include <vector>

namespace raystep::gui {

using AnswerInputMaker = AnswerInput* (*)();

/// How an exercise kind is answered: the input that takes it and, for the text box, its rule.
struct AnswerInputRow {
    ExerciseKind kind;
    AnswerInputMaker make;  // kinds with the same maker share one input (and its widgets)
    TextBoxRule text;
};

/// The row of `kind`.
const AnswerInputRow& answerInputRow(ExerciseKind kind);

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
