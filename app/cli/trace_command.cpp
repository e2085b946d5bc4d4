// `raystep-cli trace`: one pixel or one 2D ray traced with every event recorded and written.
#include "trace_command.h"

#include "common.h"

#include "raystep/geometry/kernels.h"
#include "raystep/render/tracer.h"
#include "raystep/scene/model_import.h"
#include "raystep/scene/scene_loader.h"
#include "raystep/trace/trace_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <variant>

namespace raystep::cli {

void addTraceCommand(CLI::App& app, TraceArgs& a) {
    CLI::App* cmd =
        app.add_subcommand("trace", "Record every event of one pixel's ray tree to a trace file");
    cmd->add_option(
        "scene", a.scene,
        "Built-in scene name, scene file, or model (.obj .ply .stl .gltf .glb, with the "
        "scene render puts around it, traced with a kd-tree unless --accel says; "
        "default: default)");
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
        ->transform(wholeNumber(0, kMaxBounces));
    cmd->add_option("--spp", a.spp, "Samples per pixel")->transform(wholeNumber(1, kMaxSpp));
    cmd->add_option("--diffuse-samples", a.diffuseSamples, "Diffuse bounce rays")
        ->transform(wholeNumber(0, kMaxDiffuseSamples));
    cmd->add_option("--seed", a.seed, "Seed of the random numbers")
        ->transform(wholeNumber(0, UINT64_MAX))
        ->capture_default_str();
    addAccelOptions(cmd, a.accel);
    a.accelOption = cmd->get_option("--accel");
    addMaxEventsOption(cmd, a.maxEvents);
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
    setCurrentInput(a.scene);
    AccelChoice choice;
    // A model is a big mesh more often than not: a kd-tree (SAH) unless --accel says otherwise
    // (as render does; brute force would record a test of every triangle).
    AccelArgs accelArgs = a.accel;
    if (isModelPath(a.scene) && !(a.accelOption && a.accelOption->count() > 0))
        accelArgs.accel = "kdtree";
    if (auto problem = resolveAccel(accelArgs, choice)) return fail(*problem);
    if (auto problem = checkOutputs({{"-o", a.output}}, inputsOf(a.scene))) return fail(*problem);
    std::variant<Scene, Scene2D> any;
    try {
        any = loadInput(a.scene);
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

}  // namespace raystep::cli
