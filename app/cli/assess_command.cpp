// `raystep-cli assess`: a student's trace against raystep's own run, ray by ray; a folder of
// them as a grade CSV for Moodle's import and a table of the class's mistakes.
#include "assess_command.h"

#include "common.h"

#include "raystep/accel/outline.h"
#include "raystep/assess/assess.h"
#include "raystep/base/file_error.h"
#include "raystep/scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace raystep::cli {

void addAssessCommand(CLI::App& app, AssessArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "assess",
        "Check a student's own DDA, grid walk or tree traversal (JSON Lines) against "
        "raystep's");
    cmd->add_option("target", a.target, "dda (a bare grid walk) or a scene")->required();
    cmd->add_option("--grid", a.grid, "assess dda: cells per axis, NX,NY or NX,NY,NZ");
    cmd->add_option("--min", a.min, "assess dda: the grid's corner with the smallest coordinates");
    cmd->add_option("--max", a.max, "assess dda: the grid's corner with the largest coordinates");
    a.accel.accel = "grid";
    addAccelOptions(cmd, a.accel);
    auto* trace =
        cmd->add_option("--trace", a.trace, "The student's trace (JSON Lines)")->check(fileName());
    auto* cls = cmd->add_option("--class", a.classDir,
                                "A folder of traces: DIR/<id>.jsonl or DIR/<id>/<one>.jsonl")
                    ->check(fileName())
                    ->excludes(trace);
    cmd->add_option("-o,--output", a.output, "With --class: the folder for grades.csv and class.md")
        ->check(fileName())
        ->needs(cls);
    cmd->add_flag("--json", a.json, "Print the verdict as JSON")->excludes(cls);
    cmd->add_option("--lang", a.lang, "Language of the explanations: " + languageChoices())
        ->capture_default_str();
    cmd->add_flag("--structure", a.structure,
                  "Print the scene's structure (nodes, cells, primitives) as JSON Lines, numbered "
                  "as a trace names them, and exit")
        ->excludes(trace)
        ->excludes(cls);
}

