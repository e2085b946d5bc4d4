#pragma once
// The one palette of raystep's ray and structure colours (docs/lesson-format.md, "Colours"): the
// 3D view draws each ray kind in its colour, the 2D view its roles (visited cell, current cell,
// tested primitive, ...), the legend lists them, and a lesson's `{colour:NAME}` is replaced by the
// colour's name when the lesson is loaded, so text and screen cannot disagree. Qt-free.
//
// The colours are Okabe and Ito's set for colour-blind viewers (and a grey): within the rays and
// within the 2D roles no two share a hue, and each pair differs in lightness too, which a
// projector keeps when it washes out saturation.
#include "raystep/base/i18n.h"
#include "raystep/base/ray.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace raystep {

struct PaletteColour {
    std::string_view key;  // as a lesson names it: {colour:KEY}
    std::uint8_t r, g, b;
    std::string_view
        en;  // the colour's name, as a lesson's text reads it (i18n/<code>/palette.json)
    /// The name in `lang`, from its catalogue (English where it has none).
    std::string_view name(Language lang) const;
};

/// What the 2D view draws, besides the rays.
enum class PaletteRole { Visited, Current, Tested, Skipped, Hit, Candidate, Chosen };
constexpr int kPaletteRoleCount = 7;

/// What the 3D view draws of a structure, besides the rays: each differs from every ray colour.
/// Roles never shown together may share a colour (the current voxel and the current kd node).
enum class StructureRole {
    GridBox,
    Voxel,
    CurrentVoxel,
    KdNode,
    SplitPlane,
    BvhBox,
    TestedPrimitive,
    HitPoint
};
constexpr int kStructureRoleCount = 8;

/// Which table the views draw with. The high-contrast one is for a projector that washes colours
/// out: each entry keeps its key and its name (a lesson's "{colour:primary}" still says what is
/// drawn), only its shade changes, to one further from the background it is drawn on (the 2D
/// view's white, the 3D view's black in high contrast).
enum class PaletteVariant { Standard, HighContrast };
/// The table rayColour, roleColour, structureColour and paletteColour read (Standard at start).
void setPaletteVariant(PaletteVariant v);
PaletteVariant paletteVariant();

/// The colour of a ray of kind `k` (3D view, legend).
const PaletteColour& rayColour(RayKind k);
/// The colour of a role of the 2D view.
const PaletteColour& roleColour(PaletteRole role);
/// The colour of a structure's role in the 3D view.
const PaletteColour& structureColour(StructureRole role);
/// Every entry: the ray kinds in RayKind's order, the roles in PaletteRole's order, then the
/// structure roles in StructureRole's order.
std::span<const PaletteColour> paletteColours();
/// The same entries of a given variant, in the same order.
std::span<const PaletteColour> paletteColours(PaletteVariant v);
/// The entry a lesson names by `key` ("primary", "visited", ...), or nullopt.
std::optional<PaletteColour> paletteColour(std::string_view key);

/// `text` with every {colour:KEY} replaced by the colour's name in `lang`. When a KEY is not in
/// the palette, returns nullopt with `unknown` set to it.
std::optional<std::string> expandColourNames(std::string_view text, Language lang,
                                             std::string* unknown);

}  // namespace raystep
