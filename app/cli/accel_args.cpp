// The acceleration options checked and turned into the core's AccelOptions and KernelOptions.
#include "accel_args.h"

#include "common.h"

#include "raystep/base/format.h"
#include "raystep/geometry/kernels.h"

#include <climits>
#include <cmath>

namespace raystep::cli {

namespace {
using O = AccelOption;

std::string doc(AccelOption o) {
    return std::string(optionInfo(o).doc);
}
/// A whole-number option's range from the table, checked by CLI11 before conversion.
CLI::Validator wholeIn(AccelOption o) {
    const OptionInfo& info = optionInfo(o);
    return wholeNumber(static_cast<std::uint64_t>(info.lo), static_cast<std::uint64_t>(info.hi));
}
/// The table's check, in the CLI's words: "--max-depth 61: must be from 1 to 60".
std::optional<std::string> problem(AccelOption o, double v) {
    if (auto why = optionProblem(o, v)) {
        const bool whole = v == std::floor(v) && std::abs(v) < 1e15;
        return cliFlag(o) + " " +
               (whole ? std::to_string(static_cast<long long>(v)) : formatNumber(v)) + ": " + *why;
    }
    return std::nullopt;
}
}  // namespace

void addAccelOptions(CLI::App* cmd, AccelArgs& a) {
    cmd->add_option("--accel", a.accel, "Accelerator: " + kindList())->capture_default_str();
    cmd->add_option(cliFlag(O::Split), a.split, doc(O::Split))->capture_default_str();
    cmd->add_option(cliFlag(O::CTrav), a.cTrav, doc(O::CTrav))->check(finiteNumber());
    cmd->add_option(cliFlag(O::CIsect), a.cIsect, doc(O::CIsect))->check(finiteNumber());
    cmd->add_option(cliFlag(O::EmptyBonus), a.emptyBonus, doc(O::EmptyBonus))
        ->check(finiteNumber());
    cmd->add_option(cliFlag(O::MaxDepth), a.maxDepth, doc(O::MaxDepth))
        ->transform(wholeIn(O::MaxDepth));
    cmd->add_option(cliFlag(O::LeafSize), a.leafSize, doc(O::LeafSize))
        ->transform(wholeIn(O::LeafSize));
    cmd->add_option(cliFlag(O::Buckets), a.buckets, doc(O::Buckets))
        ->transform(wholeIn(O::Buckets));
    cmd->add_option(cliFlag(O::BinAbove), a.binAbove, doc(O::BinAbove))
        ->transform(wholeIn(O::BinAbove));
    cmd->add_option(cliFlag(O::KdBuild), a.kdBuild, doc(O::KdBuild))->capture_default_str();
    cmd->add_option(
           cliFlag(O::GridLambda), a.gridLambda,
           doc(O::GridLambda) + "; at most " + std::to_string(GridOptions::kMaxCells) + " cells")
        ->capture_default_str();
    cmd->add_option(cliFlag(O::GridRes), a.gridRes, doc(O::GridRes));
    cmd->add_option(cliFlag(O::Mailbox), a.mailbox, doc(O::Mailbox))->capture_default_str();
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
    if (!kind) return "--accel " + a.accel + ": expected " + kindList();
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
    o.setSplit(*split);
    // The numbers, each checked against the table's limits and set where it is read.
    const std::pair<AccelOption, std::optional<double>> numbers[] = {
        {O::CTrav, a.cTrav},       {O::CIsect, a.cIsect},        {O::EmptyBonus, a.emptyBonus},
        {O::MaxDepth, a.maxDepth}, {O::LeafSize, a.leafSize},    {O::BinAbove, a.binAbove},
        {O::Buckets, a.buckets},   {O::GridLambda, a.gridLambda}};
    for (const auto& [option, value] : numbers) {
        if (!value) continue;
        if (auto p = problem(option, *value)) return p;
        o.set(option, *value);
    }
    const auto kdBuild = parseKdBuild(a.kdBuild);
    if (!kdBuild) return "--kd-build " + a.kdBuild + ": expected exact or fast";
    o.kdtree.build = *kdBuild;
    if (o.kdtree.build == KdBuild::Fast && a.binAbove) {
        return std::string(
            "--bin-above and --kd-build fast: the fast build bins every node already");
    }
    if (!a.gridRes.empty()) {
        const auto res = parseNumbers(a.gridRes);
        bool ok = res && res->size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i) ok = !optionProblem(O::GridRes, (*res)[i]);
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
    o.set(O::Mailbox, a.mailbox == "on");
    return std::nullopt;
}

std::string describeAccel(const AccelChoice& c) {
    std::string s(accelKindName(c.kind));
    if (const auto split = c.options.split(c.kind)) s += " " + std::string(name(*split));
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