namespace {

struct BadInput {
    std::string message;
};

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string o = "\"";
    for (const char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
}

GridSpec<3, double> parseGrid(const AssessArgs& a, int& dims) {
    if (a.grid.empty() || a.min.empty() || a.max.empty())
        throw BadInput{"assess dda needs --grid, --min and --max"};
    const auto res = parseNumbers(a.grid), lo = parseNumbers(a.min), hi = parseNumbers(a.max);
    if (!res || (res->size() != 2 && res->size() != 3))
        throw BadInput{"--grid " + a.grid + ": expected NX,NY or NX,NY,NZ"};
    dims = int(res->size());
    GridSpec<3, double> g;
    for (int i = 0; i < dims; ++i) {
        const double r = (*res)[i];
        if (r != std::floor(r) || r < 1 || r > 1'000'000)
            throw BadInput{"--grid " + a.grid +
                           ": cells per axis are whole numbers from 1 to 1000000"};
        g.res[i] = int(r);
    }
    if (!lo || int(lo->size()) != dims)
        throw BadInput{"--min " + a.min + ": expected " + std::to_string(dims) + " numbers"};
    if (!hi || int(hi->size()) != dims)
        throw BadInput{"--max " + a.max + ": expected " + std::to_string(dims) + " numbers"};
    for (int i = 0; i < dims; ++i) {
        g.lo[i] = (*lo)[i];
        g.hi[i] = (*hi)[i];
        if (!(g.hi[i] > g.lo[i]))
            throw BadInput{"--max " + a.max + ": not above --min " + a.min + " on every axis"};
    }
    return g;
}

/// The structure raystep checks against, numbered as the trace names it, one record a line.
template <int N>
std::string structureLines(const StructureOutline<N>& o) {
    std::string out;
    const auto vec = [](const VecN<N, double>& v) {
        nlohmann::json a = nlohmann::json::array();
        for (int i = 0; i < N; ++i) a.push_back(v[i]);
        return a;
    };
    if (o.grid) {
        nlohmann::ordered_json g;
        std::vector<int> res(N);
        for (int i = 0; i < N; ++i) res[i] = o.grid->spec.res[i];
        g["grid"] = {{"res", res}, {"lo", vec(o.grid->spec.lo)}, {"hi", vec(o.grid->spec.hi)}};
        out += g.dump() + "\n";
    }
    for (std::size_t id = 0; id < o.nodes.size(); ++id) {
        const auto& n = o.nodes[id];
        nlohmann::ordered_json j;
        j["node"] = id;
        j["lo"] = vec(n.box.lo);
        j["hi"] = vec(n.box.hi);
        if (n.leaf) {
            const auto prims = o.primitivesOf(std::uint32_t(id));
            j["prims"] = std::vector<std::uint32_t>(prims.begin(), prims.end());
        } else {
            j["axis"] = n.axis;
            if (n.plane) j["split"] = o.planes[*n.plane].position;
            j["children"] = n.children;
        }
        out += j.dump() + "\n";
    }
    return out;
}

std::string primitiveLines(const std::variant<Scene, Scene2D>& any) {
    std::string out;
    std::uint32_t id = 0;
    if (const auto* s = std::get_if<Scene2D>(&any)) {
        for (const auto& c : s->circles)
            out += nlohmann::ordered_json(
                       {{"prim", id++},
                        {"circle", {{"center", {c.center.x, c.center.y}}, {"radius", c.radius}}}})
                       .dump() +
                   "\n";
        for (const auto& g : s->segments)
            out += nlohmann::ordered_json(
                       {{"prim", id++},
                        {"segment", {{"from", {g.a.x, g.a.y}}, {"to", {g.b.x, g.b.y}}}}})
                       .dump() +
                   "\n";
        return out;
    }
    const Scene& s = std::get<Scene>(any);
    for (const auto& sp : s.spheres)
        out += nlohmann::ordered_json(
                   {{"prim", id++},
                    {"sphere",
                     {{"center", {sp.center.x, sp.center.y, sp.center.z}}, {"radius", sp.radius}}}})
                   .dump() +
               "\n";
    for (const auto& t : s.triangles)
        out += nlohmann::ordered_json({{"prim", id++},
                                       {"triangle",
                                        {std::vector<double>{t.a.x, t.a.y, t.a.z},
                                         std::vector<double>{t.b.x, t.b.y, t.b.z},
                                         std::vector<double>{t.c.x, t.c.y, t.c.z}}}})
                   .dump() +
               "\n";
    return out;
}

/// The grid's cells that list primitives, one line each.
template <int N>
std::string cellLines(const OutlineGrid<N>& grid) {
    std::string out;
    IVecN<N> c{0};
    for (std::size_t k = 0; k + 1 < grid.cellStart.size(); ++k) {
        if (grid.cellStart[k + 1] > grid.cellStart[k]) {
            std::vector<int> cell(N);
            for (int i = 0; i < N; ++i) cell[i] = c[i];
            out += nlohmann::ordered_json(
                       {{"cell", cell},
                        {"prims", std::vector<std::uint32_t>(
                                      grid.cellPrimitives.begin() + grid.cellStart[k],
                                      grid.cellPrimitives.begin() + grid.cellStart[k + 1])}})
                       .dump() +
                   "\n";
        }
        int a = 0;
        while (a < N && ++c[a] == grid.spec.res[a]) c[a++] = 0;
    }
    return out;
}

struct Target {
    std::variant<Scene, Scene2D> scene;
    AnyStructure structure;
    std::optional<Reference> reference;
    int dims = 2;
};

void loadTarget(const AssessArgs& a, Target& t) {
    if (a.target == "dda") {
        if (a.structure)
            throw BadInput{"--structure: assess dda has no scene (the grid is --grid)"};
        const GridSpec<3, double> g = parseGrid(a, t.dims);
        t.reference = Reference::dda(g, t.dims);
        return;
    }
    if (!a.grid.empty() || !a.min.empty() || !a.max.empty())
        throw BadInput{"--grid, --min and --max are for assess dda; a scene's grid is --grid-res"};
    AccelChoice choice;
    if (auto problem = resolveAccel(a.accel, choice)) throw BadInput{*problem};
    setCurrentInput(a.target);
    try {
        t.scene = loadInput(a.target);
    } catch (const SceneError& e) {
        throw BadInput{e.what()};
    }
    if (const auto* s3 = std::get_if<Scene>(&t.scene))
        if (auto problem = checkKernelRange(a.target, *s3, choice)) throw BadInput{*problem};
    t.structure = buildStructure(t.scene, choice.kind, choice.kernels, choice.options);
    t.dims = t.structure.in2D ? 2 : 3;
    t.reference = Reference::structure(t.structure, choice.kind);
}

std::string structureText(const Target& t) {
    std::string out;
    if (t.structure.in2D) {
        const auto o = outline(*t.structure.in2D, OutlineDetail::Primitives);
        out += structureLines<2>(o);
        if (o.grid) out += cellLines<2>(*o.grid);
    } else {
        const auto o = outline(*t.structure.in3D, OutlineDetail::Primitives);
        out += structureLines<3>(o);
        if (o.grid) out += cellLines<3>(*o.grid);
    }
    return out + primitiveLines(t.scene);
}

/// The traces of a class: DIR/<id>.jsonl, or the one .jsonl file of DIR/<id>/.
std::vector<std::pair<std::string, std::string>> classTraces(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw BadInput{"--class " + printable(dir) + ": not a folder"};
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const fs::path p = e.path();
        if (e.is_regular_file(ec) && p.extension() == ".jsonl") {
            out.emplace_back(p.stem().string(), p.string());
        } else if (e.is_directory(ec)) {
            std::vector<fs::path> inside;
            for (const auto& f : fs::directory_iterator(p, ec))
                if (f.is_regular_file(ec) && f.path().extension() == ".jsonl")
                    inside.push_back(f.path());
            if (inside.size() == 1)
                out.emplace_back(p.filename().string(), inside[0].string());
            else if (inside.size() > 1)
                out.emplace_back(p.filename().string(), "");  // ambiguous: said in its feedback
        }
    }
    if (ec) throw BadInput{"--class " + printable(dir) + ": " + ec.message()};
    std::sort(out.begin(), out.end());
    if (out.empty())
        throw BadInput{"--class " + printable(dir) +
                       ": no <id>.jsonl file and no <id>/ folder "
                       "with one .jsonl file"};
    return out;
}

