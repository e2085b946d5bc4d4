// The acceleration options checked and turned into the core's AccelOptions and KernelOptions.
#include "accel_args.h"

#include "common.h"

#include "raystep/base/format.h"
#include "raystep/geometry/kernels.h"

#include <climits>
#include <cmath>

namespace raystep::cli {

void addAccelOptions(CLI::App* cmd, AccelArgs& a) {
    cmd->add_option("--accel", a.accel, "Accelerator: bruteforce, grid, kdtree or bvh")
        ->capture_default_str();
    cmd->add_option("--split", a.split, "kd-tree / BVH split: midpoint, median or sah")
        ->capture_default_str();
    cmd->add_option("--c-trav", a.cTrav, "Tree SAH: cost of a traversal step (default 1)")
        ->check(finiteNumber());
    cmd->add_option("--c-isect", a.cIsect, "Tree SAH: cost of a primitive test (default 5)")
        ->check(finiteNumber());
    cmd->add_option("--empty-bonus", a.emptyBonus,
                    "kd-tree SAH: discount for a split with an empty side, 0..1 (default 0.5)")
        ->check(finiteNumber());
    cmd->add_option("--max-depth", a.maxDepth,
                    "kd-tree: depth limit (default round(8 + 1.3 log2 N))")
        ->transform(wholeNumber(1, 60));
    cmd->add_option("--leaf-size", a.leafSize,
                    "Trees: this many primitives or fewer make a leaf (kd: SAH 1, else 4; BVH 4)")
        ->transform(wholeNumber(1, 1000000));
    cmd->add_option("--buckets", a.buckets, "BVH SAH: bins along the axis (default 12)")
        ->transform(wholeNumber(2, 256));
    cmd->add_option("--bin-above", a.binAbove,
                    "kd-tree SAH: nodes of more primitives pick among 256 bins per axis "
                    "(default: the exact event sweep everywhere)")
        ->transform(wholeNumber(1, INT_MAX));
    cmd->add_option(
           "--kd-build", a.kdBuild,
           "kd-tree SAH build: exact (every split event, perfect splits) or fast (16-32 bins "
           "per axis, all cores)")
        ->capture_default_str();
    cmd->add_option(
           "--grid-lambda", a.gridLambda,
           "Grid: cells per primitive, lambda N cells in all (Cleary-Wyvill rule); at most " +
               std::to_string(GridOptions::kMaxCells) + " cells")
        ->capture_default_str();
    cmd->add_option("--grid-res", a.gridRes, "Grid: cells per axis NX,NY,NZ instead of the rule");
    cmd->add_option("--mailbox", a.mailbox,
                    "Grid and kd-tree: test each primitive once per ray (on, off)")
        ->capture_default_str();
    cmd->add_option("--precision", a.precision, "Intersection arithmetic: float or double")
        ->capture_default_str();
    cmd->add_option("--triangle-method", a.triangleMethod,
                    "Ray-triangle test: plane, moller-trumbore or watertight")
        ->capture_default_str();
    cmd->add_option("--sphere-method", a.sphereMethod, "Ray-sphere test: textbook or stable")
        ->capture_default_str();
}

std::optional<std::string> resolveAccel(const AccelArgs& a, AccelChoice& out) {
    const auto kind = parseAccelKind(a.accel);
    if (!kind) return "--accel " + a.accel + ": expected bruteforce, grid, kdtree or bvh";
    out.kind = *kind;
    const auto precision = parsePrecision(a.precision);
    if (!precision) return "--precision " + a.precision + ": expected float or double";
    const auto triangle = parseTriangleMethod(a.triangleMethod);
    if (!triangle)
        return "--triangle-method " + a.triangleMethod +
               ": expected plane, moller-trumbore or watertight";
    const auto sphere = parseSphereMethod(a.sphereMethod);
    if (!sphere) return "--sphere-method " + a.sphereMethod + ": expected textbook or stable";
    out.kernels = {*precision, *sphere, *triangle};

    const auto split = parseSplitMethod(a.split);
    if (!split) return "--split " + a.split + ": expected midpoint, median or sah";
    AccelOptions& o = out.options;
    o.kdtree.split = o.bvh.split = *split;
    if (a.cTrav) {
        if (!std::isfinite(*a.cTrav) || *a.cTrav < 0)
            return "--c-trav " + formatNumber(*a.cTrav) + ": must be a finite number, 0 or more";
        o.kdtree.cTrav = o.bvh.cTrav = *a.cTrav;
    }
    if (a.cIsect) {
        if (!std::isfinite(*a.cIsect) || !(*a.cIsect > 0))
            return "--c-isect " + formatNumber(*a.cIsect) +
                   ": must be a finite number greater than 0";
        o.kdtree.cIsect = o.bvh.cIsect = *a.cIsect;
    }
    if (a.emptyBonus) {
        if (!(*a.emptyBonus >= 0 && *a.emptyBonus <= 1))
            return "--empty-bonus " + formatNumber(*a.emptyBonus) + ": must be from 0 to 1";
        o.kdtree.emptyBonus = *a.emptyBonus;
    }
    if (a.maxDepth) {
        if (*a.maxDepth < 1 || *a.maxDepth > 60)
            return "--max-depth " + std::to_string(*a.maxDepth) + ": must be from 1 to 60";
        o.kdtree.maxDepth = *a.maxDepth;
    }
    if (a.leafSize) {
        if (*a.leafSize < 1 || *a.leafSize > 1000000)
            return "--leaf-size " + std::to_string(*a.leafSize) + ": must be from 1 to 1000000";
        o.kdtree.leafSize = o.bvh.leafSize = *a.leafSize;
        o.bvh.maxLeafSize = std::max(o.bvh.maxLeafSize, *a.leafSize);
    }
    if (a.binAbove) {
        if (*a.binAbove < 1)
            return "--bin-above " + std::to_string(*a.binAbove) + ": must be 1 or more";
        o.kdtree.binAbove = *a.binAbove;
    }
    const auto kdBuild = parseKdBuild(a.kdBuild);
    if (!kdBuild) return "--kd-build " + a.kdBuild + ": expected exact or fast";
    o.kdtree.build = *kdBuild;
    if (o.kdtree.build == KdBuild::Fast && a.binAbove) {
        return std::string(
            "--bin-above and --kd-build fast: the fast build bins every node already");
    }
    if (a.buckets) {
        if (*a.buckets < 2 || *a.buckets > 256)
            return "--buckets " + std::to_string(*a.buckets) + ": must be from 2 to 256";
        o.bvh.buckets = *a.buckets;
    }
    if (!std::isfinite(a.gridLambda) || !(a.gridLambda > 0))
        return "--grid-lambda " + formatNumber(a.gridLambda) +
               ": must be a finite number greater than 0";
    o.grid.lambda = a.gridLambda;
    if (!a.gridRes.empty()) {
        const auto res = parseNumbers(a.gridRes);
        bool ok = res && res->size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i)
            ok = (*res)[i] == std::floor((*res)[i]) && (*res)[i] >= 1 &&
                 (*res)[i] <= GridOptions::kMaxCellsPerAxis;
        if (!ok)
            return "--grid-res " + a.gridRes + ": expected NX,NY,NZ, whole numbers from 1 to " +
                   std::to_string(GridOptions::kMaxCellsPerAxis);
        const double cells = (*res)[0] * (*res)[1] * (*res)[2];
        if (cells > double(GridOptions::kMaxCells))
            return "--grid-res " + a.gridRes + ": " +
                   std::to_string(static_cast<long long>(cells)) + " cells, more than the grid's " +
                   std::to_string(GridOptions::kMaxCells) + " (2^24)";
        o.grid.res = std::array<int, 3>{int((*res)[0]), int((*res)[1]), int((*res)[2])};
    }
    if (a.mailbox != "on" && a.mailbox != "off")
        return "--mailbox " + a.mailbox + ": expected on or off";
    o.grid.mailbox = o.kdtree.mailbox = a.mailbox == "on";
    return std::nullopt;
}

std::string describeAccel(const AccelChoice& c) {
    std::string s(accelKindName(c.kind));
    if (c.kind == AccelKind::KdTree || c.kind == AccelKind::Bvh)
        s += " " + std::string(name(c.options.kdtree.split));
    return s;
}

std::optional<std::string> checkKernelRange(const std::string& sceneName, const Scene& scene,
                                            const AccelChoice& choice) {
    if (choice.kernels.precision != Precision::Float) return std::nullopt;
    if (auto problem = kernelRangeProblem(Precision::Float, largestCoordinate(scene)))
        return sceneName + ": --precision float: " + *problem;
    if (auto problem =
            primitiveRangeProblem(Precision::Float, largestCoordinate(scene), smallestSize(scene)))
        return sceneName + ": --precision float: " + *problem;
    return std::nullopt;
}

}  // namespace raystep::cli
