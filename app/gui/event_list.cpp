// The event list: the log's lines (event_text.h), filtered, following the replay's cursor.
#include "event_list.h"

#include "course/lesson_trace.h"
#include "language.h"

#include "raystep/trace/event_text.h"

#include <QLineEdit>
#include <QListView>
#include <QStyledItemDelegate>
#include <QVBoxLayout>

namespace raystep::gui {

namespace {
// Rows as wide as the list, not as their text: a long row is elided (its tooltip holds it
// whole) instead of pushing a horizontal scroll bar under a narrow dock.
class ElidedRows : public QStyledItemDelegate {
  public:
    using QStyledItemDelegate::QStyledItemDelegate;
    QSize sizeHint(const QStyleOptionViewItem& o, const QModelIndex& i) const override {
        return {1, QStyledItemDelegate::sizeHint(o, i).height()};
    }
};
}  // namespace

QString eventKindLabel(std::size_t kind) {
    // tr() with a literal each, so the catalogue test finds them.
    switch (kind) {
        case variantIndex<RayBegin>():
            return EventList::tr("ray begin");
        case variantIndex<DdaSetup>():
            return EventList::tr("DDA set-up");
        case variantIndex<DdaCell>():
            return EventList::tr("DDA step");
        case variantIndex<MailboxSkip>():
            return EventList::tr("mailbox skip");
        case variantIndex<PrimitiveTest>():
            return EventList::tr("primitive test");
        case variantIndex<NodeEnter>():
            return EventList::tr("node enter");
        case variantIndex<NodeSkip>():
            return EventList::tr("node skip");
        case variantIndex<BuildNode>():
            return EventList::tr("build node");
        case variantIndex<SplitCandidate>():
            return EventList::tr("split candidate");
        case variantIndex<SplitChosen>():
            return EventList::tr("split chosen");
        case variantIndex<LeafMade>():
            return EventList::tr("leaf made");
        case variantIndex<RayHit>():
            return EventList::tr("hit");
        case variantIndex<RayMiss>():
            return EventList::tr("miss");
        case variantIndex<RayBlocked>():
            return EventList::tr("blocked");
        case variantIndex<ShadingTerm>():
            return EventList::tr("shading term");
        default:
            return EventList::tr("pixel result");
    }
}

EventListModel::EventListModel(Session& s, QObject* parent) : QAbstractListModel(parent), s_(s) {
    const auto reset = [this] {
        beginResetModel();
        endResetModel();
    };
    connect(&s_, &Session::logChanged, this, reset);
    connect(&s_, &Session::shownChanged, this, reset);
}

int EventListModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(s_.shownEvents().size());
}

QVariant EventListModel::data(const QModelIndex& index, int role) const {
    const auto shown = s_.shownEvents();
    if (!index.isValid() || index.row() >= static_cast<int>(shown.size())) return {};
    const Event& e = shown[index.row()];
    if (role == KindNameRole) return QString::fromUtf8(kEventNames[e.index()].data());
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    return QStringLiteral("%1  %2")
        .arg(index.row() + 1)
        .arg(QString::fromStdString(eventText(s_.log(), index.row(), interfaceLanguage())));
}

void EventFilter::setText(const QString& text) {
    text_ = text.trimmed().toStdString();
    // The kinds whose name in the interface language holds the text: once, not once a row.
    const QString t = QString::fromStdString(text_);
    for (std::size_t k = 0; k < labelMatches_.size(); ++k)
        labelMatches_[k] = eventKindLabel(k).contains(t, Qt::CaseInsensitive);
    invalidateFilter();
}

bool EventFilter::filterAcceptsRow(int row, const QModelIndex& parent) const {
    const auto shown = s_.shownEvents();
    if (parent.isValid() || row >= static_cast<int>(shown.size())) return false;
    // The lessons' rule (course/lesson_trace.h), so a step's filter shows what validation saw;
    // and the line as this list shows it (in the app's language).
    const QString text = QString::fromStdString(text_);
    return eventMatchesFilter(shown[row], s_.log().dims(), text_) ||
           labelMatches_[shown[row].index()] ||
           sourceModel()
               ->index(row, 0)
               .data()
               .toString()
               .section(QStringLiteral("  "), 1)  // not the row's number
               .contains(text, Qt::CaseInsensitive);
}