int gradeClass(const AssessArgs& a, const Target& t, Language lang) {
    if (a.output.empty())
        throw BadInput{"--class needs -o DIR, the folder for grades.csv and class.md"};
    const auto traces = classTraces(a.classDir);
    std::string grades = "id,grade,feedback\r\n";
    std::map<std::string, int> mistakeStudents, quantityRays;
    int allPassed = 0, unreadable = 0;
    double total = 0;
    for (const auto& [id, path] : traces) {
        std::string feedback;
        double pct = 0.0;
        if (path.empty()) {
            feedback = tr(lang, "more than one .jsonl file in the folder");
            ++unreadable;
        } else {
            try {
                const Assessment as = assess(loadStudentTrace(path, t.dims), *t.reference, lang);
                pct = 100.0 * as.score();
                allPassed += as.allPassed();
                const std::string passed = std::to_string(as.passed()),
                                  rays = std::to_string(as.rays.size());
                feedback = trf(lang, "%1/%2 rays passed", {passed, rays});
                std::set<std::string> named;
                bool first = true;
                for (const RayVerdict& v : as.rays) {
                    if (v.passed) continue;
                    const Divergence& d = *v.divergence;
                    // The first failed ray, where the student looks first: its line and quantity.
                    if (first)
                        feedback =
                            trf(lang, "%1/%2 rays passed; ray %3 first fails at line %4, %5 (%6)",
                                {passed, rays, std::to_string(v.ray), std::to_string(d.line),
                                 divergencePlace(d, lang), d.quantity}) +
                            (v.mistake ? ": " + std::string(mistakeInfo(*v.mistake).name) : "");
                    first = false;
                    ++quantityRays[d.quantity];
                    if (v.mistake) named.insert(std::string(mistakeInfo(*v.mistake).name));
                }
                for (const auto& m : named) ++mistakeStudents[m];
            } catch (const FileError& e) {
                feedback = trf(lang, "unreadable: %1", {e.what()});
                ++unreadable;
            }
        }
        total += pct;
        char g[32];
        std::snprintf(g, sizeof g, "%.2f", pct);
        grades += csvField(id) + "," + g + "," + csvField(feedback) + "\r\n";
    }
    char mean[32];
    std::snprintf(mean, sizeof mean, "%.1f", total / double(traces.size()));
    // Counts as "label: n", so no language needs its plurals here.
    std::string md = "# " + trf(lang, "%1: the class", {a.target}) + "\n\n" +
                     trf(lang,
                         "Students: %1. Passed every ray: %2. Mean grade: %3. Traces that could "
                         "not be read: %4.",
                         {std::to_string(traces.size()), std::to_string(allPassed),
                          formatNumber(std::atof(mean), lang), std::to_string(unreadable)}) +
                     "\n\n## " + tr(lang, "The mistakes, most common first") + "\n\n| " +
                     tr(lang, "mistake") + " | " + tr(lang, "students") + " | " +
                     tr(lang, "what it does wrong") + " |\n|---|---|---|\n";
    std::vector<std::pair<int, std::string>> byCount;
    for (const auto& [m, n] : mistakeStudents) byCount.emplace_back(-n, m);
    std::sort(byCount.begin(), byCount.end());
    for (const auto& [n, m] : byCount)
        md += "| " + m + " | " + std::to_string(-n) + " | " +
              // i18n: the descriptions are marked in mistakes.cpp
              tr(lang, mistakeInfo(*parseMistake(m)).description) + " |\n";
    md += "\n## " + tr(lang, "The quantities that decided the failed rays") + "\n\n| " +
          tr(lang, "quantity") + " | " + tr(lang, "rays") + " |\n|---|---|\n";
    std::vector<std::pair<int, std::string>> byRays;
    for (const auto& [q, n] : quantityRays) byRays.emplace_back(-n, q);
    std::sort(byRays.begin(), byRays.end());
    for (const auto& [n, q] : byRays) md += "| " + q + " | " + std::to_string(-n) + " |\n";
    std::error_code ec;
    std::filesystem::create_directories(a.output, ec);
    const std::string gp = (std::filesystem::path(a.output) / "grades.csv").string();
    const std::string cp = (std::filesystem::path(a.output) / "class.md").string();
    if (auto problem = writeOutputs({{gp, grades}, {cp, md}})) throw BadInput{*problem};
    std::printf("%s, %s: students %zu, passed every ray %d%s\n", gp.c_str(), cp.c_str(),
                traces.size(), allPassed,
                byCount.empty() ? ""
                                : ("; most common mistake " + byCount[0].second + " (students " +
                                   std::to_string(-byCount[0].first) + ")")
                                      .c_str());
    return 0;
}

}  // namespace

int runAssess(const AssessArgs& a) {
    const auto lang = parseLanguage(a.lang);
    if (!lang) return fail("--lang " + a.lang + ": expected " + languageChoices());
    try {
        if (a.trace.empty() && a.classDir.empty() && !a.structure)
            throw BadInput{"assess needs --trace FILE, --class DIR or --structure"};
        Target t;
        loadTarget(a, t);
        if (a.structure) {
            std::fputs(structureText(t).c_str(), stdout);
            return 0;
        }
        if (!a.classDir.empty()) return gradeClass(a, t, *lang);
        const Assessment as = assess(loadStudentTrace(a.trace, t.dims), *t.reference, *lang);
        const std::string out = a.json ? assessmentJson(as, *lang) : assessmentText(as, *lang);
        std::fputs(out.c_str(), stdout);
        return as.allPassed() ? 0 : 1;
    } catch (const BadInput& e) {
        return fail(e.message);
    } catch (const FileError& e) {
        return fail(e.what());
    }
}

}  // namespace raystep::cli
