// The palette's entries: Okabe-Ito (Okabe & Ito 2008, "Color Universal Design") and a grey.
#include "course/palette.h"

#include <atomic>

namespace raystep {

namespace {
constexpr int kPaletteSize = kRayKindCount + kPaletteRoleCount + kStructureRoleCount;
constexpr std::array<PaletteColour, kPaletteSize> kPalette{{
    // Rays, on the 3D view's dark background: all bright enough to read there.
    {"primary", 213, 94, 0, "orange-red", "rosso arancio"},  // Okabe-Ito vermilion
    {"shadow", 240, 228, 66, "yellow", "giallo"},
    {"reflection", 86, 180, 233, "sky blue", "azzurro"},
    {"refraction", 204, 121, 167, "pink", "rosa"},  // reddish purple
    {"diffuse", 0, 158, 115, "green", "verde"},     // bluish green
    // The 2D view's roles, on its white background (its ray is drawn in the primary colour).
    {"visited", 240, 228, 66, "yellow", "giallo"},
    {"current", 230, 159, 0, "orange", "arancione"},
    {"tested", 204, 121, 167, "pink", "rosa"},
    {"skipped", 153, 153, 153, "grey", "grigio"},
    {"hit", 0, 158, 115, "green", "verde"},
    {"candidate", 86, 180, 233, "sky blue", "azzurro"},
    {"chosen", 0, 114, 178, "blue", "blu"},
    // The 3D view's structures, on its dark background: none near a ray's hue (orange was read
    // as the primary ray's orange-red, blue as the reflection's sky blue on a projector). What
    // the ray passes through in greys; the current voxel or node in violet, the one hue the
    // rays leave free.
    {"grid-box", 200, 200, 200, "light grey", "grigio chiaro"},
    {"voxel", 150, 150, 165, "grey", "grigio"},
    {"current-voxel", 170, 120, 255, "violet", "viola"},
    {"kd-node", 170, 120, 255, "violet", "viola"},
    {"split-plane", 150, 150, 165, "grey", "grigio"},
    {"bvh-box", 150, 150, 165, "grey", "grigio"},
    {"tested-primitive", 255, 255, 255, "white", "bianco"},
    {"hit-point", 255, 255, 255, "white", "bianco"},
}};
// High contrast: the same keys and names, each shade moved away from its background (WCAG
// contrast ratio up on the 2D view's white for the roles and the primary ray, on black for the
// rays and structures), hue kept so the name stays true.
constexpr std::array<PaletteColour, kPaletteSize> kHighContrast{{
    {"primary", 220, 65, 0, "orange-red", "rosso arancio"},
    {"shadow", 255, 240, 40, "yellow", "giallo"},
    {"reflection", 90, 210, 255, "sky blue", "azzurro"},
    {"refraction", 255, 140, 210, "pink", "rosa"},
    {"diffuse", 0, 155, 85, "green", "verde"},
    {"visited", 255, 210, 0, "yellow", "giallo"},
    {"current", 240, 125, 0, "orange", "arancione"},
    {"tested", 215, 40, 140, "pink", "rosa"},
    {"skipped", 105, 105, 105, "grey", "grigio"},
    {"hit", 0, 140, 60, "green", "verde"},
    {"candidate", 0, 155, 240, "sky blue", "azzurro"},
    {"chosen", 0, 85, 200, "blue", "blu"},
    {"grid-box", 235, 235, 235, "light grey", "grigio chiaro"},
    {"voxel", 175, 175, 190, "grey", "grigio"},
    {"current-voxel", 195, 150, 255, "violet", "viola"},
    {"kd-node", 195, 150, 255, "violet", "viola"},
    {"split-plane", 175, 175, 190, "grey", "grigio"},
    {"bvh-box", 175, 175, 190, "grey", "grigio"},
    {"tested-primitive", 255, 255, 255, "white", "bianco"},
    {"hit-point", 255, 255, 255, "white", "bianco"},
}};
static_assert(kRayKindCount == 5 && kPaletteRoleCount == 7 && kStructureRoleCount == 8);

// Read by the GUI thread's views and by lesson loading on workers: atomic.
std::atomic<PaletteVariant> gVariant{PaletteVariant::Standard};

const std::array<PaletteColour, kPaletteSize>& table() {
    return gVariant.load(std::memory_order_relaxed) == PaletteVariant::HighContrast ? kHighContrast
                                                                                    : kPalette;
}
}  // namespace

void setPaletteVariant(PaletteVariant v) {
    gVariant.store(v, std::memory_order_relaxed);
}

PaletteVariant paletteVariant() {
    return gVariant.load(std::memory_order_relaxed);
}

const PaletteColour& rayColour(RayKind k) {
    return table()[static_cast<std::size_t>(k)];
}

const PaletteColour& roleColour(PaletteRole role) {
    return table()[kRayKindCount + static_cast<std::size_t>(role)];
}

const PaletteColour& structureColour(StructureRole role) {
    return table()[kRayKindCount + kPaletteRoleCount + static_cast<std::size_t>(role)];
}

std::span<const PaletteColour> paletteColours() {
    return table();
}

std::span<const PaletteColour> paletteColours(PaletteVariant v) {
    if (v == PaletteVariant::HighContrast) return kHighContrast;
    return kPalette;
}

std::optional<PaletteColour> paletteColour(std::string_view key) {
    for (const PaletteColour& c : table())
        if (c.key == key) return c;
    return std::nullopt;
}

std::optional<std::string> expandColourNames(std::string_view text, Language lang,
                                             std::string* unknown) {
    constexpr std::string_view kOpen = "{colour:";
    std::string out;
    std::size_t from = 0;
    for (;;) {
        const std::size_t at = text.find(kOpen, from);
        if (at == std::string_view::npos) break;
        const std::size_t close = text.find('}', at + kOpen.size());
        if (close == std::string_view::npos) {
            if (unknown) *unknown = std::string(text.substr(at));
            return std::nullopt;
        }
        const std::string_view key = text.substr(at + kOpen.size(), close - at - kOpen.size());
        const auto c = paletteColour(key);
        if (!c) {
            if (unknown) *unknown = std::string(key);
            return std::nullopt;
        }
        out.append(text.substr(from, at - from));
        out.append(c->name(lang));
        from = close + 1;
    }
    out.append(text.substr(from));
    return out;
}

}  // namespace raystep
