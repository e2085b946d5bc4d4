// `raystep-cli build`: one structure built and reported, its events written on request.
#include "build_command.h"

#include "common.h"
#include "progress.h"
#include "tree_report.h"

#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <type_traits>
#include <variant>

namespace raystep::cli {

namespace {

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

}  // namespace

void addBuildCommand(CLI::App& app, BuildArgs& a) {
    CLI::App* cmd = app.add_subcommand("build", "Build an acceleration structure and report it");
    cmd->add_option(
        "scene", a.scene,
        "Built-in scene name, scene file, or model (.obj .ply .stl .gltf .glb, with the "
        "scene render puts around it; default: default)");
    a.accel.accel = "kdtree";
    addAccelOptions(cmd, a.accel);
    cmd->add_flag("--json", a.json, "Print the report as JSON");
    cmd->add_option("--events", a.events,
                    "Write the build's events (nodes, split candidates, leaves) as a trace file")
        ->check(fileName());
    addMaxEventsOption(cmd, a.maxEvents);
}

int runBuild(const BuildArgs& a) {
    setCurrentInput(a.scene);
    AccelChoice choice;
    if (auto problem = resolveAccel(a.accel, choice)) return fail(*problem);
    if (auto problem = checkOutputs({{"--events", a.events}}, inputsOf(a.scene)))
        return fail(*problem);
    std::variant<Scene, Scene2D> any;
    try {
        any = loadInput(a.scene);
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
    const AnyStructure built =
        buildStructure(any, choice.kind, choice.kernels, choice.options, record);
    summary = built.in2D ? summarize(*built.in2D) : summarize(*built.in3D);
    bar.finish();
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
    if (hasSplit(choice.kind)) {  // a tree: why each leaf was made
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

}  // namespace raystep::cli
