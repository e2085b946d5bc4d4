// `raystep-cli compare`: the three split rules built and traced, as a table or as JSON.
#include "compare_command.h"

#include "common.h"
#include "progress.h"
#include "tree_report.h"

#include "raystep/render/tracer.h"
#include "raystep/scene/model_import.h"
#include "raystep/scene/scene_loader.h"

#include <tbb/info.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace raystep::cli {

namespace {

std::optional<Scene> loadOrFail(const std::string& name, int& code) {
    try {
        // A scene file through loadScene: a 2D one is refused there with its line.
        if (isModelPath(name)) return std::get<Scene>(loadInput(name));
        return loadScene(name);
    } catch (const SceneError& e) {
        code = fail(e.what());
        return std::nullopt;
    }
}

}  // namespace

void addCompareCommand(CLI::App& app, CompareArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "compare", "Midpoint against median against SAH on one scene: build and trace each");
    cmd->add_option(
        "scene", a.scene,
        "Built-in scene name, scene file, or model (.obj .ply .stl .gltf .glb, with the "
        "scene render puts around it; default: default)");
    a.accel.accel = "kdtree";
    addAccelOptions(cmd, a.accel);
    cmd->add_option("--width", a.width, "Image width of the rays traced")
        ->transform(wholeNumber(1, kMaxImageSide))
        ->capture_default_str();
    cmd->add_option("--height", a.height, "Image height of the rays traced")
        ->transform(wholeNumber(1, kMaxImageSide))
        ->capture_default_str();
    cmd->add_option("--bounces", a.bounces, "Depth of secondary rays (default: the scene's)")
        ->transform(wholeNumber(0, 64));
    cmd->add_option("--threads", a.threads, "Threads (default: all cores)")
        ->transform(wholeNumber(1, 1024));
    cmd->add_flag("--json", a.json, "Print the table as JSON");
}

int runCompare(const CompareArgs& a) {
    setCurrentInput(a.scene);
    AccelChoice base;
    if (auto problem = resolveAccel(a.accel, base)) return fail(*problem);
    // The split methods are compared: a structure without them has nothing to compare.
    if (!hasSplit(base.kind))
        return fail("--accel " + a.accel.accel + ": compare takes " + kindList(hasSplit));
    int code = 0;
    const auto scene = loadOrFail(a.scene, code);
    if (!scene) return code;
    if (auto problem = checkKernelRange(a.scene, *scene, base)) return fail(*problem);
    RenderOptions opt;
    opt.width = a.width;
    opt.height = a.height;
    opt.trace.bounces = a.bounces.value_or(scene->settings.bounces);
    opt.threads = threadCount(a.threads);

    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const SplitMethod split : structureInfo(base.kind).splits) {
        AccelChoice c = base;
        c.options.setSplit(split);
        ProgressBar buildBar("build " + describeAccel(c));
        c.options.setProgress([&](double f) { return buildBar.update(f); });
        const Accelerator accel = buildAccelerator(*scene, c.kind, c.kernels, c.options);
        buildBar.finish();
        BuildSummary b = summarize(accel);
        b.description = describeAccel(c);
        ProgressBar bar("trace " + b.description);
        const RenderResult r = render(*scene, accel, opt, [&](double f) { return bar.update(f); });
        bar.finish();
        const double rays = std::max<double>(1.0, r.counters.totalRays());
        nlohmann::ordered_json row = statsJson(b);
        row["rays"] = r.counters.totalRays();
        row["primitive_tests_per_ray"] = r.counters.traversal.primitiveTests / rays;
        row["node_visits_per_ray"] = r.counters.traversal.nodeVisits / rays;
        row["mailbox_skips_per_ray"] = r.counters.traversal.mailboxSkips / rays;
        row["render_ms"] = r.renderMs;
        row["mrays_per_s"] = rays / (r.renderMs * 1e3);
        rows.push_back(row);
    }
    if (a.json) {
        nlohmann::ordered_json j;
        j["scene"] = scene->name;
        j["primitives"] = scene->primitiveCount();
        j["image"] = {opt.width, opt.height};
        j["bounces"] = opt.trace.bounces;
        j["threads"] = opt.threads;
        j["results"] = rows;
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }
    std::printf("%s, %u primitives, %dx%d, %d bounces, %d threads\n", scene->name.c_str(),
                scene->primitiveCount(), opt.width, opt.height, opt.trace.bounces, opt.threads);
    std::printf("%-16s %9s %8s %6s %9s %10s %12s %12s %9s\n", "structure", "build ms", "nodes",
                "depth", "SAH cost", "refs/prim", "tests/ray", "visits/ray", "Mrays/s");
    const double n = std::max(1u, scene->primitiveCount());
    for (const auto& row : rows)
        std::printf("%-16s %9.1f %8u %6u %9.4g %10.2f %12.2f %12.2f %9.3f\n",
                    row["structure"].get<std::string>().c_str(), row["build_ms"].get<double>(),
                    row["nodes"].get<unsigned>(), row["max_depth"].get<unsigned>(),
                    row["sah_cost"].get<double>(), row["references"].get<double>() / n,
                    row["primitive_tests_per_ray"].get<double>(),
                    row["node_visits_per_ray"].get<double>(), row["mrays_per_s"].get<double>());
    return 0;
}

}  // namespace raystep::cli
