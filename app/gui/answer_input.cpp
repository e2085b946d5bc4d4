// The answer inputs: each keeps its own widgets and reads its answer as the text parseAnswer
// takes, so the exercise box never asks which kind of exercise it shows.
#include "answer_input.h"

#include "language.h"

#include "course/exercise.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpressionValidator>
#include <QStringList>
#include <QVBoxLayout>

namespace raystep::gui {

namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

QVBoxLayout* tightLayout(QWidget* w) {
    auto* layout = new QVBoxLayout(w);
    layout->setContentsMargins(0, 0, 0, 0);
    return layout;
}

class TextBox final : public AnswerInput {
  public:
    TextBox() {
        QVBoxLayout* layout = tightLayout(this);
        line_ = new QLineEdit;
        line_->setObjectName("answer");
        layout->addWidget(line_);
        clear_ = new QPushButton(tr("Clear the cells"));
        clear_->setObjectName("clearSequence");
        clear_->setToolTip(tr("Start the order again"));
        layout->addWidget(clear_, 0, Qt::AlignRight);
        connect(clear_, &QPushButton::clicked, this, [this] {
            cells_.clear();
            line_->clear();
            emit cellsChanged(cells_);
        });
        // Typing a sequence replaces the clicked cells (the typed text is the answer).
        connect(line_, &QLineEdit::textEdited, this, [this] {
            if (cells_.isEmpty()) return;
            cells_.clear();
            emit cellsChanged(cells_);
        });
        connect(line_, &QLineEdit::returnPressed, this, &AnswerInput::submitted);
        number_ = new QRegularExpressionValidator(line_);
    }
    void prepare(const Exercise& ex, const AnswerContext& ctx, const TextBoxRule& rule) override {
        line_->setValidator(nullptr);
        if (rule.placeholder) line_->setPlaceholderText(rule.placeholder(ex, ctx));
        if (rule.number) {
            // A number box: digits, one sign, a decimal point, comma or the language's own
            // mark, an exponent.
            const QString mark = QRegularExpression::escape(
                QString::fromStdString(std::string(decimalMark(ctx.lang))));
            number_->setRegularExpression(QRegularExpression(
                QStringLiteral("[-+]?[0-9]*(([.,]|%1)[0-9]*)?([eE][-+]?[0-9]*)?").arg(mark)));
            line_->setValidator(number_);
        }
        appendCells_ = rule.cells == CellClick::Append;
        answerCell_ = rule.cells == CellClick::Answer;
        clear_->setVisible(appendCells_);
    }
    QString text() const override { return line_->text(); }
    void setAnswer(const QString& answer) override { line_->setText(answer); }
    void clear() override {
        // The cells a sequence answer clicked are drawn numbered on the grid: they go with it.
        if (!cells_.isEmpty()) {
            cells_.clear();
            emit cellsChanged(cells_);
        }
        line_->clear();
    }
    bool fillCell(int x, int y) override {
        if (appendCells_) {
            // The cells in the order clicked; checked when the student says so.
            cells_.append(QPoint(x, y));
            QStringList cells;
            for (const QPoint& c : cells_) cells << QStringLiteral("%1,%2").arg(c.x()).arg(c.y());
            line_->setText(cells.join(QStringLiteral("; ")));
            emit cellsChanged(cells_);
            return false;
        }
        if (!answerCell_) return false;
        line_->setText(QStringLiteral("%1,%2").arg(x).arg(y));
        return true;
    }

