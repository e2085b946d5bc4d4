// raystep-cli: the renderer from the command line, for lecturers' scripts and for tests.
#include "accel_args.h"
#include "common.h"
#include "dda_command.h"
#include "intersect_command.h"
#include "lesson_command.h"
#include "progress.h"
#include "tree_commands.h"

#include "raystep/accel/accel.h"
#include "raystep/render/image.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/render/tracer.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <tbb/info.h>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
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
    cli::AccelArgs accel;
    std::string rayOffset = "robust";
    int threads = 0;
    std::uint64_t seed = 1;
    std::string stats;
    std::string heatmap;
};

int listScenes() {
    std::vector<std::string> names = builtinSceneNames();
    for (const std::string& n : builtinScene2DNames()) names.push_back(n);
    for (const std::string& name : names) {
        std::visit(
            [&](const auto& s) {
                std::printf("%-15s %7u primitives  %s\n", name.c_str(), s.primitiveCount(),
                            s.description.c_str());
            },
            loadAnyScene(name));
    }
    return 0;
}

int runRender(const RenderArgs& a) {
    const std::string output =
        a.output.empty() ? std::filesystem::path(a.scene).stem().string() + ".png" : a.output;
    if (!cli::hasExtension(output, ".png"))
        return fail("-o " + output + ": the image is written as PNG; name it *.png");
    if (!a.heatmap.empty() && !cli::hasExtension(a.heatmap, ".png"))
        return fail("--heatmap " + a.heatmap + ": the heat map is written as PNG; name it *.png");
    if (auto problem = cli::checkOutputs(
            {{"-o", output}, {"--stats", a.stats}, {"--heatmap", a.heatmap}}, {a.scene}))
        return fail(*problem);
    cli::AccelChoice choice;
    if (auto problem = cli::resolveAccel(a.accel, choice)) return fail(*problem);
    const auto offset = parseRayOffset(a.rayOffset);
    if (!offset) return fail("--ray-offset " + a.rayOffset + ": expected epsilon or robust");

    Scene scene;
    try {
        scene = loadScene(a.scene);
    } catch (const SceneError& e) {
        return fail(e.what());
    }
    if (auto problem = cli::checkKernelRange(a.scene, scene, choice)) return fail(*problem);

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
    {
        cli::ProgressBar buildBar("build " + cli::describeAccel(choice));
        choice.options.setProgress([&](double f) { return buildBar.update(f); });
        accel = buildAccelerator(scene, choice.kind, choice.kernels, choice.options);
        buildBar.finish();
    }

    cli::ProgressBar bar("render " + scene.name);
    const RenderResult result =
        render(scene, *accel, opt, [&bar](double f) { return bar.update(f); });
    bar.finish();

    // The image, the heat map and the stats are written all or none, once all are ready.
    std::vector<FileToWrite> files;
    const std::string png = encodePng(output, toSrgb8(result.image), opt.width, opt.height);
    files.push_back({output, png});
    std::string heatmapPng, statsJson;
    if (!a.heatmap.empty()) {
        heatmapPng = encodePng(a.heatmap, heatmapRgb8(result.costPerPixel, opt.width, opt.height),
                               opt.width, opt.height);
        files.push_back({a.heatmap, heatmapPng});
    }
    if (!a.stats.empty()) {
        const RayCounters& c = result.counters;
        nlohmann::ordered_json j;
        j["scene"] = scene.name;
        j["width"] = opt.width;
        j["height"] = opt.height;
        j["spp"] = opt.spp;
        j["bounces"] = opt.trace.bounces;
        j["diffuse_samples"] = opt.trace.diffuseSamples;
        j["accel"] = cli::describeAccel(choice);
        j["precision"] = a.accel.precision;
        j["ray_offset"] = a.rayOffset;
        j["triangle_method"] = a.accel.triangleMethod;
        j["sphere_method"] = a.accel.sphereMethod;
        if (const auto* grid = std::get_if<UniformGrid>(&*accel)) {
            const auto& res = grid->spec().res;
            j["grid"] = {{"cells", {res.x, res.y, res.z}},
                         {"references", grid->references()},
                         {"empty_cells", grid->emptyCells()},
                         {"mailbox", a.accel.mailbox}};
        }
        if (choice.kind == AccelKind::KdTree || choice.kind == AccelKind::Bvh) {
            const BuildSummary b = summarize(*accel);
            j["tree"] = {{"nodes", b.stats.nodes},        {"leaves", b.stats.leaves},
                         {"max_depth", b.stats.maxDepth}, {"references", b.stats.references},
                         {"sah_cost", b.stats.sahCost},   {"build_ms", b.stats.buildMs}};
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
        statsJson = j.dump(2) + "\n";
        files.push_back({a.stats, statsJson});
    }
    if (auto problem = cli::writeOutputs(files)) return fail(*problem);
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
    render->add_option("-o,--output", r.output, "Output PNG (default: <scene>.png)")
        ->check(cli::fileName());
    render->add_option("--width", r.width, "Image width in pixels")
        ->transform(cli::wholeNumber(1, kMaxImageSide));
    render->add_option("--height", r.height, "Image height in pixels")
        ->transform(cli::wholeNumber(1, kMaxImageSide));
    render->add_option("--bounces", r.bounces, "Depth of secondary rays (0 = primary rays only)")
        ->transform(cli::wholeNumber(0, 64));
    render->add_option("--spp", r.spp, "Jittered samples per pixel")
        ->transform(cli::wholeNumber(1, 4096));
    render
        ->add_option("--diffuse-samples", r.diffuseSamples,
                     "Random diffuse bounce rays at the first diffuse hit (0 = none)")
        ->transform(cli::wholeNumber(0, 1024));
    cli::addAccelOptions(render, r.accel);
    render
        ->add_option("--ray-offset", r.rayOffset,
                     "Secondary-ray origins: epsilon (fixed 1e-4) or robust (error bounds)")
        ->capture_default_str();
    render->add_option("--threads", r.threads, "Threads (default: all cores)")
        ->transform(cli::wholeNumber(1, 1024));
    render->add_option("--seed", r.seed, "Seed of the random numbers")
        ->transform(cli::wholeNumber(0, UINT64_MAX))
        ->capture_default_str();
    render->add_option("--stats", r.stats, "Write ray counts and timings as JSON")
        ->check(cli::fileName());
    render->add_option("--heatmap", r.heatmap, "Write primitive tests per pixel as a PNG heat map")
        ->check(cli::fileName());

    // CLI11 would only say "A subcommand is required": name the word it did not know.
    const std::string first = argc > 1 ? argv[1] : "";
    const std::array<std::string, 8> commands = {"scenes", "render", "intersect", "dda",
                                                 "build",  "trace",  "compare",   "lesson"};
    if (!first.empty() && first[0] != '-' &&
        std::find(commands.begin(), commands.end(), first) == commands.end())
        return fail(std::string("unknown command '") + argv[1] +
                    "' (expected: scenes, render, intersect, dda, build, trace, compare, lesson)");
    cli::IntersectArgs intersectArgs;
    cli::addIntersectCommand(app, intersectArgs);
    cli::DdaArgs ddaArgs;
    cli::addDdaCommand(app, ddaArgs);
    cli::BuildArgs buildArgs;
    cli::addBuildCommand(app, buildArgs);
    cli::TraceArgs traceArgs;
    cli::addTraceCommand(app, traceArgs);
    cli::CompareArgs compareArgs;
    cli::addCompareCommand(app, compareArgs);
    cli::LessonArgs lessonArgs;
    cli::addLessonCommand(app, lessonArgs);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(e.what());
    }

    int code = 0;
    // Whatever a command did not catch (a path the file system refuses, memory) is still bad
    // input: one line and exit 2, never an abort.
    try {
        if (app.got_subcommand("scenes"))
            code = listScenes();
        else if (app.got_subcommand("intersect"))
            code = cli::runIntersect(intersectArgs);
        else if (app.got_subcommand("dda"))
            code = cli::runDda(ddaArgs);
        else if (app.got_subcommand("build"))
            code = cli::runBuild(buildArgs);
        else if (app.got_subcommand("trace"))
            code = cli::runTrace(traceArgs);
        else if (app.got_subcommand("compare"))
            code = cli::runCompare(compareArgs);
        else if (app.got_subcommand("lesson"))
            code = cli::runLesson(app.get_subcommand("lesson"), lessonArgs);
        else
            code = runRender(r);
    } catch (const std::filesystem::filesystem_error& e) {
        return fail(e.path1().string() + ": " + e.code().message());
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    // Output redirected to a full disk or a closed file is a failed write too.
    errno = 0;
    if ((std::fflush(stdout) != 0 || std::ferror(stdout)) && code == 0)
        return fail(std::string("standard output: cannot write: ") +
                    (errno ? std::strerror(errno) : "write error"));
    return code;
}
