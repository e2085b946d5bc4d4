#pragma once
// Lessons > Practice (docs/practice.md): a bar over the lesson panel to choose a topic and a
// level, and "New exercise", a fresh instance drawn by the topic's generator and opened as a
// lesson, answered and graded as any other. Each instance's result goes into the student's
// progress (course/progress.h): right, missed or open, and mastery at kMasteryStreak in a row.
#include "course/lesson.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QPushButton;
class QWidget;

namespace raystep::gui {

class LessonController;
class LessonPanel;

class PracticeController : public QObject {
    Q_OBJECT
  public:
    /// The bar goes over `panel`; the progress is `lessons`'.
    PracticeController(QObject* parent, LessonController& lessons, LessonPanel& panel);

    /// Lessons > Practice...: the bar, and a new instance of the topic and level it shows.
    void addLessonItems(QMenu* lessons);
    /// Draws a new instance of the chosen topic and level (never one the student was given).
    void newExercise();
    /// After a change of language: the combos' texts and the status again.
    void retranslate(Language lang);

  signals:
    void lessonRequested(const QString& id);

  private:
    std::string topic() const;
    std::string level() const;
    void lessonShown(const Lesson& lesson);
    void answerRecorded(const Lesson& lesson);
    void refresh();

    LessonController& lessons_;
    std::function<std::uint64_t()> draw_;  // a new seed
    QWidget* bar_ = nullptr;
    QComboBox* topics_ = nullptr;
    QComboBox* levels_ = nullptr;
    QPushButton* newButton_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* seedLabel_ = nullptr;
    QAction* practice_ = nullptr;
    std::optional<std::uint64_t> shownSeed_;  // the practice instance shown, if one is
};

}  // namespace raystep::gui
