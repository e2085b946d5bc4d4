// `raystep-cli render`: build, render, then write image, heat map and stats all or none.
#include "render_command.h"

#include "common.h"
#include "progress.h"

#include "raystep/accel/outline.h"
#include "raystep/render/image.h"
#include "raystep/render/render.h"
#include "raystep/scene/model_import.h"
#include "raystep/scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <tbb/info.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace raystep::cli {

void addRenderCommand(CLI::App& app, RenderArgs& a) {
    CLI::App* cmd = app.add_subcommand("render", "Render a scene to a PNG image");
    cmd->add_option("scene", a.scene,
                    "Built-in scene name, scene file, or model (.obj .ply .stl .gltf .glb: a "
                    "camera, a floor and two lights are put around it; default: default)");
    cmd->add_option("-o,--output", a.output, "Output PNG (default: <scene>.png)")
        ->check(fileName());
    cmd->add_option("--width", a.width, "Image width in pixels")
        ->transform(wholeNumber(1, kMaxImageSide));
    cmd->add_option("--height", a.height, "Image height in pixels")
        ->transform(wholeNumber(1, kMaxImageSide));
    cmd->add_option("--bounces", a.bounces, "Depth of secondary rays (0 = primary rays only)")
        ->transform(wholeNumber(0, kMaxBounces));
    cmd->add_option("--spp", a.spp, "Jittered samples per pixel")
        ->transform(wholeNumber(1, kMaxSpp));
    cmd->add_option("--diffuse-samples", a.diffuseSamples,
                    "Random diffuse bounce rays at the first diffuse hit (0 = none)")
        ->transform(wholeNumber(0, kMaxDiffuseSamples));
    addAccelOptions(cmd, a.accel);
    CLI::Option* accelOption = cmd->get_option("--accel");
    a.accelOption = accelOption;
    accelOption->description("Accelerator: " + std::string(kFastAccel) +
                             " (the fast path: a four-wide BVH in float, SIMD, nothing "
                             "recorded) or a teaching structure, " +
                             accelOption->get_description().substr(13));
    for (const char* k : {"--precision", "--triangle-method", "--sphere-method"})
        a.kernelOptions.push_back(cmd->get_option(k));
    cmd->add_option("--ray-offset", a.rayOffset,
                    "Secondary-ray origins: epsilon (fixed 1e-4) or robust (error bounds)")
        ->capture_default_str();
    cmd->add_option("--threads", a.threads, "Threads (default: all cores)")
        ->transform(wholeNumber(1, 1024));
    cmd->add_option("--seed", a.seed, "Seed of the random numbers")
        ->transform(wholeNumber(0, UINT64_MAX))
        ->capture_default_str();
    cmd->add_option("--stats", a.stats, "Write ray counts and timings as JSON")->check(fileName());
    cmd->add_option("--heatmap", a.heatmap, "Write primitive tests per pixel as a PNG heat map")
        ->check(fileName());
    cmd->add_option("--save-scene", a.saveScene,
                    "Model only: write the scene made around it as a scene file (*.json), its "
                    "mesh beside it as <name>.mesh.obj")
        ->check(fileName());
}

