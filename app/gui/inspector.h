#pragma once
// The inspector: the current event and the algorithm's variables at the replay's cursor, named
// as on the board (X, Y, tMax, tDelta; the node and its interval; the SAH's NL, NR, P(L|C)).
#include "session.h"

#include <QTextBrowser>

namespace raystep::gui {

/// The inspector's text for the session's cursor.
QString describeState(const Session& s);

class Inspector : public QTextBrowser {
    Q_OBJECT
  public:
    explicit Inspector(Session& s, QWidget* parent = nullptr);

  private:
    Session& session_;
};

}  // namespace raystep::gui
