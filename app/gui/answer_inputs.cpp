// The table of answer inputs: for each input the course asks for (answerInput: a text line, a
// number box, the split's candidates, options, the sweep's rows), the widget that takes it. The
// one place that says how an answer is entered; which kind wants which is the kind's own
// (app/course/exercises/<kind>.cpp), so a new kind answered in an existing way adds nothing here.
#include "answer_inputs.h"

#include "course/exercise.h"

#include <algorithm>
#include <stdexcept>

namespace raystep::gui {

namespace {

// The course's words for the box, for the trace's dimensions and in the panel's language.
QString coursePlaceholder(const Exercise& ex, const AnswerContext& ctx) {
    return QString::fromStdString(answerPlaceholder(ex, ctx.dims, ctx.lang));
}

const AnswerInputRow kRows[] = {
    {AnswerInputSpec::Widget::Text, makeTextBox, false},
    {AnswerInputSpec::Widget::Number, makeTextBox, true},
    {AnswerInputSpec::Widget::SplitPicker, makeSplitPicker, false},
    {AnswerInputSpec::Widget::Options, makeOptionButtons, false},
    {AnswerInputSpec::Widget::SweepRows, makeSweepPicker, false},
};

CellClick cellClickOf(AnswerInputSpec::ViewClick click) {
    switch (click) {
        case AnswerInputSpec::ViewClick::Fills:
            return CellClick::Answer;
        case AnswerInputSpec::ViewClick::Appends:
            return CellClick::Append;
        case AnswerInputSpec::ViewClick::None:
            break;
    }
    return CellClick::None;
}

}  // namespace

const AnswerInputRow& answerInputRow(AnswerInputSpec::Widget widget) {
    for (const AnswerInputRow& row : kRows)
        if (row.widget == widget) return row;
    throw std::logic_error("answer_inputs.cpp: no widget for answer input " +
                           std::to_string(static_cast<int>(widget)));
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
    const AnswerInputSpec spec = answerInput(ex);
    const AnswerInputRow& row = answerInputRow(spec.widget);
    for (const auto& [make, input] : made_)
        if (make == row.make) current_ = input;
    for (AnswerInput* input : inputs_) input->setVisible(input == current_);
    TextBoxRule rule;
    if (row.make == makeTextBox) {
        rule.placeholder = coursePlaceholder;
        rule.number = row.number;
        rule.cells = cellClickOf(spec.click);
    }
    current_->prepare(ex, ctx, rule);
    return current_;
}

}  // namespace raystep::gui
