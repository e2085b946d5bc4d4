// The timeline: its buttons and scrubber move the session's replay cursor; a timer plays it.
#include "timeline.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>

namespace raystep::gui {

namespace {
// Event kinds the timeline can jump to, with their variant index.
const std::pair<const char*, std::size_t> kJumpKinds[] = {
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "DDA step"), variantIndex<DdaCell>()},
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "primitive test"), variantIndex<PrimitiveTest>()},
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "mailbox skip"), variantIndex<MailboxSkip>()},
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "node enter"), variantIndex<NodeEnter>()},
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "ray begin"), variantIndex<RayBegin>()},
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "hit"), variantIndex<RayHit>()},
    {QT_TRANSLATE_NOOP("raystep::gui::Timeline", "split chosen"), variantIndex<SplitChosen>()},
};
}  // namespace

Timeline::Timeline(Session& s, QWidget* parent) : QWidget(parent), session_(s) {
    auto* tl = new QHBoxLayout(this);
    tl->setContentsMargins(6, 2, 6, 2);
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
    // i18n: the kinds' names are marked with QT_TRANSLATE_NOOP in kJumpKinds.
    for (const auto& [name, kind] : kJumpKinds) kindCombo_->addItem(tr(name));
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
    tl->addWidget(position_);
    connect(scrubber_, &QSlider::valueChanged, this,
            [this](int v) { session_.setCursor(static_cast<std::size_t>(v)); });

    timer_ = new QTimer(this);
    connect(timer_, &QTimer::timeout, this, [this] {
        if (session_.cursor() >= session_.size()) return togglePlay();
        stepForward();
    });
    connect(speed_, &QSpinBox::valueChanged, this,
            [this](int v) { timer_->setInterval(1000 / v); });
    timer_->setInterval(1000 / speed_->value());
    connect(&session_, &Session::cursorChanged, this, [this] { updateTimeline(); });
}

void Timeline::stepForward() {
    session_.setCursor(session_.cursor() + 1);
}
void Timeline::stepBack() {
    if (session_.cursor() > 0) session_.setCursor(session_.cursor() - 1);
}
void Timeline::jumpToNextOfKind() {
    const std::size_t kind = kJumpKinds[std::max(0, kindCombo_->currentIndex())].second;
    const std::size_t at = session_.replay().nextOfKind(session_.cursor(), kind);
    session_.setCursor(at < session_.size() ? at + 1 : session_.size());
}
void Timeline::togglePlay() {
    if (timer_->isActive()) {
        timer_->stop();
        play_->setText(QStringLiteral(">"));
    } else {
        if (session_.cursor() >= session_.size()) session_.setCursor(0);
        timer_->start();
        play_->setText(QStringLiteral("||"));
    }
}

void Timeline::updateTimeline() {
    const QSignalBlocker block(scrubber_);
    scrubber_->setRange(0, static_cast<int>(session_.size()));
    scrubber_->setValue(static_cast<int>(session_.cursor()));
    position_->setText(tr("%1 / %2").arg(session_.cursor()).arg(session_.size()));
}

}  // namespace raystep::gui
