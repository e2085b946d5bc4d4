// raystep-cli: the renderer from the command line, for lecturers' scripts and for tests.
#include "common.h"
#include "dda_command.h"
#include "intersect_command.h"
#include "progress.h"

#include "raystep/accel.h"
#include "raystep/image.h"
#include "raystep/scene_loader.h"
#include "raystep/tracer.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <tbb/info.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

namespace {

using namespace raystep;

using cli::fail;

struct RenderArgs {
    std::string scene = "default";
    std::string output;
    std::optional<int> width, height, bounces, spp, diffuseSamples;
    std::string accel = "bruteforce";
    std::string precision = "double";
    std::string rayOffset = "robust";
    std::string triangleMethod = "watertight";
    std::string sphereMethod = "stable";
    double gridLambda = 4.0;
    std::string gridRes;
    std::string mailbox = "on";
    int threads = 0;
    std::uint64_t seed = 1;
    std::string stats;
    std::string heatmap;
};

bool hasExtension(const std::string& path, const std::string& ext) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e == ext;
}

/// Checks that a file can be created at `path` before any long work is done.
std::optional<std::string> checkWritable(const std::string& option, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent))
        return option + " " + path + ": folder '" + parent.string() + "' does not exist";
    if (fs::is_directory(path)) return option + " " + path + ": is a folder";
    return std::nullopt;
}

int listScenes() {
    for (const std::string& name : builtinSceneNames()) {
        const Scene s = loadBuiltinScene(name);
        std::printf("%-10s %7u primitives  %s\n", name.c_str(), s.primitiveCount(),
                    s.description.c_str());
    }
    return 0;
}

