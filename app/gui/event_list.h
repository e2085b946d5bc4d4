#pragma once
// The event list: every event of the replayed log, one line each, with a filter; the current
// event is selected, and a click moves the replay there.
#include "session.h"

#include <QAbstractListModel>
#include <QWidget>

class QLineEdit;
class QListView;
class QSortFilterProxyModel;

namespace raystep::gui {

/// The log as a list: rows are made when shown, so a million events cost nothing up front.
class EventListModel : public QAbstractListModel {
  public:
    EventListModel(Session& s, QObject* parent);
    int rowCount(const QModelIndex& parent) const override;
    QVariant data(const QModelIndex& index, int role) const override;

  private:
    Session& s_;
};

class EventList : public QWidget {
    Q_OBJECT
  public:
    explicit EventList(Session& s, QWidget* parent = nullptr);
    /// Shows only the events whose line contains `text` (a lesson's step sets it).
    void setFilter(const QString& text);

  private:
    void showCursor();

    Session& session_;
    EventListModel* model_ = nullptr;
    QSortFilterProxyModel* filter_ = nullptr;
    QLineEdit* filterEdit_ = nullptr;
    QListView* list_ = nullptr;
};

}  // namespace raystep::gui
