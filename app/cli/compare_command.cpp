// `raystep-cli compare`: structures built and traced on the same rays, as a table or as JSON.
#include "compare_command.h"

#include "common.h"
#include "progress.h"
#include "tree_report.h"

#include "raystep/render/render.h"
#include "raystep/scene/model_import.h"
#include "raystep/scene/scene_loader.h"

#include <tbb/info.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

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
        "compare",
        "Structures side by side on one scene's rays: a tree's split methods (midpoint, median, "
        "SAH), or any set of kinds (--accel grid,kdtree,bvh[,bruteforce] [--split ...])");
    a.command = cmd;
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
        ->transform(wholeNumber(0, kMaxBounces));
    cmd->add_option("--spp", a.spp, "Samples per pixel (default: the scene's)")
        ->transform(wholeNumber(1, kMaxSpp));
    cmd->add_option("--diffuse-samples", a.diffuseSamples,
                    "Diffuse bounce rays at the first diffuse hit (default: the scene's)")
        ->transform(wholeNumber(0, kMaxDiffuseSamples));
    cmd->add_option("--threads", a.threads, "Threads (default: all cores)")
        ->transform(wholeNumber(1, 1024));
    cmd->add_flag("--json", a.json, "Print the table as JSON");
}

int runCompare(const CompareArgs& a) {
    setCurrentInput(a.scene);
    // The split methods asked for, or none: a single tree then shows all of its own.
    const bool splitGiven = a.command && a.command->count("--split") > 0;
    const auto asked = parseStructureChoices(
        a.accel.accel, splitGiven ? std::optional<std::string_view>(a.accel.split) : std::nullopt);
    if (const auto* problem = std::get_if<std::string>(&asked)) return fail(*problem);
    const auto& rows = std::get<std::vector<StructureChoice>>(asked);
    // Every other option checked once, as render checks it (the first kind stands for all).
    AccelArgs first = a.accel;
    first.accel = std::string(accelKindName(rows.front().kind));
    first.split = "sah";
    AccelChoice base;
    if (auto problem = resolveAccel(first, base)) return fail(*problem);
    int code = 0;
    const auto scene = loadOrFail(a.scene, code);
    if (!scene) return code;
    if (auto problem = checkKernelRange(a.scene, *scene, base)) return fail(*problem);
    // The rays render traces with the same options (render --stats counts the same tests).
    RenderOptions opt;
    opt.width = a.width;
    opt.height = a.height;
    opt.spp = a.spp.value_or(scene->settings.spp);
    opt.trace.bounces = a.bounces.value_or(scene->settings.bounces);
    opt.trace.diffuseSamples = a.diffuseSamples.value_or(scene->settings.diffuseSamples);
    opt.threads = threadCount(a.threads);

    nlohmann::ordered_json results = nlohmann::ordered_json::array();
    for (const StructureChoice& asked : rows) {
        AccelChoice c = base;
        c.kind = asked.kind;
        if (asked.split) c.options.setSplit(*asked.split);
        ProgressBar buildBar("build " + describeAccel(c));
        c.options.setProgress([&](double f) { return buildBar.update(f); });
        const Accelerator accel = buildAccelerator(*scene, c.kind, c.kernels, c.options);
        buildBar.finish();
        BuildSummary b = summarize(accel);
        ProgressBar bar("trace " + describeAccel(c));
        const RenderResult r = render(*scene, accel, opt, [&](double f) { return bar.update(f); });
        bar.finish();
        const RayCounters& n = r.counters;
        const double rays = std::max<double>(1.0, n.totalRays());
        nlohmann::ordered_json row;
        row["accel"] = describeAccel(c);  // as render --stats names it
        row["kind"] = accelKindName(c.kind);
        row["split"] = asked.split ? nlohmann::ordered_json(name(*asked.split)) : nullptr;
        const nlohmann::ordered_json built = statsJson(b);  // kept: items() refers to it
        for (const auto& [key, value] : built.items()) row[key] = value;
        // Only a tree has a SAH cost of its own.
        if (!hasSplit(c.kind)) row["sah_cost"] = nullptr;
        for (int k = 0; k < kRayKindCount; ++k)
            row["rays"][std::string(kRayKindNames[k])] = n.rays[k];
        row["rays"]["total"] = n.totalRays();
        row["primitive_tests"] = n.traversal.primitiveTests;
        row["node_visits"] = n.traversal.nodeVisits;
        row["mailbox_skips"] = n.traversal.mailboxSkips;
        row["primitive_tests_per_ray"] = n.traversal.primitiveTests / rays;
        row["node_visits_per_ray"] = n.traversal.nodeVisits / rays;
        row["mailbox_skips_per_ray"] = n.traversal.mailboxSkips / rays;
        row["render_ms"] = r.renderMs;
        row["mrays_per_s"] = rays / (r.renderMs * 1e3);
        results.push_back(row);
    }
    if (a.json) {
        nlohmann::ordered_json j;
        j["scene"] = scene->name;
        j["primitives"] = scene->primitiveCount();
        j["image"] = {opt.width, opt.height};
        j["spp"] = opt.spp;
        j["bounces"] = opt.trace.bounces;
        j["diffuse_samples"] = opt.trace.diffuseSamples;
        j["threads"] = opt.threads;
        j["results"] = results;
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }
    std::printf("%s, %u primitives, %dx%d, %d spp, %d bounces, %d threads\n", scene->name.c_str(),
                scene->primitiveCount(), opt.width, opt.height, opt.spp, opt.trace.bounces,
                opt.threads);
    // A grid's nodes are its cells, and what it visits per ray are cells.
    std::printf("%-18s %9s %9s %6s %9s %10s %10s %12s %11s %9s\n", "structure", "build ms", "nodes",
                "depth", "SAH cost", "refs/prim", "tests/ray", "visits/ray", "skips/ray",
                "Mrays/s");
    const double prims = std::max(1u, scene->primitiveCount());
    for (const auto& row : results) {
        char sah[32] = "-";
        if (!row["sah_cost"].is_null())
            std::snprintf(sah, sizeof sah, "%.4g", row["sah_cost"].get<double>());
        std::printf("%-18s %9.1f %9u %6u %9s %10.2f %10.2f %12.2f %11.2f %9.3f\n",
                    row["structure"].get<std::string>().c_str(), row["build_ms"].get<double>(),
                    row["nodes"].get<unsigned>(), row["max_depth"].get<unsigned>(), sah,
                    row["references"].get<double>() / prims,
                    row["primitive_tests_per_ray"].get<double>(),
                    row["node_visits_per_ray"].get<double>(),
                    row["mailbox_skips_per_ray"].get<double>(), row["mrays_per_s"].get<double>());
    }
    return 0;
}

}  // namespace raystep::cli
