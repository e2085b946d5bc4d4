#pragma once
// The event list: every event of the replayed log up to where the replay may go (an open
// exercise stops it: quiz mode), one line each, with a filter; the current event is selected,
// and a click moves the replay there.
#include "session.h"

#include <QAbstractListModel>
#include <QSortFilterProxyModel>
#include <QWidget>

#include <array>
#include <variant>

class QLineEdit;
class QListView;

namespace raystep::gui {

/// An event kind's name in the interface language (variant index; "primitive test", "test di
/// intersezione"): what the event list's filter shows for a kind and what the timeline jumps to.
QString eventKindLabel(std::size_t kind);

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
/// dda_cell, primitive_test, ...; or in the interface language: eventKindLabel) or of the line
/// the list shows (docs/lesson-format.md).
class EventFilter : public QSortFilterProxyModel {
  public:
    EventFilter(Session& s, QObject* parent) : QSortFilterProxyModel(parent), s_(s) {}
    void setText(const QString& text);

  protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override;

  private:
    Session& s_;
    std::string text_;
    std::array<bool, std::variant_size_v<Event>> labelMatches_{};  // by kind, for text_
};

class EventList : public QWidget {
    Q_OBJECT
  public:
    explicit EventList(Session& s, QWidget* parent = nullptr);
    /// Shows only the events the filter text matches (a lesson's step sets it). A filter of
    /// trace names (primitive_test; node: node_enter, node_skip, build_node) is shown as those
    /// kinds' names in the interface language and still filters as the trace name does (the
    /// lesson's validation counted those rows).
    void setFilter(const QString& text);
    /// The filter in force: a step's kind as its trace name, else the text typed.
    QString filter() const;
    /// What the filter box shows.
    QString filterShown() const;
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
    QString kindKey_, kindShown_;  // a step's kind filter and the name the box shows for it
};

}  // namespace raystep::gui
