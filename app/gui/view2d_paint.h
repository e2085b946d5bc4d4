#pragma once
// What the 2D view's drawing files share (view2d*.cpp only): the picture's colours from the
// palette, pen widths as presenter mode scales them, the cost chart's proportions.
#include "presentation.h"

#include "course/palette.h"

#include <QColor>
#include <QFontMetricsF>

namespace raystep::gui::draw2d {

inline QColor colourOf(const PaletteColour& c, int alpha = 255) {
    return QColor(c.r, c.g, c.b, alpha);
}
// The roles' colours come from the one palette (course/palette.h), as the lessons name them.
inline QColor role(PaletteRole r, int alpha = 255) {
    return colourOf(roleColour(r), alpha);
}
/// The picture's colours as the palette (standard or high contrast) has them now.
struct Ink {
    QColor background, gridLine, primitive, label;
    QColor visited, current, tested, skipped, hit, ray;
    QColor student;  // a student's own walk over raystep's (File > Open student trace)
};
inline Ink ink() {
    const bool high = presentation().highContrast();
    Ink k;
    // High contrast: a white page, darker lines and labels (a projector washes greys out).
    k.background = high ? QColor(255, 255, 255) : QColor(250, 250, 247);
    k.gridLine = high ? QColor(140, 140, 140) : QColor(200, 200, 200);
    k.primitive = high ? QColor(15, 15, 20) : QColor(60, 60, 70);  // ink, not a role
    k.label = high ? QColor(20, 20, 20) : QColor(120, 120, 120);
    // Visited cells as a light tint of the palette's colour, so the grid and labels stay readable.
    k.visited = role(PaletteRole::Visited, high ? 170 : 120);
    k.current = role(PaletteRole::Current, 200);
    k.tested = role(PaletteRole::Tested);
    k.skipped = role(PaletteRole::Skipped);
    k.hit = role(PaletteRole::Hit);
    k.ray = colourOf(rayColour(RayKind::Primary));
    // The chosen plane's blue: a build's colour, never on screen with a ray's walk, and of a
    // hue none of the walk's roles has.
    k.student = role(PaletteRole::Chosen);
    return k;
}
/// A pen width (or a mark's radius) as drawn: wider in presenter mode.
inline double px(double width) {
    return width * presentation().lineScale();
}
// The cost chart: its strip under the picture and the room left of it for the cost values.
// Both grow with the label font (presenter mode, UI zoom): a plot about 116 px high between the
// title's row and two rows of values, and about four lines' height for a value like "0.1234".
constexpr double kChartPlot = 116;
inline double chartHeight(const QFontMetricsF& fm, double plot = kChartPlot) {
    return plot + (fm.height() + 14) + 2 * (fm.height() + 1) + 12;
}
inline double chartAxisRoom(const QFontMetricsF& fm) {
    return 4 * fm.height();
}
// The most of the view the chart's strip takes: the scene it explains keeps the rest.
constexpr double kChartShare = 0.42;
// Its X and Y curves in two of the palette's colours that no other part of the chart uses.
inline const PaletteColour& curveColour(int axis) {
    return rayColour(axis == 0 ? RayKind::Primary : RayKind::Diffuse);
}

}  // namespace raystep::gui::draw2d
