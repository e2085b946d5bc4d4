#pragma once
// The timeline under the views: step, play, jump to the next event of a kind, speed, and the
// scrubber over the replayed log.
#include "session.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QTimer;
class QToolButton;

namespace raystep::gui {

class Timeline : public QWidget {
    Q_OBJECT
  public:
    explicit Timeline(Session& s, QWidget* parent = nullptr);

  public slots:
    void stepForward();
    void stepBack();
    /// To just after the next event of the kind chosen in the combo box (or to the end).
    void jumpToNextOfKind();
    void togglePlay();
    /// The scrubber and the position label, from the session's cursor.
    void updateTimeline();

  public:
    /// N jumps to events of this kind (a variant index of Event); false if the combo lacks it.
    bool setJumpKind(std::size_t eventKind);
    /// The variant index N jumps to now.
    std::size_t jumpKind() const;
    /// The quiz cue ("Answer the exercise to see what comes next"), shown while a limit holds.
    QString quizCue() const;

  private:
    Session& session_;
    QComboBox* kindCombo_ = nullptr;
    QSpinBox* speed_ = nullptr;
    QSlider* scrubber_ = nullptr;
    QLabel* position_ = nullptr;
    QLabel* quizCue_ = nullptr;
    QToolButton* play_ = nullptr;
    QTimer* timer_ = nullptr;
};

}  // namespace raystep::gui
