#include "tree_commands.h"

#include "common.h"
#include "progress.h"

#include "raystep/render/image.h"
#include "raystep/geometry/kernels.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"
#include "raystep/render/tracer.h"

#include <tbb/info.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace raystep::cli {

namespace {

std::optional<Scene> loadOrFail(const std::string& name, int& code) {
    try {
        return loadScene(name);
    } catch (const SceneError& e) {
        code = fail(e.what());
        return std::nullopt;
    }
}

struct SceneInfo {
    std::string name;
    unsigned dimensions;
    unsigned primitives;
};
SceneInfo infoOf(const std::variant<Scene, Scene2D>& any) {
    return std::visit(
        [](const auto& s) {
            const unsigned dims = std::is_same_v<std::decay_t<decltype(s)>, Scene2D> ? 2 : 3;
            return SceneInfo{s.name, dims, s.primitiveCount()};
        },
        any);
}

nlohmann::ordered_json statsJson(const BuildSummary& b) {
    const TreeStats& s = b.stats;
    nlohmann::ordered_json reasons;
    for (std::size_t i = 0; i < kLeafReasonNames.size(); ++i)
        reasons[std::string(kLeafReasonNames[i])] = s.leafReasons[i];
    return {
        {"structure", b.description},    {"nodes", s.nodes},        {"leaves", s.leaves},
        {"empty_leaves", s.emptyLeaves}, {"max_depth", s.maxDepth}, {"references", s.references},
        {"sah_cost", s.sahCost},         {"build_ms", s.buildMs},   {"leaf_reasons", reasons}};
}

void addCapOption(CLI::App* cmd, std::size_t& cap) {
    cmd->add_option("--max-events", cap, "Stop recording after this many events")
        ->transform(wholeNumber(1, 20'000'000))
        ->capture_default_str();
}

}  // namespace

void addBuildCommand(CLI::App& app, BuildArgs& a) {
    CLI::App* cmd = app.add_subcommand("build", "Build an acceleration structure and report it");
    cmd->add_option("scene", a.scene, "Built-in scene name or scene file (default: default)");
    a.accel.accel = "kdtree";
    addAccelOptions(cmd, a.accel);
    cmd->add_flag("--json", a.json, "Print the report as JSON");
    cmd->add_option("--events", a.events,
                    "Write the build's events (nodes, split candidates, leaves) as a trace file")
        ->check(fileName());
    addCapOption(cmd, a.maxEvents);
}

int runBuild(const BuildArgs& a) {
    AccelChoice choice;
    if (auto problem = resolveAccel(a.accel, choice)) return fail(*problem);
    if (auto problem = checkOutputs({{"--events", a.events}}, {a.scene})) return fail(*problem);
    std::variant<Scene, Scene2D> any;
    try {
        any = loadAnyScene(a.scene);
    } catch (const SceneError& e) {
        return fail(e.what());
    }
    EventLog log(a.maxEvents);
    EventLog* record = a.events.empty() ? nullptr : &log;
    BuildSummary summary;
    ProgressBar bar("build " + describeAccel(choice));
    choice.options.setProgress([&](double f) { return bar.update(f); });
    if (const auto* s3 = std::get_if<Scene>(&any))
        if (auto problem = checkKernelRange(a.scene, *s3, choice)) return fail(*problem);
    const SceneInfo scene = infoOf(any);
    if (const auto* s2 = std::get_if<Scene2D>(&any)) {
        summary = summarize(buildAccelerator2D(*s2, choice.kind, choice.options, record));
    } else {
        const Scene& s3 = std::get<Scene>(any);
        summary = summarize(
            record ? buildAccelerator(s3, choice.kind, choice.kernels, choice.options, log)
                   : buildAccelerator(s3, choice.kind, choice.kernels, choice.options));
    }
    bar.finish();
    if (choice.kind != AccelKind::Grid) summary.description = describeAccel(choice);
    if (!a.events.empty()) {
        TraceInfo info;
        info.what = "build";
        info.scene = scene.name;
        info.accel = summary.description;
        if (auto problem = writeOutputs({{a.events, traceToJson(log, info)}}))
            return fail(*problem);
        if (log.truncated()) std::cerr << "raystep-cli: warning: " << capMessage(log) << "\n";
    }
    if (a.json) {
        nlohmann::ordered_json j = statsJson(summary);
        j["scene"] = scene.name;
        j["dimensions"] = scene.dimensions;
        j["primitives"] = scene.primitives;
        if (!a.events.empty()) j["events"] = log.events().size();
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }
    const TreeStats& s = summary.stats;
    const double n = std::max(1u, scene.primitives);
    std::printf("%s on %s (%uD, %u primitives)\n", summary.description.c_str(), scene.name.c_str(),
                scene.dimensions, scene.primitives);
    std::printf("  nodes         %u\n  leaves        %u (%u empty)\n  max depth     %u\n", s.nodes,
                s.leaves, s.emptyLeaves, s.maxDepth);
    std::printf("  references    %llu (%.2f per primitive)\n",
                static_cast<unsigned long long>(s.references), s.references / n);
    std::printf("  SAH cost      %.4g\n  build         %.1f ms\n", s.sahCost, s.buildMs);
    if (choice.kind == AccelKind::KdTree || choice.kind == AccelKind::Bvh) {
        std::printf("  leaves made:");
        for (std::size_t i = 0; i < kLeafReasonNames.size(); ++i)
            if (s.leafReasons[i])
                std::printf(" %s %u", kLeafReasonNames[i].data(), s.leafReasons[i]);
        std::printf("\n");
    }
    if (!a.events.empty())
        std::printf("wrote %s (%zu events)\n", a.events.c_str(), log.events().size());
    return 0;
}

