#pragma once
// The event list: every event of the replayed log up to where the replay may go (an open
// exercise stops it: quiz mode), one line each, with a filter; the current event is selected,
// and a click moves the replay there.
#include "session.h"

#include <QAbstractListModel>
#include <QSortFilterProxyModel>
#include <QWidget>

class QLineEdit;
class QListView;

namespace raystep::gui {

/// The log as a list: rows are made when shown, so a million events cost nothing up front. It
/// ends at Session::end(): no row for an event past an open exercise.
class EventListModel : public QAbstractListModel {
  public:
    enum Role { KindNameRole = Qt::UserRole + 1 };
    EventListModel(Session& s, QObject* parent);
    int rowCount(const QModelIndex& parent) const override;
    /// DisplayRole: the line shown; KindNameRole: the event's kind name (dda_cell, ...).
    QVariant data(const QModelIndex& index, int role) const override;

  private:
    Session& s_;
};

/// A filter text matches an event when it is part of its kind name (the trace file's:
/// dda_cell, primitive_test, ...) or of the line the list shows (docs/lesson-format.md).
class EventFilter : public QSortFilterProxyModel {
  public:
    EventFilter(Session& s, QObject* parent) : QSortFilterProxyModel(parent), s_(s) {}
    void setText(const QString& text);

  protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override;

  private:
    Session& s_;
    std::string text_;
};

class EventList : public QWidget {
    Q_OBJECT
  public:
    explicit EventList(Session& s, QWidget* parent = nullptr);
    /// Shows only the events the filter text matches (a lesson's step sets it).
    void setFilter(const QString& text);
    QString filter() const;
    /// The rows shown (tests read them) and the highlighted one (-1: none).
    int rowCount() const;
    QString rowText(int row) const;
    int currentRow() const;

  private:
    /// Highlights the event the cursor is after, or the last shown before it when the filter
    /// hides that one.
    void showCursor();

    Session& session_;
    EventListModel* model_ = nullptr;
    EventFilter* filter_ = nullptr;
    QLineEdit* filterEdit_ = nullptr;
    QListView* list_ = nullptr;
};

}  // namespace raystep::gui
