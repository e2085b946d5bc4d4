// The timeline: its buttons and scrubber move the session's replay cursor; a timer plays it.
#include "timeline.h"

#include "event_list.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace raystep::gui {

namespace {
// Event kinds the timeline can jump to (N), by variant index, in the order the combo lists them.
const std::size_t kJumpKinds[] = {
    variantIndex<DdaCell>(),     variantIndex<PrimitiveTest>(),  variantIndex<MailboxSkip>(),
    variantIndex<NodeEnter>(),   variantIndex<RayBegin>(),       variantIndex<RayHit>(),
    variantIndex<SplitChosen>(), variantIndex<SplitCandidate>(), variantIndex<BuildNode>(),
    variantIndex<LeafMade>(),    variantIndex<DdaSetup>(),       variantIndex<NodeSkip>(),
    variantIndex<ShadingTerm>(),
};

}  // namespace

Timeline::Timeline(Session& s, QWidget* parent) : QWidget(parent), session_(s) {
    // The controls in a row; the quiz cue under them, only while an exercise stops the replay
    // (beside them it squeezed the scrubber to nothing at 1366 pixels).
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(6, 2, 6, 2);
    rows->setSpacing(2);
    auto* tl = new QHBoxLayout;
    rows->addLayout(tl);
    const auto button = [&](const QString& text, const QString& tip, auto slot) {
        auto* b = new QToolButton;
        b->setText(text);
        b->setToolTip(tip);
        connect(b, &QToolButton::clicked, this, slot);
        tl->addWidget(b);
        return b;
    };
    button(QStringLiteral("|<"), tr("First event (Home)"), [this] { session_.setCursor(0); });
    button(QStringLiteral("<"), tr("Step back (Left)"), [this] { stepBack(); });
    play_ = button(QStringLiteral(">"), tr("Play / pause (Space)"), [this] { togglePlay(); });
    button(QStringLiteral(">|"), tr("Step forward (Right)"), [this] { stepForward(); });
    kindCombo_ = new QComboBox;
    kindCombo_->setObjectName("jumpKind");
    for (const std::size_t kind : kJumpKinds)
        kindCombo_->addItem(eventKindLabel(kind), QVariant::fromValue<qulonglong>(kind));
    tl->addWidget(kindCombo_);
    button(tr("next"), tr("Jump to the next event of this kind (N)"),
           [this] { jumpToNextOfKind(); });
    tl->addWidget(new QLabel(tr("speed")));
    speed_ = new QSpinBox;
    speed_->setRange(1, 200);
    speed_->setValue(4);
    speed_->setSuffix(tr(" /s"));
    tl->addWidget(speed_);
    scrubber_ = new QSlider(Qt::Horizontal);
    tl->addWidget(scrubber_, 1);
    position_ = new QLabel;
    position_->setObjectName("position");
    tl->addWidget(position_);
    // Quiz mode: why the replay stops at an open exercise.
    quizCue_ = new QLabel(tr("Answer the exercise to see what comes next"));
    quizCue_->setObjectName("quizCue");
    quizCue_->setStyleSheet(
        QStringLiteral("#quizCue { background: #fff4d6; color: #5a4300; padding: 2px 6px; "
                       "border: 1px solid #e0c070; border-radius: 3px; }"));
    quizCue_->hide();
    rows->addWidget(quizCue_, 0, Qt::AlignRight);
    connect(scrubber_, &QSlider::valueChanged, this,
            [this](int v) { session_.setCursor(static_cast<std::size_t>(v)); });

    timer_ = new QTimer(this);
    connect(timer_, &QTimer::timeout, this, [this] {
        if (session_.cursor() >= session_.end()) return togglePlay();
        stepForward();
    });
    connect(speed_, &QSpinBox::valueChanged, this,
            [this](int v) { timer_->setInterval(1000 / v); });
    timer_->setInterval(1000 / speed_->value());
    connect(&session_, &Session::cursorChanged, this, [this] { updateTimeline(); });
    connect(&session_, &Session::limitChanged, this, [this] { updateTimeline(); });
    connect(&session_, &Session::shownChanged, this, [this] { updateTimeline(); });
}

void Timeline::stepForward() {
    session_.setCursor(session_.cursor() + 1);
}
void Timeline::stepBack() {
    if (session_.cursor() > 0) session_.setCursor(session_.cursor() - 1);
}
void Timeline::jumpToNextOfKind() {
    const std::size_t at = session_.replay().nextOfKind(session_.cursor(), jumpKind());
    // Past an open exercise the session stops it at the exercise (quiz mode).
    session_.setCursor(at < session_.size() ? at + 1 : session_.size());
}

bool Timeline::setJumpKind(std::size_t eventKind) {
    const int i = kindCombo_->findData(QVariant::fromValue<qulonglong>(eventKind));
    if (i < 0) return false;
    kindCombo_->setCurrentIndex(i);
    return true;
}

std::size_t Timeline::jumpKind() const {
    return static_cast<std::size_t>(kindCombo_->currentData().toULongLong());
}

QString Timeline::quizCue() const {
    return quizCue_->isHidden() ? QString() : quizCue_->text();
}
void Timeline::togglePlay() {
    if (timer_->isActive()) {
        timer_->stop();
        play_->setText(QStringLiteral(">"));
    } else {
        if (session_.cursor() >= session_.end()) session_.setCursor(0);
        timer_->start();
        play_->setText(QStringLiteral("||"));
    }
}

void Timeline::updateTimeline() {
    const QSignalBlocker block(scrubber_);
    // In quiz mode the scrubber ends at the exercise: what lies past it is not shown.
    scrubber_->setRange(0, static_cast<int>(session_.end()));
    scrubber_->setValue(static_cast<int>(session_.cursor()));
    // A question to the room: the trace's length is not told (the scrubber still reaches it).
    position_->setText(session_.hidesAhead()
                           ? QString::number(session_.cursor())
                           : tr("%1 / %2").arg(session_.cursor()).arg(session_.end()));
    quizCue_->setVisible(session_.limit().has_value());
}

}  // namespace raystep::gui
