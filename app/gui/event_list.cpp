// The event list: the log's lines (event_text.h), filtered, following the replay's cursor.
#include "event_list.h"

#include "language.h"

#include "raystep/trace/event_text.h"

#include <QLineEdit>
#include <QListView>
#include <QSortFilterProxyModel>
#include <QVBoxLayout>

namespace raystep::gui {

EventListModel::EventListModel(Session& s, QObject* parent) : QAbstractListModel(parent), s_(s) {
    connect(&s_, &Session::logChanged, this, [this] {
        beginResetModel();
        endResetModel();
    });
}

int EventListModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(s_.size());
}

QVariant EventListModel::data(const QModelIndex& index, int role) const {
    if (role != Qt::DisplayRole || !index.isValid()) return {};
    return QStringLiteral("%1  %2")
        .arg(index.row() + 1)
        .arg(QString::fromStdString(eventText(s_.log(), index.row(), interfaceLanguage())));
}

EventList::EventList(Session& s, QWidget* parent) : QWidget(parent), session_(s) {
    auto* ll = new QVBoxLayout(this);
    ll->setContentsMargins(0, 0, 0, 0);
    filterEdit_ = new QLineEdit;
    filterEdit_->setPlaceholderText(tr("Filter events (e.g. cell, test, mailbox)"));
    ll->addWidget(filterEdit_);
    model_ = new EventListModel(session_, this);
    filter_ = new QSortFilterProxyModel(this);
    filter_->setSourceModel(model_);
    filter_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    connect(filterEdit_, &QLineEdit::textChanged, filter_,
            &QSortFilterProxyModel::setFilterFixedString);
    list_ = new QListView;
    list_->setModel(filter_);
    list_->setUniformItemSizes(true);
    ll->addWidget(list_);
    connect(list_, &QListView::clicked, this, [this](const QModelIndex& i) {
        session_.setCursor(static_cast<std::size_t>(filter_->mapToSource(i).row()) + 1);
    });
    connect(&session_, &Session::cursorChanged, this, [this] { showCursor(); });
}

void EventList::setFilter(const QString& text) {
    filterEdit_->setText(text);
}

void EventList::showCursor() {
    if (session_.cursor() == 0) return;
    const QModelIndex i =
        filter_->mapFromSource(model_->index(static_cast<int>(session_.cursor()) - 1));
    if (i.isValid()) {
        list_->setCurrentIndex(i);
        list_->scrollTo(i);
    }
}

}  // namespace raystep::gui