EventList::EventList(Session& s, QWidget* parent) : QWidget(parent), session_(s) {
    auto* ll = new QVBoxLayout(this);
    ll->setContentsMargins(0, 0, 0, 0);
    filterEdit_ = new QLineEdit;
    filterEdit_->setObjectName("eventFilter");
    filterEdit_->setPlaceholderText(tr("Filter: a kind (DDA step, primitive test) or any text"));
    filterEdit_->setClearButtonEnabled(true);
    ll->addWidget(filterEdit_);
    model_ = new EventListModel(session_, this);
    filter_ = new EventFilter(session_, this);
    filter_->setSourceModel(model_);
    connect(filterEdit_, &QLineEdit::textChanged, this, [this](const QString& text) {
        // A step's kind, as the box names it, filters by the kind's trace name; edited, by text.
        if (text != kindShown_) kindKey_.clear(), kindShown_.clear();
        filter_->setText(filter());
        showCursor();  // the rows moved: the highlight follows the cursor, not the old row
    });
    list_ = new QListView;
    list_->setObjectName("eventList");
    list_->setModel(filter_);
    list_->setUniformItemSizes(true);
    // The row's number, kind and values read from the left: a long row is cut at its end.
    list_->setItemDelegate(new ElidedRows(list_));
    list_->setTextElideMode(Qt::ElideRight);
    list_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    ll->addWidget(list_);
    connect(list_, &QListView::clicked, this, [this](const QModelIndex& i) {
        session_.setCursor(static_cast<std::size_t>(filter_->mapToSource(i).row()) + 1);
    });
    connect(&session_, &Session::cursorChanged, this, [this] { showCursor(); });
    connect(&session_, &Session::shownChanged, this, [this] { showCursor(); });
}

void EventList::setFilter(const QString& text) {
    // A step's filter names kinds by their trace names ("primitive_test", "node"): the box
    // shows those kinds in the interface language.
    QStringList kinds;
    if (!text.trimmed().isEmpty())
        for (std::size_t k = 0; k < kEventNames.size(); ++k)
            if (QString::fromUtf8(kEventNames[k].data(), qsizetype(kEventNames[k].size()))
                    .contains(text.trimmed(), Qt::CaseInsensitive))
                kinds << eventKindLabel(k);
    kindKey_ = kinds.isEmpty() ? QString() : text;
    kindShown_ = kinds.join(QStringLiteral(", "));
    filterEdit_->setText(kindKey_.isEmpty() ? text : kindShown_);
    filter_->setText(filter());  // the box may have shown this name already
    showCursor();
}

QString EventList::filter() const {
    return kindKey_.isEmpty() ? filterEdit_->text() : kindKey_;
}

QString EventList::filterShown() const {
    return filterEdit_->text();
}

int EventList::rowCount() const {
    return filter_->rowCount();
}

QString EventList::rowText(int row) const {
    return filter_->index(row, 0).data().toString();
}

int EventList::currentRow() const {
    const QModelIndex i = list_->currentIndex();
    return i.isValid() && list_->selectionModel()->isSelected(i) ? i.row() : -1;
}

void EventList::showCursor() {
    // The last row shown at or before the cursor's event (the filter may hide that event).
    QModelIndex shown;
    const int cursor = static_cast<int>(std::min(session_.cursor(), session_.end()));
    if (cursor > 0) {
        const QModelIndex exact = filter_->mapFromSource(model_->index(cursor - 1));
        if (exact.isValid()) {
            shown = exact;
        } else {
            // Rows are in event order: the last one before the cursor, by bisection.
            int lo = 0, hi = filter_->rowCount();
            while (lo < hi) {
                const int mid = (lo + hi) / 2;
                if (filter_->mapToSource(filter_->index(mid, 0)).row() < cursor - 1)
                    lo = mid + 1;
                else
                    hi = mid;
            }
            if (lo > 0) shown = filter_->index(lo - 1, 0);
        }
    }
    if (shown.isValid()) {
        list_->setCurrentIndex(shown);
        list_->scrollTo(shown);
    } else {
        list_->clearSelection();
        list_->setCurrentIndex({});
    }
}

}  // namespace raystep::gui
