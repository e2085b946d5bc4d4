#include "lesson_text.h"

#include "presentation.h"

#include <QTextBlock>
#include <QTextTable>

#include <algorithm>

namespace raystep::gui {

namespace {
QString q(const std::string& s) {
    return QString::fromStdString(s);
}
}  // namespace

LessonText::LessonText(QWidget* parent) : QTextBrowser(parent) {
    setObjectName("lessonText");
    setOpenExternalLinks(true);
    // A few lines of the step's text however tall the exercise box grows (1366x768).
    setMinimumHeight(100);  // five lines: the window still fits 1024x600
}

void LessonText::wrapLongLines() {
    // Markdown's code blocks are laid out unbroken: in a narrow panel (a 1366x768 laptop) their
    // lines ran off the side. Every line may wrap, at a word if it can, else anywhere.
    setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    QTextCursor c(document());
    for (QTextBlock b = document()->begin(); b.isValid(); b = b.next())
        if (b.blockFormat().nonBreakableLines()) {
            c.setPosition(b.position());
            QTextBlockFormat f;
            f.setNonBreakableLines(false);
            c.mergeBlockFormat(f);
        }
    codeFollowsTextSize(*document());  // the zoom enlarges code and formulas too
}

void LessonText::showMarkdown(const QString& markdown) {
    stepAnchor_ = -1;
    setMarkdown(markdown);
    wrapLongLines();
}

void LessonText::appendErrata(QTextCursor& at, const std::vector<Erratum>& errata, Language lang) {
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
                                .arg(q(erratumHeading(lang)), tr("The slide:"), q(e.slide.in(lang)),
                                     tr("Correct:"), q(e.correct.in(lang)), q(e.why.in(lang))));
        at.movePosition(QTextCursor::End);
    }
}

void LessonText::showLesson(const Lesson& lesson, int step, std::optional<int> waitsFor,
                            bool errata, Language lang) {
    setMarkdown(QStringLiteral("# %1\n\n%2\n")
                    .arg(q(lessonHeading(lesson, lang)), q(lesson.text.in(lang))));
    QTextCursor at(document());
    at.movePosition(QTextCursor::End);
    if (errata) appendErrata(at, lesson.errata, lang);
    stepAnchor_ = -1;
    if (!lesson.steps.empty()) {
        const LessonStep& s = lesson.steps[step];
        // A step past an unsolved exercise's position tells what comes after it: its text, its
        // computed note and its notes on the slides wait with the replay (a step may name the
        // next cell or the count the exercise asks for).
        const bool waits = waitsFor.has_value();
        const QString text =
            waits ? tr("This step comes after exercise %1: answer it, or put it away, to read it.")
                        .arg(*waitsFor + 1)
                  : q(s.text.in(lang));
        QString md = QStringLiteral("\n---\n\n**%1 %2 / %3.** %4\n")
                         .arg(tr("Step"))
                         .arg(step + 1)
                         .arg(lesson.steps.size())
                         .arg(text);
        // A computed note (the slides' DDA loop beside the exact walk), as a quote under the step.
        if (!waits && !s.note.en.empty()) md += QStringLiteral("\n> %1\n").arg(q(s.note.in(lang)));
        at.movePosition(QTextCursor::End);
        // A plain block: one inserted after a text ending in a list would be an empty bullet.
        at.insertBlock(QTextBlockFormat(), QTextCharFormat());
        stepAnchor_ = at.position();
        at.insertMarkdown(md);
        if (!waits && errata) appendErrata(at, s.errata, lang);
    }
    wrapLongLines();
    keepStepInView();
}

void LessonText::keepStepInView() {
    if (stepAnchor_ < 0) {
        moveCursor(QTextCursor::Start);
        return;
    }
    // The step's text is what the lecturer points at: in sight, from its heading down, however
    // long the notes on the slides under it are. From the end back to the heading: the
    // smallest scroll that shows it puts the heading at the top when the whole does not fit.
    moveCursor(QTextCursor::End);
    ensureCursorVisible();
    QTextCursor c(document());
    // The rule (---) the markdown puts first: the step's own heading is the block after it.
    c.setPosition(std::min(stepAnchor_, document()->characterCount() - 1));
    setTextCursor(c);
    ensureCursorVisible();
}

}  // namespace raystep::gui