  private:
    QLineEdit* line_ = nullptr;
    QRegularExpressionValidator* number_ = nullptr;  // a number box's, one for every exercise
    QPushButton* clear_ = nullptr;                   // a sequence answer: start again
    QList<QPoint> cells_;  // cells clicked for a sequence answer, in order
    bool appendCells_ = false, answerCell_ = false;
};

class SplitPicker final : public AnswerInput {
  public:
    SplitPicker() {
        box_ = new QComboBox;
        box_->setObjectName("candidates");
        tightLayout(this)->addWidget(box_);
    }
    void prepare(const Exercise& ex, const AnswerContext& ctx, const TextBoxRule&) override {
        if (!ctx.log || ctx.waits) return;
        // The candidates without their cost: computing it is the exercise.
        for (const SplitCandidate& c : splitCandidates(ex, *ctx.log))
            box_->addItem(
                QStringLiteral("%1 = %2   (NL %3, NR %4, P(L|C) %5, P(R|C) %6)")
                    .arg(QChar("xyz"[c.axis]))
                    .arg(numberText(c.position, 'g', 6))
                    .arg(c.nl)
                    .arg(c.nr)
                    .arg(numberText(c.pl, 'g', 4), numberText(c.pr, 'g', 4)),
                QStringLiteral("%1=%2").arg(QChar("xyz"[c.axis])).arg(c.position, 0, 'g', 17));
    }
    QString text() const override { return box_->currentData().toString(); }
    void setAnswer(const QString& answer) override {
        const int i = box_->findData(answer);
        if (i >= 0) box_->setCurrentIndex(i);
    }
    void clear() override { box_->clear(); }

  private:
    QComboBox* box_ = nullptr;
};

class OptionButtons final : public AnswerInput {
  public:
    OptionButtons() {
        setObjectName("choices");
        tightLayout(this);
        group_ = new QButtonGroup(this);
    }
    void prepare(const Exercise& ex, const AnswerContext& ctx, const TextBoxRule&) override {
        // Hidden while its buttons are made, then shown with them (a button added to a shown
        // widget shows only once the event loop runs).
        hide();
        if (ctx.waits) return;
        for (std::size_t k = 0; k < ex.choices.size(); ++k) {
            auto* b = new QRadioButton(QStringLiteral("%1) %2")
                                           .arg(QChar('a' + static_cast<int>(k)))
                                           .arg(q(ex.choices[k].text.in(ctx.lang))));
            b->setObjectName(QStringLiteral("choice%1").arg(k));
            group_->addButton(b, static_cast<int>(k));
            layout()->addWidget(b);
        }
        show();
    }
    QString text() const override {
        return group_->checkedId() < 0 ? QString() : QString::number(group_->checkedId() + 1);
    }
    void setAnswer(const QString& answer) override {
        // "b" or "2": the radio button a student would click.
        const QString a = answer.trimmed().toLower();
        bool number = false;
        const int n = a.toInt(&number);
        const int i = number ? n - 1 : (a.size() == 1 ? a[0].unicode() - 'a' : -1);
        if (QAbstractButton* b = group_->button(i)) b->setChecked(true);
    }
    void clear() override {
        for (QAbstractButton* b : group_->buttons()) {
            group_->removeButton(b);
            delete b;
        }
    }
    bool choosesAnOption() const override { return true; }

  private:
    QButtonGroup* group_ = nullptr;
};

class SweepPicker final : public AnswerInput {
  public:
    SweepPicker() {
        box_ = new QComboBox;
        box_->setObjectName("sweepPicker");
        tightLayout(this)->addWidget(box_);
    }
    void prepare(const Exercise&, const AnswerContext& ctx, const TextBoxRule&) override {
        hide();  // made anew, as the options' buttons are
        box_->clear();
        if (ctx.resolutions)
            for (int r : *ctx.resolutions) box_->addItem(tr("%1 cells per axis").arg(r), r);
        show();
    }
    QString text() const override {
        return box_->currentIndex() < 0 ? QString() : QString::number(box_->currentData().toInt());
    }
    void setAnswer(const QString& answer) override {
        const int i = box_->findData(answer.trimmed().toInt());
        if (i >= 0) box_->setCurrentIndex(i);
    }
    void clear() override { box_->clear(); }
    bool choosesAnOption() const override { return true; }
    bool needsSweep() const override { return true; }

  private:
    QComboBox* box_ = nullptr;
};

}  // namespace

AnswerInput* makeTextBox() {
    return new TextBox;
}
AnswerInput* makeSplitPicker() {
    return new SplitPicker;
}
AnswerInput* makeOptionButtons() {
    return new OptionButtons;
}
AnswerInput* makeSweepPicker() {
    return new SweepPicker;
}

}  // namespace raystep::gui
