// `raystep-cli dda`: the 3D-DDA walk of one ray, as a table or as JSON.
#include "dda_command.h"

#include "common.h"

#include "raystep/accel/dda.h"
#include "raystep/base/format.h"
#include "raystep/geometry/kernels.h"
#include "raystep/trace/board.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace raystep::cli {

void addDdaCommand(CLI::App& app, DdaArgs& a) {
    CLI::App* cmd =
        app.add_subcommand("dda", "Walk a ray through a regular grid, cell by cell (3D-DDA)");
    cmd->add_option("--grid", a.grid, "Cells per axis: NX,NY or NX,NY,NZ")->required();
    cmd->add_option("--min", a.min, "Grid corner with the smallest coordinates")->required();
    cmd->add_option("--max", a.max, "Grid corner with the largest coordinates")->required();
    cmd->add_option("--origin", a.origin, "Ray origin")->required();
    cmd->add_option("--dir", a.dir, "Ray direction")->required();
    cmd->add_option("--precision", a.precision, "float or double")->capture_default_str();
    auto* json = cmd->add_flag("--json", a.json, "Print the steps as JSON");
    cmd->add_option("--format", a.format,
                    "Print the steps as the GUI's board: csv, markdown or latex")
        ->excludes(json);
}

namespace {

constexpr const char* kAxisNames = "XYZ";

template <int N, typename T>
int walk(const DdaArgs& a, const std::vector<double>& res, const std::vector<double>& lo,
         const std::vector<double>& hi, const std::vector<double>& o,
         const std::vector<double>& d) {
    GridSpec<N, T> grid;
    VecN<N, T> origin, dir;
    for (int i = 0; i < N; ++i) {
        grid.res[i] = static_cast<int>(res[i]);
        grid.lo[i] = T(lo[i]);
        grid.hi[i] = T(hi[i]);
        origin[i] = T(o[i]);
        dir[i] = T(d[i]);
    }
    Dda<N, T> dda(grid, origin, dir);
    // In float, --max may round onto --min: the walk refuses the grid, which is not a miss.
    if (dda.problem())
        return fail(std::string("--precision ") + (sizeof(T) == 4 ? "float" : "double") + ": " +
                    dda.problem());
    const auto axes = [](unsigned mask) {
        std::vector<int> v;
        for (int i = 0; i < N; ++i)
            if (mask & (1u << i)) v.push_back(i);
        return v;
    };
    if (a.json) {
        // Streamed a step at a time (a long walk would not fit in memory as one JSON value), in
        // the layout dump(2) gives {"steps": [...]}.
        std::printf("{\n  \"steps\": [");
        bool first = true;
        for (bool more = dda.valid(); more && !std::ferror(stdout); more = dda.next()) {
            nlohmann::ordered_json s;
            s["cell"] = std::vector<int>(&dda.cell()[0], &dda.cell()[0] + N);
            const std::vector<int> taken = axes(dda.axesTaken());
            s["axis"] =
                taken.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(taken[0]);
            if (taken.size() > 1) s["axes"] = taken;  // an exact tie: a diagonal step
            nlohmann::ordered_json tMax = nlohmann::ordered_json::array(), tDelta = tMax;
            for (int i = 0; i < N; ++i) {
                const T m = dda.tMax()[i], dl = dda.tDelta()[i];
                tMax.push_back(std::isfinite(m) ? nlohmann::ordered_json(double(m))
                                                : nlohmann::ordered_json(nullptr));
                tDelta.push_back(std::isfinite(dl) ? nlohmann::ordered_json(double(dl))
                                                   : nlohmann::ordered_json(nullptr));
            }
            s["tMax"] = tMax;
            s["tDelta"] = tDelta;
            s["t_enter"] = double(dda.tEnter());
            s["t_exit"] = double(dda.tCellExit());
            std::string text = s.dump(2);
            for (std::size_t at = text.find('\n'); at != std::string::npos;
                 at = text.find('\n', at + 1))
                text.insert(at + 1, "    ");
            std::printf("%s\n    %s", first ? "" : ",", text.c_str());
            first = false;
        }
        std::printf(first ? "]\n}\n" : "\n  ]\n}\n");
        return 0;
    }
    if (!a.format.empty()) {
        // The board's rows, streamed (a walk of millions of cells is never held); the format
        // was checked by runDda.
        const BoardFormat format = *parseBoardFormat(a.format);
        BoardOptions options;
        options.primitives = false;  // a walk without a scene tests nothing
        std::fputs(formatBoardStart(ddaHeader(N, options), format).c_str(), stdout);
        std::array<double, 3> tDelta{0.0, 0.0, 0.0};
        for (int i = 0; i < N; ++i) tDelta[i] = double(dda.tDelta()[i]);
        std::size_t step = 0;
        for (bool more = dda.valid(); more && !std::ferror(stdout); more = dda.next()) {
            DdaCell c{0, static_cast<std::uint8_t>(dda.axesTaken()), {0, 0, 0}, {0.0, 0.0, 0.0}};
            for (int i = 0; i < N; ++i) {
                c.cell[i] = dda.cell()[i];
                c.tMax[i] = double(dda.tMax()[i]);
            }
            std::fputs(
                formatBoardLine(ddaCells(step++, c, tDelta, N, Language::En), format).c_str(),
                stdout);
        }
        std::fputs(formatBoardEnd(format).c_str(), stdout);
        return 0;
    }
    const auto num = [](T v) {
        if (!std::isfinite(v)) return std::string("inf");
        return formatNumber(double(v));
    };
    if (!dda.valid()) {
        std::printf("the ray misses the grid: no cells\n");
        return 0;
    }
    std::printf("step:  ");
    for (int i = 0; i < N; ++i) std::printf(" step%c = %+d", kAxisNames[i], dda.step()[i]);
    std::printf("\ntDelta:");
    for (int i = 0; i < N; ++i)
        std::printf(" tDelta%c = %s", kAxisNames[i], num(dda.tDelta()[i]).c_str());
    std::printf("\n\n %4s", "#");
    for (int i = 0; i < N; ++i) std::printf(" %5c", kAxisNames[i]);
    for (int i = 0; i < N; ++i) std::printf(" %11s%c", "tMax", kAxisNames[i]);
    std::printf("  %10s %10s  next step\n", "t enter", "t exit");
    int row = 0;
    for (bool more = true; more && !std::ferror(stdout);) {
        std::printf(" %4d", row++);
        for (int i = 0; i < N; ++i) std::printf(" %5d", dda.cell()[i]);
        const VecN<N, T> tMax = dda.tMax();
        for (int i = 0; i < N; ++i) std::printf(" %12s", num(tMax[i]).c_str());
        std::printf("  %10s %10s  ", num(dda.tEnter()).c_str(), num(dda.tCellExit()).c_str());
        more = dda.next();
        if (!more) {
            std::printf("leaves the grid\n");
            break;
        }
        const std::vector<int> taken = axes(dda.axesTaken());
        std::string what;
        for (int ax : taken) what += std::string(what.empty() ? "" : "+") + kAxisNames[ax];
        std::printf("%s%s\n", what.c_str(),
                    taken.size() > 1 ? " (tie: through a grid edge or vertex)" : "");
    }
    return 0;
}

}  // namespace

