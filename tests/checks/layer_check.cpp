#include "layer_check.h"

#include <algorithm>
#include <optional>

namespace raystep::checks {

namespace {

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

/// The floor's rank (0 = base), for "raystep/<floor>/..." or "algorithms/raystep/<floor>/...".
std::optional<std::size_t> floorOf(std::string_view path) {
    if (startsWith(path, "algorithms/")) path.remove_prefix(std::string_view("algorithms/").size());
    if (!startsWith(path, "raystep/")) return std::nullopt;
    path.remove_prefix(std::string_view("raystep/").size());
    const std::string_view floor = path.substr(0, path.find('/'));
    for (std::size_t i = 0; i < std::size(kFloors); ++i)
        if (kFloors[i] == floor) return i;
    return std::nullopt;
}

bool isGuiHeader(std::string_view h) {
    // Qt's and VTK's headers: <QWidget>, <QtCore/...>, <vtkActor.h>, <QVTK...>.
    return (h.size() > 1 && h[0] == 'Q' && h[1] >= 'A' && h[1] <= 'Z') || startsWith(h, "Qt") ||
           startsWith(h, "vtk") || startsWith(h, "QVTK");
}

}  // namespace

std::vector<std::pair<std::size_t, std::string>> includesOf(std::string_view source) {
    std::vector<std::pair<std::size_t, std::string>> out;
    std::size_t line = 1;
    for (std::size_t at = 0; at <= source.size();) {
        const std::size_t end = std::min(source.find('\n', at), source.size());
        std::string_view l = source.substr(at, end - at);
        const auto skipBlanks = [&] {
            while (!l.empty() && (l.front() == ' ' || l.front() == '\t')) l.remove_prefix(1);
        };
        skipBlanks();
        if (!l.empty() && l.front() == '#') {
            l.remove_prefix(1);
            skipBlanks();
            if (startsWith(l, "include")) {
                l.remove_prefix(std::string_view("include").size());
                skipBlanks();
                if (!l.empty() && (l.front() == '"' || l.front() == '<')) {
                    const char close = l.front() == '"' ? '"' : '>';
                    const std::size_t stop = l.find(close, 1);
                    if (stop != std::string_view::npos)
                        out.emplace_back(line, std::string(l.substr(1, stop - 1)));
                }
            }
        }
        ++line;
        at = end + 1;
    }
    return out;
}

std::vector<LayerViolation> findLayerViolations(std::string_view path, std::string_view source) {
    std::vector<LayerViolation> out;
    const std::optional<std::size_t> own = floorOf(path);
    const bool core = startsWith(path, "algorithms/");
    const bool course = startsWith(path, "app/course/");
    const bool client = startsWith(path, "app/");
    for (const auto& [line, header] : includesOf(source)) {
        if (own) {
            if (const auto floor = floorOf(header); floor && *floor > *own)
                out.push_back({line, header,
                               std::string(kFloors[*own]) + "/ includes a floor above it (" +
                                   std::string(kFloors[*floor]) + "/)"});
        }
        if ((core || course) && isGuiHeader(header))
            out.push_back(
                {line, header,
                 std::string(core ? "the core" : "the course engine") + " includes Qt or VTK"});
        if (core && startsWith(header, "course/"))
            out.push_back({line, header, "the core includes the course engine"});
        if (client && std::find(std::begin(kInternalHeaders), std::end(kInternalHeaders), header) !=
                          std::end(kInternalHeaders))
            out.push_back({line, header, "a client includes a structure's internal header"});
    }
    return out;
}

}  // namespace raystep::checks
