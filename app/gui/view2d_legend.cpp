// The 2D view's caption (the scene and its structure) and its legend: each colour role the
// picture uses, named with its colour as the lessons write it.
#include "view2d.h"

#include "view2d_paint.h"

#include "language.h"
#include "presentation.h"

#include <QPainter>

namespace raystep::gui {

using namespace draw2d;

/// The legend's row for the ray: "the ray (orange-red)".
static QString rayLegendLabel(Language lang) {
    const std::string_view colour = rayColour(RayKind::Primary).name(lang);
    return QStringLiteral("%1 (%2)").arg(View2D::tr("the ray"),
                                         QString::fromUtf8(colour.data(), colour.size()));
}

static QString roleName(PaletteRole r) {
    switch (r) {
        case PaletteRole::Visited:
            return View2D::tr("visited");
        case PaletteRole::Current:
            return View2D::tr("current cell or node");
        case PaletteRole::Tested:
            return View2D::tr("tested primitive");
        case PaletteRole::Skipped:
            return View2D::tr("skipped");
        case PaletteRole::Hit:
            return View2D::tr("nearest hit");
        case PaletteRole::Candidate:
            return View2D::tr("candidate plane");
        case PaletteRole::Chosen:
            return View2D::tr("chosen plane");
    }
    return {};
}

/// A role as the legend shows it, with its colour's name as the lessons write it.
static QString roleLabel(PaletteRole r, Language lang) {
    const std::string_view colour = roleColour(r).name(lang);
    return QStringLiteral("%1 (%2)").arg(roleName(r),
                                         QString::fromUtf8(colour.data(), colour.size()));
}

QString View2D::captionText() const {
    return QString::fromStdString(session_.name()) + QStringLiteral("  -  ") +
           structureName(session_.kind());
}

std::vector<std::pair<QColor, QString>> View2D::legendRows(bool build) const {
    // The colour roles this picture uses, from the palette (the lessons name the same colours).
    if (build)
        return {{role(PaletteRole::Current), roleLabel(PaletteRole::Current, lang_)},
                {role(PaletteRole::Candidate), roleLabel(PaletteRole::Candidate, lang_)},
                {role(PaletteRole::Chosen), roleLabel(PaletteRole::Chosen, lang_)}};
    std::vector<std::pair<QColor, QString>> rows{{ink().ray, rayLegendLabel(lang_)}};
    if (showsStudentWalk()) {
        // A student's walk over raystep's: whose cells are whose, each in its colour.
        const auto named = [&](const QString& who, PaletteRole r) {
            const std::string_view colour = roleColour(r).name(lang_);
            return QStringLiteral("%1 (%2)").arg(who,
                                                 QString::fromUtf8(colour.data(), colour.size()));
        };
        rows.emplace_back(ink().visited, named(tr("raystep"), PaletteRole::Visited));
        rows.emplace_back(ink().student, named(tr("your walk"), PaletteRole::Chosen));
    } else {
        rows.emplace_back(ink().visited, roleLabel(PaletteRole::Visited, lang_));
    }
    rows.emplace_back(ink().current, roleLabel(PaletteRole::Current, lang_));
    for (PaletteRole r : {PaletteRole::Tested, PaletteRole::Skipped, PaletteRole::Hit})
        rows.emplace_back(role(r), roleLabel(r, lang_));
    return rows;
}

void View2D::drawLegend(QPainter& g, bool build) const {
    // Where fit() laid it out: a column on the right or rows under the caption.
    const auto rows = legendRows(build);
    if (rows.size() != legend_.entries.size()) return;
    g.save();
    g.setFont(presentation().captionFont());
    const QFontMetricsF fm(g.font());
    const double swatch = fm.height() - 2;
    g.setPen(QColor(200, 200, 200));
    g.setBrush(QColor(255, 255, 255, 225));
    g.drawRoundedRect(legend_.box, 4, 4);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const QRectF& e = legend_.entries[k];
        g.setPen(Qt::NoPen);
        g.setBrush(rows[k].first);
        g.drawRect(QRectF(e.left(), e.center().y() - swatch / 2, swatch, swatch));
        g.setPen(presentation().highContrast() ? QColor(0, 0, 0) : QColor(40, 40, 40));
        g.drawText(QRectF(e.left() + swatch + 6, e.top(), e.width() - swatch - 6, e.height()),
                   Qt::AlignLeft | Qt::AlignVCenter, rows[k].second);
    }
    g.restore();
}

}  // namespace raystep::gui
