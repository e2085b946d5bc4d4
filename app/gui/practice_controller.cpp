// The practice bar: a topic, a level, "New exercise", and the student's streak towards mastery.
#include "practice_controller.h"

#include "lesson_controller.h"
#include "lesson_panel.h"

#include "course/practice/practice.h"
#include "course/progress.h"

#include <QAction>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSettings>

namespace raystep::gui {

namespace {
QString q(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}
constexpr PracticeLevel kLevels[] = {PracticeLevel::Easy, PracticeLevel::Medium,
                                     PracticeLevel::Hard};
}  // namespace

PracticeController::PracticeController(QObject* parent, LessonController& lessons,
                                       LessonPanel& panel)
    : QObject(parent),
      lessons_(lessons),
      // Nine digits: a seed a lecturer reads off the bar and types into `practice make`.
      draw_([] { return QRandomGenerator::global()->bounded(Q_UINT64_C(1'000'000'000)); }) {
    bar_ = new QWidget;
    bar_->setObjectName("practiceBar");
    bar_->setStyleSheet(QStringLiteral("#practiceBar { background: #e8f1fb; }"));
    auto* grid = new QGridLayout(bar_);
    grid->setContentsMargins(6, 4, 6, 4);
    topics_ = new QComboBox;
    topics_->setObjectName("practiceTopic");
    levels_ = new QComboBox;
    levels_->setObjectName("practiceLevel");
    newButton_ = new QPushButton(tr("New exercise"));
    newButton_->setObjectName("newExercise");
    newButton_->setToolTip(tr("A new instance of this topic at this level (Ctrl+Shift+N)"));
    status_ = new QLabel;
    status_->setObjectName("practiceStatus");
    status_->setWordWrap(true);
    seedLabel_ = new QLabel;
    seedLabel_->setObjectName("practiceSeed");
    seedLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    seedLabel_->setStyleSheet(QStringLiteral("color: #4a4a4a"));
    // Two rows, so that the lesson's text (which states the instance's data) keeps its room on
    // a laptop's screen: what to practise, then how it is going.
    topics_->setToolTip(tr("Practice: the topic"));
    levels_->setToolTip(tr("Practice: the level"));
    grid->addWidget(topics_, 0, 0);
    grid->addWidget(levels_, 0, 1);
    grid->addWidget(newButton_, 0, 2);
    grid->addWidget(status_, 1, 0, 1, 2);
    grid->addWidget(seedLabel_, 1, 2, Qt::AlignRight | Qt::AlignTop);
    grid->setColumnStretch(0, 1);
    bar_->hide();
    panel.setHeader(bar_);
    retranslate(Language::En);

    // A topic or a level picked: an instance of it at once, as a lesson picked opens.
    for (QComboBox* combo : {topics_, levels_})
        connect(combo, &QComboBox::activated, this, [this] {
            QSettings().setValue("practice/topic", q(topic()));
            QSettings().setValue("practice/level", q(level()));
            newExercise();
        });
    connect(newButton_, &QPushButton::clicked, this, &PracticeController::newExercise);
    connect(&lessons_, &LessonController::lessonShown, this, &PracticeController::lessonShown);
    connect(&lessons_, &LessonController::lessonClosed, this, [this] {
        shownSeed_.reset();
        bar_->hide();
    });
    connect(&lessons_, &LessonController::answerRecorded, this,
            &PracticeController::answerRecorded);
}

void PracticeController::addLessonItems(QMenu* lessons) {
    practice_ = lessons->addAction(tr("Pr&actice..."), this, [this] { newExercise(); });
    practice_->setObjectName("practice");
    practice_->setStatusTip(
        tr("Fresh exercises on a topic, at a level, until you master it (three right in a row)"));
    // Also where the focus is in the answer box: the student's next instance without the mouse.
    auto* next = lessons->addAction(tr("New practice e&xercise"), this, [this] { newExercise(); });
    next->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
    next->setObjectName("newPracticeExercise");
}

void PracticeController::retranslate(Language lang) {
    const QSettings settings;
    const QString wantTopic =
        topics_->count() ? q(topic()) : settings.value("practice/topic").toString();
    const QString wantLevel =
        levels_->count() ? q(level()) : settings.value("practice/level").toString();
    topics_->clear();
    for (const PracticeTopic& t : practiceTopics())
        topics_->addItem(q(t.title.in(lang)), q(t.name));
    topics_->setCurrentIndex(std::max(0, topics_->findData(wantTopic)));
    levels_->clear();
    for (const PracticeLevel l : kLevels)
        levels_->addItem(q(practiceLevelLabel(l, lang)), q(practiceLevelName(l)));
    levels_->setCurrentIndex(std::max(0, levels_->findData(wantLevel)));
    refresh();
}

std::string PracticeController::topic() const {
    return topics_->currentData().toString().toStdString();
}

std::string PracticeController::level() const {
    return levels_->currentData().toString().toStdString();
}

void PracticeController::newExercise() {
    const auto parsedLevel = parsePracticeLevel(level());
    if (topic().empty() || !parsedLevel) return;
    PracticeRecord& record = lessons_.studentProgress().practice[practiceKey(topic(), level())];
    // An instance the student was never given at this topic and level (two seeds may draw the
    // same one): made here, a few milliseconds, then opened by its id as any lesson is.
    std::uint64_t seed = 0;
    std::string digest;
    try {
        const PracticeInstance inst =
            drawPractice(topic(), *parsedLevel, draw_, [&](std::uint64_t s, const std::string& d) {
                return record.drawn(s) || record.given(d);
            });
        seed = inst.seed;
        digest = practiceDigest(inst);
    } catch (const std::exception& e) {
        status_->setText(QString::fromUtf8(e.what()));
        return;
    }
    recordPractice(record, seed, PracticeRecord::Result::Open, digest);
    lessons_.save();
    bar_->show();
    emit lessonRequested(q(practiceLessonId(topic(), *parsedLevel, seed)));
}

void PracticeController::lessonShown(const Lesson& lesson) {
    const auto key = parsePracticeLessonId(lesson.id);
    if (!key) {
        shownSeed_.reset();
        bar_->hide();
        return;
    }
    // A practice lesson opened otherwise (a file, --lesson): the bar follows it.
    topics_->setCurrentIndex(std::max(0, topics_->findData(q(key->topic))));
    levels_->setCurrentIndex(std::max(0, levels_->findData(q(practiceLevelName(key->level)))));
    shownSeed_ = key->seed;
    bar_->show();
    refresh();
}

void PracticeController::answerRecorded(const Lesson& lesson) {
    const auto key = parsePracticeLessonId(lesson.id);
    if (!key) return;
    Progress& progress = lessons_.studentProgress();
    recordPractice(progress.practice[practiceKey(key->topic, practiceLevelName(key->level))],
                   key->seed, practiceResult(lesson, progress.lessons[lesson.id]));
    refresh();
}

void PracticeController::refresh() {
    const Progress& progress = lessons_.studentProgress();
    const auto it = progress.practice.find(practiceKey(topic(), level()));
    const PracticeRecord none;
    const PracticeRecord& rec = it != progress.practice.end() ? it->second : none;
    QString text = tr("Right in a row: %1 of %2").arg(rec.streak()).arg(kMasteryStreak);
    if (rec.mastered())
        text = tr("Mastered at this level (%1 right of %2). Try the next level.")
                   .arg(rec.right())
                   .arg(rec.instances.size());
    // What the shown instance came to: the student sees the streak move, or why it did not.
    if (shownSeed_ && it != progress.practice.end())
        for (const PracticeRecord::Instance& in : rec.instances)
            if (in.seed == *shownSeed_) {
                if (in.result == PracticeRecord::Result::Right)
                    text += QStringLiteral("\n") +
                            tr("This one is right at every first answer: press New exercise.");
                else if (in.result == PracticeRecord::Result::Missed)
                    text += QStringLiteral("\n") +
                            tr("A first answer here was wrong: the streak starts again. Finish "
                               "this one, then press New exercise.");
            }
    status_->setText(text);
    seedLabel_->setText(shownSeed_ ? tr("seed %1").arg(*shownSeed_) : QString());
    seedLabel_->setToolTip(tr("raystep-cli practice make %1 --seed %2 --level %3 gives it again")
                               .arg(q(topic()))
                               .arg(shownSeed_.value_or(0))
                               .arg(q(level())));
}

}  // namespace raystep::gui