int runRender(const RenderArgs& a) {
    setCurrentInput(a.scene);
    const std::string output =
        a.output.empty() ? std::filesystem::path(a.scene).stem().string() + ".png" : a.output;
    if (!hasExtension(output, ".png"))
        return fail("-o " + output + ": the image is written as PNG; name it *.png");
    if (!a.heatmap.empty() && !hasExtension(a.heatmap, ".png"))
        return fail("--heatmap " + a.heatmap + ": the heat map is written as PNG; name it *.png");
    const bool model = isModelPath(a.scene);
    std::string meshPath;  // --save-scene's mesh: <name>.mesh.obj beside the scene file
    if (!a.saveScene.empty()) {
        if (!model)
            return fail("--save-scene " + a.saveScene + ": only a model (" +
                        "*.obj, *.ply, *.stl, *.gltf, *.glb) is made into a scene; " + a.scene +
                        " is a scene already");
        if (!hasExtension(a.saveScene, ".json"))
            return fail("--save-scene " + a.saveScene +
                        ": the scene is written as a scene file; name it *.json");
        meshPath = (std::filesystem::path(a.saveScene).parent_path() /
                    (std::filesystem::path(a.saveScene).stem().string() + ".mesh.obj"))
                       .string();
    }
    if (auto problem = checkOutputs({{"-o", output},
                                     {"--stats", a.stats},
                                     {"--heatmap", a.heatmap},
                                     {"--save-scene", a.saveScene},
                                     {"--save-scene (its mesh)", meshPath}},
                                    inputsOf(a.scene)))
        return fail(*problem);
    // A whole image records nothing: the fast path, whose images equal the accurate path's within
    // docs/accuracy.md's tolerance, unless --accel or a kernel option asks for a structure (a
    // model then gets a kd-tree, a scene brute force, as before there was a fast path).
    AccelArgs accelArgs = a.accel;
    const bool accelGiven = a.accelOption && a.accelOption->count() > 0;
    bool kernelsGiven = false;
    for (const CLI::Option* k : a.kernelOptions) kernelsGiven = kernelsGiven || k->count() > 0;
    if (!accelGiven)
        accelArgs.accel = kernelsGiven ? (model ? "kdtree" : "bruteforce") : kFastAccel;
    // The fast path has one set of kernels; the other options are checked as a BVH's would be.
    bool fast = accelArgs.accel == kFastAccel;
    if (fast) {
        const std::pair<std::string, std::string> fixed[] = {{"float", a.accel.precision},
                                                             {"watertight", a.accel.triangleMethod},
                                                             {"stable", a.accel.sphereMethod}};
        for (std::size_t k = 0; k < a.kernelOptions.size(); ++k)
            if (a.kernelOptions[k]->count() > 0 && fixed[k].second != fixed[k].first)
                return fail(a.kernelOptions[k]->get_name() + " " + fixed[k].second +
                            ": --accel fast tests in float with watertight triangles and stable "
                            "spheres; choose a teaching structure (--accel bvh) for " +
                            fixed[k].second);
        accelArgs.accel = "bvh";
    }
    AccelChoice choice;
    if (auto problem = resolveAccel(accelArgs, choice)) return fail(*problem);
    if (fast) choice.kernels = WideBvh::kKernels;
    const auto offset = parseRayOffset(a.rayOffset);
    if (!offset) return fail("--ray-offset " + a.rayOffset + ": expected epsilon or robust");

    Scene scene;
    try {
        // A scene file through loadScene: a 2D one is refused there with its line.
        scene = model ? std::get<Scene>(loadInput(a.scene)) : loadScene(a.scene);
    } catch (const SceneError& e) {
        return fail(e.what());
    }
    if (auto problem = checkKernelRange(a.scene, scene, choice)) {
        if (!fast || accelGiven) return fail(*problem);
        // The default only: a scene beyond float's range is rendered by the accurate path.
        fast = false;
        choice.kernels = KernelOptions{};
        accelArgs.accel = model ? "kdtree" : "bruteforce";
        if (auto p = resolveAccel(accelArgs, choice)) return fail(*p);
        std::fprintf(stderr,
                     "raystep-cli: note: %s lies beyond the fast path's float range: rendered "
                     "with %s in double\n",
                     a.scene.c_str(), describeAccel(choice).c_str());
    }

    RenderOptions opt;
    opt.width = a.width.value_or(scene.settings.width);
    opt.height = a.height.value_or(scene.settings.height);
    opt.spp = a.spp.value_or(scene.settings.spp);
    opt.trace.bounces = a.bounces.value_or(scene.settings.bounces);
    opt.trace.diffuseSamples = a.diffuseSamples.value_or(scene.settings.diffuseSamples);
    opt.threads = threadCount(a.threads);
    opt.seed = a.seed;
    opt.trace.rayOffset = *offset;

    // Every cap (kMaxImageSide, kMaxSpp, kMaxDiffuseSamples) allows a render of years: its
    // size said before it starts, in rays and in time at a brisk pace. Ctrl+C stops it.
    const double rays = double(opt.width) * opt.height * opt.spp * (1.0 + opt.trace.diffuseSamples);
    if (rays > 1e11) {
        const double seconds = rays / 1e7;
        char when[64];
        if (seconds < 86400 * 2)
            std::snprintf(when, sizeof when, "%.0f hours", seconds / 3600);
        else
            std::snprintf(when, sizeof when, "%.0f days", seconds / 86400);
        std::fprintf(stderr,
                     "raystep-cli: warning: %s asks for about %.2g camera and diffuse rays (%dx%d "
                     "pixels, %d samples, %d diffuse rays each): at 10 million rays a second, %s "
                     "(Ctrl+C stops it)\n",
                     scene.name.c_str(), rays, opt.width, opt.height, opt.spp,
                     opt.trace.diffuseSamples, when);
    }

    std::optional<Accelerator> accel;
    std::optional<WideBvh> wide;
    const std::string description = fast ? std::string(kFastAccel) : describeAccel(choice);
    {
        ProgressBar buildBar("build " + description);
        const ProgressFn progress = [&](double f) { return buildBar.update(f); };
        if (fast) {
            WideBvhOptions wideOptions;
            wideOptions.progress = progress;
            wide.emplace(scene, wideOptions);
        } else {
            choice.options.setProgress(progress);
            accel = buildAccelerator(scene, choice.kind, choice.kernels, choice.options);
        }
        buildBar.finish();
    }

    ProgressBar bar("render " + scene.name);
    const RenderResult result = render(scene, fast ? SceneQuery(*wide) : SceneQuery(*accel), opt,
                                       [&bar](double f) { return bar.update(f); });
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
        j["accel"] = description;
        j["precision"] = std::string(name(choice.kernels.precision));
        j["ray_offset"] = a.rayOffset;
        j["triangle_method"] = std::string(name(choice.kernels.triangle));
        j["sphere_method"] = std::string(name(choice.kernels.sphere));
        if (fast) {
            const WideBvhStats& w = wide->stats();
            j["fast"] = {{"nodes", w.nodes},        {"leaves", w.leaves},
                         {"blocks", w.blocks},      {"empty_lanes", w.emptyLanes},
                         {"max_depth", w.maxDepth}, {"bytes", w.bytes},
                         {"build_ms", w.buildMs}};
        }
        // A grid's cells from its outline (asked of a grid only: a tree's lists every node).
        if (!fast && readsOption(choice.kind, AccelOption::GridRes))
            if (const auto grid = outline(*accel).grid) {
                const BuildSummary b = summarize(*accel);
                const auto& res = grid->spec.res;
                j["grid"] = {{"cells", {res.x, res.y, res.z}},
                             {"references", b.stats.references},
                             {"empty_cells", b.stats.emptyLeaves},
                             {"mailbox", a.accel.mailbox}};
            }
        if (!fast && hasSplit(choice.kind)) {
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
    SceneFiles sceneFiles;
    if (!a.saveScene.empty()) {
        // The model's triangles come first in the scene (sceneAroundModel); the floor follows.
        const std::size_t modelTriangles = scene.triangles.size() - 2;
        sceneFiles = sceneFilesFor(scene, modelTriangles,
                                   std::filesystem::path(meshPath).filename().string());
        files.push_back({a.saveScene, sceneFiles.sceneJson});
        files.push_back({meshPath, sceneFiles.meshObj});
    }
    if (auto problem = writeOutputs(files)) return fail(*problem);
    std::printf("wrote %s (%dx%d, %d spp, %llu rays, %.0f ms)\n", output.c_str(), opt.width,
                opt.height, opt.spp, static_cast<unsigned long long>(result.counters.totalRays()),
                result.renderMs);
    if (!a.heatmap.empty())
        std::printf("wrote %s (primitive tests per pixel, 0 = dark to %llu = bright)\n",
                    a.heatmap.c_str(),
                    static_cast<unsigned long long>(
                        *std::max_element(result.costPerPixel.begin(), result.costPerPixel.end())));
    if (!a.saveScene.empty())
        std::printf("wrote %s (the scene around %s) and %s (its mesh)\n", a.saveScene.c_str(),
                    a.scene.c_str(), meshPath.c_str());
    return 0;
}

}  // namespace raystep::cli
