#pragma once
// The lesson panel's text: the lesson's title and text, its notes on the slides (errata), and
// the step shown, kept in sight as the panel's room changes.
#include "course/lesson.h"

#include "raystep/base/i18n.h"

#include <QTextBrowser>
#include <QTextCursor>

#include <optional>
#include <vector>

namespace raystep::gui {

class LessonText : public QTextBrowser {
    Q_OBJECT
  public:
    explicit LessonText(QWidget* parent = nullptr);
    /// Free text (no lesson open).
    void showMarkdown(const QString& markdown);
    /// The lesson's text and step `step`; `waitsFor`: the step comes after the position of that
    /// unsolved exercise, so its text, note and errata wait; `errata`: the notes on the slides.
    void showLesson(const Lesson& lesson, int step, std::optional<int> waitsFor, bool errata,
                    Language lang);
    /// Scrolls the text so the step's own text is in sight (its heading at the top when the
    /// whole does not fit), not the notes under it.
    void keepStepInView();

  private:
    /// The lesson's or a step's slide errata, as marked boxes at the end of the text.
    void appendErrata(QTextCursor& at, const std::vector<Erratum>& errata, Language lang);
    /// Markdown's code blocks wrap as the other lines do.
    void wrapLongLines();

    int stepAnchor_ = -1;  // where the step's text starts in the lesson text
};

}  // namespace raystep::gui