void addTraceCommand(CLI::App& app, TraceArgs& a) {
    CLI::App* cmd =
        app.add_subcommand("trace", "Record every event of one pixel's ray tree to a trace file");
    cmd->add_option("scene", a.scene, "Built-in scene name or scene file (default: default)");
    cmd->add_option("--pixel", a.pixel, "3D scenes: the pixel X,Y (0,0 is the top left)");
    cmd->add_option("--ray", a.ray,
                    "2D scenes: the ray OX,OY,DX,DY (default: the scene's example ray)");
    cmd->add_option("-o,--output", a.output, "Trace file to write (JSON)")
        ->required()
        ->check(fileName());
    cmd->add_option("--width", a.width, "Image width in pixels")
        ->transform(wholeNumber(1, kMaxImageSide));
    cmd->add_option("--height", a.height, "Image height in pixels")
        ->transform(wholeNumber(1, kMaxImageSide));
    cmd->add_option("--bounces", a.bounces, "Depth of secondary rays")
        ->transform(wholeNumber(0, 64));
    cmd->add_option("--spp", a.spp, "Samples per pixel")->transform(wholeNumber(1, 4096));
    cmd->add_option("--diffuse-samples", a.diffuseSamples, "Diffuse bounce rays")
        ->transform(wholeNumber(0, 1024));
    cmd->add_option("--seed", a.seed, "Seed of the random numbers")
        ->transform(wholeNumber(0, UINT64_MAX))
        ->capture_default_str();
    addAccelOptions(cmd, a.accel);
    addCapOption(cmd, a.maxEvents);
}

namespace {
/// A 2D scene's ray through its structure, every event recorded.
int trace2D(const TraceArgs& a, const AccelChoice& choice, const Scene2D& scene) {
    Ray2 ray;
    if (!a.ray.empty()) {
        const auto v = parseNumbers(a.ray);
        if (!v || v->size() != 4 || ((*v)[2] == 0 && (*v)[3] == 0))
            return fail("--ray " + a.ray + ": expected OX,OY,DX,DY with a non-zero direction");
        ray = Ray2{Vec2((*v)[0], (*v)[1]), Vec2((*v)[2], (*v)[3])};
        if (auto problem = rayRangeProblem(Precision::Double,
                                           std::max(std::abs(ray.origin.x), std::abs(ray.origin.y)),
                                           std::max(std::abs(ray.dir.x), std::abs(ray.dir.y))))
            return fail("--ray " + a.ray + ": " + *problem);
    } else if (scene.exampleRay) {
        ray = *scene.exampleRay;
    } else {
        return fail(scene.name + ": the scene has no example ray; give one with --ray");
    }
    const Accelerator2D accel = buildAccelerator2D(scene, choice.kind, choice.options);
    EventLog log(a.maxEvents);
    TraversalCounters counters;
    const auto hit = traceRay2D(accel, ray, log, &counters);
    TraceInfo info;
    info.what = "ray";
    info.scene = scene.name;
    info.accel = summarize(accel).description;
    if (auto problem = writeOutputs({{a.output, traceToJson(log, info)}})) return fail(*problem);
    if (log.truncated()) std::cerr << "raystep-cli: warning: " << capMessage(log) << "\n";
    if (hit)
        std::printf("ray (%g, %g) + t (%g, %g): hits primitive %u at t = %.17g\n", ray.origin.x,
                    ray.origin.y, ray.dir.x, ray.dir.y, hit->prim, hit->t);
    else
        std::printf("ray (%g, %g) + t (%g, %g): misses everything\n", ray.origin.x, ray.origin.y,
                    ray.dir.x, ray.dir.y);
    std::printf("  primitive tests %llu, cells or nodes visited %llu, mailbox skips %llu\n",
                static_cast<unsigned long long>(counters.primitiveTests),
                static_cast<unsigned long long>(counters.nodeVisits),
                static_cast<unsigned long long>(counters.mailboxSkips));
    std::printf("wrote %s (%zu events)\n", a.output.c_str(), log.events().size());
    return 0;
}
}  // namespace

