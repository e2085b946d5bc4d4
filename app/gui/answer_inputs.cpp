// The table of answer inputs: for each exercise kind, the input that takes its answer and, for
// the text box, its placeholder, whether only a number can be typed and what a cell clicked in
// the 2D view does. The one place that says how a kind is answered.
#include "answer_inputs.h"

#include "course/exercise.h"

#include <QObject>

#include <algorithm>

#include <stdexcept>

namespace raystep::gui {

namespace {

// A cell or a sequence: the cell's indices for the trace's dimensions (the course's words).
QString cellPlaceholder(const Exercise& ex, const AnswerContext& ctx) {
    return QString::fromStdString(answerPlaceholder(ex, ctx.dims, ctx.lang));
}

const AnswerInputRow kRows[] = {
    {ExerciseKind::NextCell, makeTextBox, {cellPlaceholder, false, CellClick::Answer}},
    {ExerciseKind::Value, makeTextBox, {[](const Exercise&, const AnswerContext&) {
         return QObject::tr("a number, e.g. 1.25");
     }}},
    {ExerciseKind::PickSplit, makeSplitPicker, {}},
    {ExerciseKind::Count, makeTextBox, {[](const Exercise&, const AnswerContext&) {
         return QObject::tr("a whole number");
     }}},
    {ExerciseKind::HitOrMiss, makeTextBox, {[](const Exercise& ex, const AnswerContext&) {
         return ex.withT ? QObject::tr("hit T, or miss") : QObject::tr("hit or miss");
     }}},
    {ExerciseKind::Choice, makeOptionButtons, {}},
    {ExerciseKind::Sequence, makeTextBox, {cellPlaceholder, false, CellClick::Append}},
    {ExerciseKind::SweepPick, makeSweepPicker, {}},
    {ExerciseKind::Compute,
     makeTextBox,
     {[](const Exercise&, const AnswerContext&) {
          return QObject::tr("your result, a number (e.g. -2.5 or 0,75)");
      },
      true}},
    {ExerciseKind::Overlap, makeTextBox, {cellPlaceholder}},
};

}  // namespace

const AnswerInputRow& answerInputRow(ExerciseKind kind) {
    for (const AnswerInputRow& row : kRows)
        if (row.kind == kind) return row;
    throw std::logic_error("answer_inputs.cpp: no answer input for exercise kind " +
                           std::string(exerciseKindName(kind)));
}

AnswerInputs::AnswerInputs(QBoxLayout* layout) {
    for (const AnswerInputRow& row : kRows) {
        const bool made = std::any_of(made_.begin(), made_.end(),
                                      [&](const auto& m) { return m.first == row.make; });
        if (made) continue;
        AnswerInput* input = row.make();
        layout->addWidget(input);
        made_.emplace_back(row.make, input);
        inputs_.push_back(input);
    }
    current_ = inputs_.front();
}

void AnswerInputs::clear() {
    for (AnswerInput* input : inputs_) input->clear();
}

AnswerInput* AnswerInputs::show(const Exercise& ex, const AnswerContext& ctx) {
    clear();
    const AnswerInputRow& row = answerInputRow(ex.kind);
    for (const auto& [make, input] : made_)
        if (make == row.make) current_ = input;
    for (AnswerInput* input : inputs_) input->setVisible(input == current_);
    current_->prepare(ex, ctx, row.text);
    return current_;
}

}  // namespace raystep::gui