int runDda(const DdaArgs& a) {
    if (!a.format.empty() && !parseBoardFormat(a.format))
        return fail("--format " + a.format + ": expected csv, markdown or latex");
    const auto res = parseNumbers(a.grid);
    if (!res || (res->size() != 2 && res->size() != 3))
        return fail("--grid " + a.grid + ": expected NX,NY or NX,NY,NZ");
    const std::size_t n = res->size();
    for (double r : *res)
        if (r != std::floor(r) || r < 1 || r > 1e6)
            return fail("--grid " + a.grid +
                        ": cells per axis must be whole numbers from 1 to 1000000");
    const auto vec = [&](const std::string& text) {
        const auto v = parseNumbers(text);
        if (!v || v->size() != n) return std::optional<std::vector<double>>();
        return v;
    };
    const auto lo = vec(a.min), hi = vec(a.max), o = vec(a.origin), d = vec(a.dir);
    const std::string dims = n == 2 ? "2 finite numbers x,y" : "3 finite numbers x,y,z";
    if (!lo) return fail("--min " + a.min + ": expected " + dims + " (as many as --grid)");
    if (!hi) return fail("--max " + a.max + ": expected " + dims + " (as many as --grid)");
    if (!o) return fail("--origin " + a.origin + ": expected " + dims + " (as many as --grid)");
    if (!d) return fail("--dir " + a.dir + ": expected " + dims + " (as many as --grid)");
    for (std::size_t i = 0; i < n; ++i) {
        if (!((*hi)[i] > (*lo)[i]))
            return fail("--max " + a.max + ": must be greater than --min on every axis");
        if (!std::isfinite((*hi)[i] - (*lo)[i]))
            return fail("--max " + a.max + ": the grid's size from --min overflows a double");
    }
    bool zero = true;
    for (double x : *d) zero = zero && x == 0.0;
    if (zero) return fail("--dir " + a.dir + ": the direction must not be zero");
    const auto precision = parsePrecision(a.precision);
    if (!precision) return fail("--precision " + a.precision + ": expected float or double");
    if (*precision == Precision::Float) {
        // The same numbers must survive rounding to float (a finite float grid and ray).
        for (const auto* v : {&*lo, &*hi, &*o, &*d})
            for (double x : *v)
                if (!std::isfinite(float(x)))
                    return fail("--precision float: " + std::to_string(x) +
                                " is too large for float");
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(float((*hi)[i]) - float((*lo)[i])))
                return fail(
                    "--precision float: the grid's size from --min to --max overflows "
                    "a float");
        return n == 2 ? walk<2, float>(a, *res, *lo, *hi, *o, *d)
                      : walk<3, float>(a, *res, *lo, *hi, *o, *d);
    }
    return n == 2 ? walk<2, double>(a, *res, *lo, *hi, *o, *d)
                  : walk<3, double>(a, *res, *lo, *hi, *o, *d);
}

}  // namespace raystep::cli