int runRender(const RenderArgs& a) {
    const std::string output =
        a.output.empty() ? std::filesystem::path(a.scene).stem().string() + ".png" : a.output;
    if (!hasExtension(output, ".png"))
        return fail("-o " + output + ": the image is written as PNG; name it *.png");
    if (!a.heatmap.empty() && !hasExtension(a.heatmap, ".png"))
        return fail("--heatmap " + a.heatmap + ": the heat map is written as PNG; name it *.png");
    for (const auto& [opt, path] : {std::pair<std::string, std::string>{"-o", output},
                                    {"--stats", a.stats},
                                    {"--heatmap", a.heatmap}}) {
        if (path.empty()) continue;
        if (auto problem = checkWritable(opt, path)) return fail(*problem);
    }
    const auto accelKind = parseAccelKind(a.accel);
    if (!accelKind)
        return fail("--accel " + a.accel + ": expected bruteforce, grid, kdtree or bvh");
    KernelOptions kernels;
    const auto precision = parsePrecision(a.precision);
    if (!precision) return fail("--precision " + a.precision + ": expected float or double");
    const auto offset = parseRayOffset(a.rayOffset);
    if (!offset) return fail("--ray-offset " + a.rayOffset + ": expected epsilon or robust");
    const auto triangleMethod = parseTriangleMethod(a.triangleMethod);
    if (!triangleMethod)
        return fail("--triangle-method " + a.triangleMethod +
                    ": expected plane, moller-trumbore or watertight");
    const auto sphereMethod = parseSphereMethod(a.sphereMethod);
    if (!sphereMethod)
        return fail("--sphere-method " + a.sphereMethod + ": expected textbook or stable");
    kernels = {*precision, *sphereMethod, *triangleMethod};
    AccelOptions accelOptions;
    if (!std::isfinite(a.gridLambda) || !(a.gridLambda > 0))
        return fail("--grid-lambda " + std::to_string(a.gridLambda) +
                    ": must be a finite number greater than 0");
    accelOptions.grid.lambda = a.gridLambda;
    if (!a.gridRes.empty()) {
        const auto res = cli::parseNumbers(a.gridRes);
        bool ok = res && res->size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i)
            ok = (*res)[i] == std::floor((*res)[i]) && (*res)[i] >= 1 &&
                 (*res)[i] <= GridOptions::kMaxCellsPerAxis;
        if (!ok)
            return fail("--grid-res " + a.gridRes +
                        ": expected NX,NY,NZ, whole numbers from 1 to " +
                        std::to_string(GridOptions::kMaxCellsPerAxis));
        accelOptions.grid.res = std::array<int, 3>{int((*res)[0]), int((*res)[1]), int((*res)[2])};
    }
    if (a.mailbox != "on" && a.mailbox != "off")
        return fail("--mailbox " + a.mailbox + ": expected on or off");
    accelOptions.grid.mailbox = a.mailbox == "on";

    Scene scene;
    try {
        scene = loadScene(a.scene);
    } catch (const SceneError& e) {
        return fail(e.what());
    }

    RenderOptions opt;
    opt.width = a.width.value_or(scene.settings.width);
    opt.height = a.height.value_or(scene.settings.height);
    opt.spp = a.spp.value_or(scene.settings.spp);
    opt.trace.bounces = a.bounces.value_or(scene.settings.bounces);
    opt.trace.diffuseSamples = a.diffuseSamples.value_or(scene.settings.diffuseSamples);
    opt.threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
    opt.seed = a.seed;
    opt.trace.rayOffset = *offset;

    std::optional<Accelerator> accel;
    try {
        accel = buildAccelerator(scene, *accelKind, kernels, accelOptions);
    } catch (const std::exception& e) {
        return fail(e.what());
    }

    cli::ProgressBar bar("render " + scene.name);
    const RenderResult result =
        render(scene, *accel, opt, [&bar](double f) { return bar.update(f); });
    bar.finish();

    try {
        writePng(output, toSrgb8(result.image), opt.width, opt.height);
        if (!a.heatmap.empty())
            writePng(a.heatmap, heatmapRgb8(result.costPerPixel, opt.width, opt.height), opt.width,
                     opt.height);
        if (!a.stats.empty()) {
            const RayCounters& c = result.counters;
            nlohmann::ordered_json j;
            j["scene"] = scene.name;
            j["width"] = opt.width;
            j["height"] = opt.height;
            j["spp"] = opt.spp;
            j["bounces"] = opt.trace.bounces;
            j["diffuse_samples"] = opt.trace.diffuseSamples;
            j["accel"] = a.accel;
            j["precision"] = a.precision;
            j["ray_offset"] = a.rayOffset;
            j["triangle_method"] = a.triangleMethod;
            j["sphere_method"] = a.sphereMethod;
            if (const auto* grid = std::get_if<UniformGrid>(&*accel)) {
                const auto& res = grid->spec().res;
                j["grid"] = {{"cells", {res.x, res.y, res.z}},
                             {"references", grid->references()},
                             {"empty_cells", grid->emptyCells()},
                             {"mailbox", a.mailbox}};
            }
            j["threads"] = opt.threads;
            j["seed"] = opt.seed;
            j["primitives"] = {{"spheres", scene.spheres.size()},
                               {"triangles", scene.triangles.size()}};
            for (int k = 0; k < kRayKindCount; ++k)
                j["rays"][std::string(kRayKindNames[k])] = c.rays[k];
            j["rays"]["total"] = c.totalRays();
            j["primitive_tests"] = c.traversal.primitiveTests;
            j["node_visits"] = c.traversal.nodeVisits;
            j["mailbox_skips"] = c.traversal.mailboxSkips;
            j["max_primitive_tests_per_pixel"] =
                *std::max_element(result.costPerPixel.begin(), result.costPerPixel.end());
            j["render_ms"] = result.renderMs;
            j["mrays_per_s"] = c.totalRays() / (result.renderMs * 1e3);
            writeFileAtomic(a.stats, j.dump(2) + "\n");
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    std::printf("wrote %s (%dx%d, %d spp, %llu rays, %.0f ms)\n", output.c_str(), opt.width,
                opt.height, opt.spp, static_cast<unsigned long long>(result.counters.totalRays()),
                result.renderMs);
    if (!a.heatmap.empty())
        std::printf("wrote %s (primitive tests per pixel, 0 = dark to %llu = bright)\n",
                    a.heatmap.c_str(),
                    static_cast<unsigned long long>(
                        *std::max_element(result.costPerPixel.begin(), result.costPerPixel.end())));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"raystep-cli: the raystep ray tracer from the command line"};
    app.require_subcommand(1);

    app.add_subcommand("scenes", "List the built-in scenes");

    RenderArgs r;
    CLI::App* render = app.add_subcommand("render", "Render a scene to a PNG image");
    render->add_option("scene", r.scene, "Built-in scene name or scene file (default: default)");
    render->add_option("-o,--output", r.output, "Output PNG (default: <scene>.png)");
    render->add_option("--width", r.width, "Image width in pixels")
        ->check(CLI::Range(1, kMaxImageSide));
    render->add_option("--height", r.height, "Image height in pixels")
        ->check(CLI::Range(1, kMaxImageSide));
    render->add_option("--bounces", r.bounces, "Depth of secondary rays (0 = primary rays only)")
        ->check(CLI::Range(0, 64));
    render->add_option("--spp", r.spp, "Jittered samples per pixel")->check(CLI::Range(1, 4096));
    render
        ->add_option("--diffuse-samples", r.diffuseSamples,
                     "Random diffuse bounce rays at the first diffuse hit (0 = none)")
        ->check(CLI::Range(0, 1024));
    render->add_option("--accel", r.accel, "Accelerator: bruteforce, grid, kdtree or bvh")
        ->capture_default_str();
    render->add_option("--precision", r.precision, "Intersection arithmetic: float or double")
        ->capture_default_str();
    render
        ->add_option("--ray-offset", r.rayOffset,
                     "Secondary-ray origins: epsilon (fixed 1e-4) or robust (error bounds)")
        ->capture_default_str();
    render
        ->add_option("--triangle-method", r.triangleMethod,
                     "Ray-triangle test: plane, moller-trumbore or watertight")
        ->capture_default_str();
    render->add_option("--sphere-method", r.sphereMethod, "Ray-sphere test: textbook or stable")
        ->capture_default_str();
    render
        ->add_option("--grid-lambda", r.gridLambda,
                     "Grid: about this many primitives a cell (Cleary-Wyvill rule)")
        ->capture_default_str();
    render->add_option("--grid-res", r.gridRes,
                       "Grid: cells per axis NX,NY,NZ instead of the rule");
    render->add_option("--mailbox", r.mailbox, "Grid: test each primitive once per ray (on, off)")
        ->capture_default_str();
    render->add_option("--threads", r.threads, "Threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    render->add_option("--seed", r.seed, "Seed of the random numbers")->capture_default_str();
    render->add_option("--stats", r.stats, "Write ray counts and timings as JSON");
    render->add_option("--heatmap", r.heatmap, "Write primitive tests per pixel as a PNG heat map");

    // CLI11 would only say "A subcommand is required": name the word it did not know.
    const std::string first = argc > 1 ? argv[1] : "";
    if (!first.empty() && first[0] != '-' && first != "scenes" && first != "render" &&
        first != "intersect" && first != "dda")
        return fail(std::string("unknown command '") + argv[1] +
                    "' (expected: scenes, render, intersect, dda)");
    cli::IntersectArgs intersectArgs;
    cli::addIntersectCommand(app, intersectArgs);
    cli::DdaArgs ddaArgs;
    cli::addDdaCommand(app, ddaArgs);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(e.what());
    }

    if (app.got_subcommand("scenes")) return listScenes();
    if (app.got_subcommand("intersect")) return cli::runIntersect(intersectArgs);
    if (app.got_subcommand("dda")) return cli::runDda(ddaArgs);
    return runRender(r);
}
