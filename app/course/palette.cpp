// The palette's entries: Okabe-Ito (Okabe & Ito 2008, "Color Universal Design") and a grey.
#include "course/palette.h"

#include <atomic>

namespace raystep {

namespace {
constexpr int kPaletteSize = kRayKindCount + kPaletteRoleCount + kStructureRoleCount;
constexpr std::array<PaletteColour, kPaletteSize> kPalette{{
    // Rays, on the 3D view's dark background: all bright enough to read there.
    {"primary", 213, 94, 0, trNoop("orange-red")},  // Okabe-Ito vermilion
    {"shadow", 240, 228, 66, trNoop("yellow")},
    {"reflection", 86, 180, 233, trNoop("sky blue")},
    {"refraction", 204, 121, 167, trNoop("pink")},  // reddish purple
    {"diffuse", 0, 158, 115, trNoop("green")},      // bluish green
    // The 2D view's roles, on its white background (its ray is drawn in the primary colour).
    {"visited", 240, 228, 66, trNoop("yellow")},
    {"current", 230, 159, 0, trNoop("orange")},
    {"tested", 204, 121, 167, trNoop("pink")},
    {"skipped", 153, 153, 153, trNoop("grey")},
    {"hit", 0, 158, 115, trNoop("green")},
    {"candidate", 86, 180, 233, trNoop("sky blue")},
    {"chosen", 0, 114, 178, trNoop("blue")},
    // The 3D view's structures, on its dark background: none near a ray's hue (orange was read
    // as the primary ray's orange-red, blue as the reflection's sky blue on a projector). What
    // the ray passes through in greys; the current voxel or node in violet, the one hue the
    // rays leave free.
    {"grid-box", 200, 200, 200, trNoop("light grey")},
    {"voxel", 150, 150, 165, trNoop("grey")},
    {"current-voxel", 170, 120, 255, trNoop("violet")},
    {"kd-node", 170, 120, 255, trNoop("violet")},
    {"split-plane", 150, 150, 165, trNoop("grey")},
    {"bvh-box", 150, 150, 165, trNoop("grey")},
    {"tested-primitive", 255, 255, 255, trNoop("white")},
    {"hit-point", 255, 255, 255, trNoop("white")},
}};
// High contrast: the same keys and names, each shade moved away from its background (WCAG
// contrast ratio up on the 2D view's white for the roles and the primary ray, on black for the
// rays and structures), hue kept so the name stays true.
constexpr std::array<PaletteColour, kPaletteSize> kHighContrast{{
    {"primary", 220, 65, 0, trNoop("orange-red")},
    {"shadow", 255, 240, 40, trNoop("yellow")},
    {"reflection", 90, 210, 255, trNoop("sky blue")},
    {"refraction", 255, 140, 210, trNoop("pink")},
    {"diffuse", 0, 155, 85, trNoop("green")},
    {"visited", 255, 210, 0, trNoop("yellow")},
    {"current", 240, 125, 0, trNoop("orange")},
    {"tested", 215, 40, 140, trNoop("pink")},
    {"skipped", 105, 105, 105, trNoop("grey")},
    {"hit", 0, 140, 60, trNoop("green")},
    {"candidate", 0, 155, 240, trNoop("sky blue")},
    {"chosen", 0, 85, 200, trNoop("blue")},
    {"grid-box", 235, 235, 235, trNoop("light grey")},
    {"voxel", 175, 175, 190, trNoop("grey")},
    {"current-voxel", 195, 150, 255, trNoop("violet")},
    {"kd-node", 195, 150, 255, trNoop("violet")},
    {"split-plane", 175, 175, 190, trNoop("grey")},
    {"bvh-box", 175, 175, 190, trNoop("grey")},
    {"tested-primitive", 255, 255, 255, trNoop("white")},
    {"hit-point", 255, 255, 255, trNoop("white")},
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

std::string_view PaletteColour::name(Language lang) const {
    // A view into the catalogue, which lives as long as the program: the views keep it.
    const auto& table = catalogue(lang);
    const auto it = table.find(en);
    return it == table.end() ? en : std::string_view(it->second);
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