int runTrace(const TraceArgs& a) {
    AccelChoice choice;
    if (auto problem = resolveAccel(a.accel, choice)) return fail(*problem);
    if (auto problem = checkOutputs({{"-o", a.output}}, {a.scene})) return fail(*problem);
    std::variant<Scene, Scene2D> any;
    try {
        any = loadAnyScene(a.scene);
    } catch (const SceneError& e) {
        return fail(e.what());
    }
    if (const auto* s2 = std::get_if<Scene2D>(&any)) return trace2D(a, choice, *s2);
    if (auto problem = checkKernelRange(a.scene, std::get<Scene>(any), choice))
        return fail(*problem);
    if (a.pixel.empty()) return fail("--pixel X,Y is required for a 3D scene");
    const auto xy = parseNumbers(a.pixel);
    if (!xy || xy->size() != 2 || (*xy)[0] != std::floor((*xy)[0]) ||
        (*xy)[1] != std::floor((*xy)[1]) || (*xy)[0] < 0 || (*xy)[1] < 0)
        return fail("--pixel " + a.pixel + ": expected X,Y, two whole numbers 0 or more");
    const Scene* scene = &std::get<Scene>(any);
    RenderOptions opt;
    opt.width = a.width.value_or(scene->settings.width);
    opt.height = a.height.value_or(scene->settings.height);
    opt.spp = a.spp.value_or(scene->settings.spp);
    opt.trace.bounces = a.bounces.value_or(scene->settings.bounces);
    opt.trace.diffuseSamples = a.diffuseSamples.value_or(scene->settings.diffuseSamples);
    opt.seed = a.seed;
    // Compared as doubles: a cast of 2^31 or more to int is undefined (it wrapped to -2^31).
    if ((*xy)[0] >= opt.width || (*xy)[1] >= opt.height)
        return fail("--pixel " + a.pixel + ": outside the " + std::to_string(opt.width) + "x" +
                    std::to_string(opt.height) + " image");
    const int x = static_cast<int>((*xy)[0]), y = static_cast<int>((*xy)[1]);

    const Accelerator accel = buildAccelerator(*scene, choice.kind, choice.kernels, choice.options);
    const Tracer tracer(*scene, accel, opt.trace);
    EventLog log(a.maxEvents);
    RayCounters counters;
    const Color c = tracer.renderPixel(x, y, opt, counters, log);
    TraceInfo info;
    info.what = "pixel";
    info.scene = scene->name;
    info.accel = describeAccel(choice);
    info.pixelX = x;
    info.pixelY = y;
    info.width = opt.width;
    info.height = opt.height;
    if (auto problem = writeOutputs({{a.output, traceToJson(log, info)}})) return fail(*problem);
    if (log.truncated()) std::cerr << "raystep-cli: warning: " << capMessage(log) << "\n";
    std::printf("pixel (%d, %d) of %dx%d: colour (%.4f, %.4f, %.4f)\n", x, y, opt.width, opt.height,
                c.x, c.y, c.z);
    std::printf("  rays:");
    for (int k = 0; k < kRayKindCount; ++k)
        if (counters.rays[k])
            std::printf(" %s %llu", kRayKindNames[k].data(),
                        static_cast<unsigned long long>(counters.rays[k]));
    std::printf("\n  primitive tests %llu, node visits %llu, mailbox skips %llu\n",
                static_cast<unsigned long long>(counters.traversal.primitiveTests),
                static_cast<unsigned long long>(counters.traversal.nodeVisits),
                static_cast<unsigned long long>(counters.traversal.mailboxSkips));
    std::printf("wrote %s (%zu events, %zu rays)\n", a.output.c_str(), log.events().size(),
                log.rays().size());
    return 0;
}

void addCompareCommand(CLI::App& app, CompareArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "compare", "Midpoint against median against SAH on one scene: build and trace each");
    cmd->add_option("scene", a.scene, "Built-in scene name or scene file (default: default)");
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
    AccelChoice base;
    if (auto problem = resolveAccel(a.accel, base)) return fail(*problem);
    if (base.kind != AccelKind::KdTree && base.kind != AccelKind::Bvh)
        return fail("--accel " + a.accel.accel + ": compare takes kdtree or bvh");
    int code = 0;
    const auto scene = loadOrFail(a.scene, code);
    if (!scene) return code;
    if (auto problem = checkKernelRange(a.scene, *scene, base)) return fail(*problem);
    RenderOptions opt;
    opt.width = a.width;
    opt.height = a.height;
    opt.trace.bounces = a.bounces.value_or(scene->settings.bounces);
    opt.threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();

    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (SplitMethod split : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
        AccelChoice c = base;
        c.options.kdtree.split = c.options.bvh.split = split;
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
