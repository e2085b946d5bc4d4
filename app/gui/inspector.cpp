// The inspector: describeState writes the replay state's variables a line each.
#include "inspector.h"

#include "language.h"

#include "raystep/trace/event_text.h"

#include <QStringList>

#include <algorithm>

namespace raystep::gui {

namespace {
QString num(double v) {
    return QString::fromStdString(raystep::numberText(v, interfaceLanguage()));
}
}  // namespace

QString describeState(const Session& s) {
    const ReplayState& st = s.state();
    QStringList lines;
    // Of the events the replay may show (an open exercise hides the rest: quiz mode); while a
    // question to the room hides what is ahead, the trace's length is not told either.
    lines << (s.hidesAhead() ? Inspector::tr("step %1").arg(st.cursor)
                             : Inspector::tr("step %1 of %2").arg(st.cursor).arg(s.end()));
    if (st.cursor > 0)
        lines << QString::fromStdString(eventText(s.log(), st.cursor - 1, interfaceLanguage()));
    if (st.ray != kNoId) lines << Inspector::tr("ray %1").arg(st.ray);
    if (st.ddaCell) {
        const DdaCell& c = *st.ddaCell;
        lines << QStringLiteral("X = %1   Y = %2%3")
                     .arg(c.cell[0])
                     .arg(c.cell[1])
                     .arg(s.is2D() ? QString() : QStringLiteral("   Z = %1").arg(c.cell[2]));
        lines << QStringLiteral("tMaxX = %1   tMaxY = %2%3")
                     .arg(num(c.tMax[0]), num(c.tMax[1]))
                     .arg(s.is2D() ? QString()
                                   : QStringLiteral("   tMaxZ = %1").arg(num(c.tMax[2])));
    }
    if (st.ddaSetup) {
        const DdaSetup& d = *st.ddaSetup;
        const bool threeD = d.dims == 3;
        lines << QStringLiteral("tDeltaX = %1   tDeltaY = %2%3")
                     .arg(num(d.tDelta[0]), num(d.tDelta[1]),
                          threeD ? QStringLiteral("   tDeltaZ = ") + num(d.tDelta[2]) : QString());
        lines << QStringLiteral("stepX = %1   stepY = %2%3")
                     .arg(d.step[0])
                     .arg(d.step[1])
                     .arg(threeD ? QStringLiteral("   stepZ = %1").arg(d.step[2]) : QString());
        lines << QStringLiteral("t_enter = %1   t_exit = %2").arg(num(d.tEnter), num(d.tGridExit));
    }
    if (st.node)
        lines << Inspector::tr("node %1, t in [%2, %3]")
                     .arg(st.node->node)
                     .arg(num(st.node->tNear), num(st.node->tFar));
    if (!st.mailboxSkips.empty()) {
        QStringList m;
        for (auto p : st.mailboxSkips) m << QString::number(p);
        lines << Inspector::tr("mailbox: skipped primitive %1 (already tested by this ray)")
                     .arg(m.join(", "));
    }
    if (st.ray != kNoId) lines << Inspector::tr("tests: %1").arg(st.tests.size());
    if (st.nearestT)
        lines << Inspector::tr("nearest hit so far: primitive %1 at t = %2")
                     .arg(st.nearestPrim)
                     .arg(num(*st.nearestT));
    // The ray's hit on a triangle: its barycentric u, v (lesson 12), as the event records them.
    if (st.hit && s.scene3D() && st.hit->prim < s.scene3D()->primitiveCount() &&
        !s.scene3D()->isSphere(st.hit->prim))
        lines << Inspector::tr("hit on triangle %1: t = %2   u = %3   v = %4")
                     .arg(st.hit->prim)
                     .arg(num(st.hit->t), num(st.hit->u), num(st.hit->v));
    if (st.buildNode) {
        lines << Inspector::tr("building node %1 (%2 primitives, depth %3), %4 candidates")
                     .arg(st.buildNode->node)
                     .arg(st.buildNode->prims)
                     .arg(st.buildNode->depth)
                     .arg(st.candidates.size());
        if (!st.candidates.empty()) {
            const SplitCandidate& c = st.candidates.back();
            lines << Inspector::tr("candidate %1 = %2")
                         .arg(QChar("XYZ"[c.axis]))
                         .arg(num(c.position));
            lines << QStringLiteral("  NL = %1   NR = %2").arg(c.nl).arg(c.nr);
            lines << QStringLiteral("  P(L|C) = %1   P(R|C) = %2").arg(num(c.pl), num(c.pr));
            lines << Inspector::tr("  sahCost = %1").arg(num(c.sahCost));
            const auto best =
                std::min_element(st.candidates.begin(), st.candidates.end(),
                                 [](const SplitCandidate& a, const SplitCandidate& b) {
                                     return a.sahCost < b.sahCost;
                                 });
            lines << Inspector::tr("cheapest so far: %1 = %2, cost %3")
                         .arg(QChar("XYZ"[best->axis]))
                         .arg(num(best->position), num(best->sahCost));
        }
        if (st.chosen)
            lines << Inspector::tr("chosen: %1 = %2 (cost %3 < leaf %4)")
                         .arg(QChar("XYZ"[st.chosen->axis]))
                         .arg(num(st.chosen->position), num(st.chosen->sahCost),
                              num(st.chosen->leafCost));
    }
    return lines.join('\n');
}

Inspector::Inspector(Session& s, QWidget* parent) : QTextBrowser(parent), session_(s) {
    setObjectName("inspector");
    connect(&session_, &Session::cursorChanged, this,
            [this] { setPlainText(describeState(session_)); });
    connect(&session_, &Session::shownChanged, this,
            [this] { setPlainText(describeState(session_)); });
    connect(&session_, &Session::limitChanged, this,
            [this] { setPlainText(describeState(session_)); });
}

}  // namespace raystep::gui
