// The table of structures and options: names both ways, the lists messages print, the limits
// every reader checks, the defaults against the options' own (written here by hand), and the
// options reaching the build they are said to steer.
#include "raystep/accel/accel.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace raystep {
namespace {

TEST(StructureInfo, NamesReadBothWays) {
    const std::pair<AccelKind, const char*> names[] = {{AccelKind::BruteForce, "bruteforce"},
                                                       {AccelKind::Grid, "grid"},
                                                       {AccelKind::KdTree, "kdtree"},
                                                       {AccelKind::Bvh, "bvh"}};
    ASSERT_EQ(structures().size(), std::size(names));
    ASSERT_EQ(structures().size(), std::variant_size_v<Accelerator2D>);
    for (const auto& [kind, name] : names) {
        EXPECT_EQ(accelKindName(kind), name);
        EXPECT_EQ(parseAccelKind(name), kind);
        EXPECT_EQ(structureInfo(kind).kind, kind);
    }
    EXPECT_FALSE(parseAccelKind("octree"));
    EXPECT_FALSE(parseAccelKind("KdTree"));
}

TEST(StructureInfo, KindListsForMessages) {
    EXPECT_EQ(kindList(), "bruteforce, grid, kdtree or bvh");
    EXPECT_EQ(kindList(hasSplit), "kdtree or bvh");
    EXPECT_EQ(kindList(recordsBuild), "kdtree or bvh");
    EXPECT_EQ(kindList([](AccelKind k) { return k == AccelKind::Grid; }), "grid");
}

TEST(StructureInfo, WhatEachStructureIs) {
    EXPECT_EQ(structureInfo(AccelKind::Bvh).subdivides, Subdivides::Primitives);
    EXPECT_EQ(structureInfo(AccelKind::KdTree).subdivides, Subdivides::Space);
    EXPECT_EQ(structureInfo(AccelKind::Grid).subdivides, Subdivides::Space);
    EXPECT_EQ(structureInfo(AccelKind::BruteForce).subdivides, Subdivides::Nothing);
    EXPECT_FALSE(hasSplit(AccelKind::Grid));
    EXPECT_FALSE(hasSplit(AccelKind::BruteForce));
    EXPECT_EQ(structureInfo(AccelKind::KdTree).splits.size(), 3u);
    EXPECT_EQ(structureInfo(AccelKind::Bvh).splits.size(), 3u);
    EXPECT_FALSE(recordsBuild(AccelKind::Grid));
    EXPECT_TRUE(recordsBuild(AccelKind::Bvh));
}

TEST(StructureInfo, LabelsInBothLanguages) {
    // i18n/it/gui.json: griglia, forza bruta; kd-tree and BVH are the same words in Italian.
    EXPECT_EQ(structureLabel(AccelKind::KdTree), "kd-tree");
    EXPECT_EQ(structureLabel(AccelKind::BruteForce), "brute force");
    EXPECT_EQ(structureLabel(AccelKind::Grid, Language::It), "griglia");
    EXPECT_EQ(structureLabel(AccelKind::BruteForce, Language::It), "forza bruta");
    EXPECT_EQ(structureLabel(AccelKind::Bvh, Language::It), "BVH");
}

TEST(StructureInfo, WhichStructureReadsWhichOption) {
    using O = AccelOption;
    EXPECT_TRUE(readsOption(AccelKind::Grid, O::Mailbox));
    EXPECT_TRUE(readsOption(AccelKind::KdTree, O::Mailbox));
    EXPECT_FALSE(readsOption(AccelKind::Bvh, O::Mailbox));  // a BVH lists a primitive once
    EXPECT_TRUE(readsOption(AccelKind::KdTree, O::MaxDepth));
    EXPECT_FALSE(readsOption(AccelKind::Bvh, O::MaxDepth));
    EXPECT_TRUE(readsOption(AccelKind::Bvh, O::Buckets));
    EXPECT_FALSE(readsOption(AccelKind::KdTree, O::Buckets));
    EXPECT_FALSE(readsOption(AccelKind::BruteForce, O::CIsect));
    // The costs steer the SAH only; the leaf size every split method.
    EXPECT_TRUE(readsOption(AccelKind::KdTree, O::EmptyBonus, SplitMethod::Sah));
    EXPECT_FALSE(readsOption(AccelKind::KdTree, O::EmptyBonus, SplitMethod::Median));
    EXPECT_FALSE(readsOption(AccelKind::Bvh, O::EmptyBonus, SplitMethod::Sah));
    EXPECT_FALSE(readsOption(AccelKind::Bvh, O::CIsect, SplitMethod::Midpoint));
    EXPECT_TRUE(readsOption(AccelKind::Bvh, O::LeafSize, SplitMethod::Midpoint));
}

TEST(StructureInfo, OptionsSpelledForLessonsAndTheCli) {
    EXPECT_EQ(optionInfo(AccelOption::CIsect).key, "c_isect");
    EXPECT_EQ(cliFlag(AccelOption::CIsect), "--c-isect");
    EXPECT_EQ(cliFlag(AccelOption::GridRes), "--grid-res");
    EXPECT_EQ(cliFlag(AccelOption::KdBuild), "--kd-build");
    for (const OptionInfo& o : accelOptions()) {
        EXPECT_EQ(&optionInfo(o.option), &o);
        EXPECT_FALSE(o.doc.empty()) << o.key;
    }
}

TEST(StructureInfo, LimitsEveryReaderChecks) {
    using O = AccelOption;
    EXPECT_FALSE(optionProblem(O::MaxDepth, 1));
    EXPECT_FALSE(optionProblem(O::MaxDepth, 60));
    EXPECT_EQ(optionProblem(O::MaxDepth, 61), "must be from 1 to 60");
    EXPECT_EQ(optionProblem(O::MaxDepth, 0), "must be from 1 to 60");
    EXPECT_EQ(optionProblem(O::MaxDepth, 2.5), "expected a whole number");
    EXPECT_EQ(optionProblem(O::CIsect, 0), "must be greater than 0");
    EXPECT_FALSE(optionProblem(O::CIsect, 1e-9));
    EXPECT_FALSE(optionProblem(O::CTrav, 0));
    EXPECT_EQ(optionProblem(O::CTrav, -0.5), "must be 0 or more");
    EXPECT_EQ(optionProblem(O::CTrav, std::nan("")), "must be a finite number");
    EXPECT_EQ(optionProblem(O::EmptyBonus, 1.5), "must be from 0 to 1");
    EXPECT_EQ(optionProblem(O::Buckets, 1), "must be from 2 to 256");
    EXPECT_EQ(optionProblem(O::LeafSize, 0), "must be from 1 to 1000000");
    EXPECT_EQ(optionProblem(O::BinAbove, 0), "must be from 1 to 2147483647");
    EXPECT_EQ(optionProblem(O::GridRes, 513), "must be from 1 to 512");
    EXPECT_EQ(optionProblem(O::GridLambda, 0), "must be greater than 0");
    EXPECT_FALSE(optionProblem(O::GridLambda, 1e300));  // capped by the grid, not refused
    // A control's range: an open lo a step up, an infinite hi the control's top, auto as 0.
    EXPECT_EQ(controlRange(O::CIsect), std::make_pair(0.01, 1000.0));
    EXPECT_EQ(controlRange(O::CTrav), std::make_pair(0.0, 1000.0));
    EXPECT_EQ(controlRange(O::MaxDepth), std::make_pair(0.0, 60.0));
    EXPECT_EQ(controlRange(O::LeafSize), std::make_pair(0.0, 1e6));
    EXPECT_EQ(controlRange(O::EmptyBonus), std::make_pair(0.0, 1.0));
}

TEST(StructureInfo, DefaultsAreTheOptionsOwn) {
    // pbrt-v4's costs (1, 5, empty bonus 0.5), 12 BVH buckets, lambda 4, mailboxing on; max depth
    // and the kd-tree's leaf size by rule (0); the BVH's leaves 4 primitives.
    const AccelOptions d;
    EXPECT_EQ(d.value(AccelKind::KdTree, AccelOption::CTrav), 1.0);
    EXPECT_EQ(d.value(AccelKind::Bvh, AccelOption::CIsect), 5.0);
    EXPECT_EQ(d.value(AccelKind::KdTree, AccelOption::EmptyBonus), 0.5);
    EXPECT_EQ(d.value(AccelKind::Bvh, AccelOption::Buckets), 12.0);
    EXPECT_EQ(d.value(AccelKind::Grid, AccelOption::GridLambda), 4.0);
    EXPECT_EQ(d.value(AccelKind::Grid, AccelOption::Mailbox), 1.0);
    EXPECT_EQ(d.value(AccelKind::KdTree, AccelOption::MaxDepth), 0.0);
    EXPECT_EQ(d.value(AccelKind::KdTree, AccelOption::LeafSize), 0.0);
    EXPECT_EQ(d.value(AccelKind::Bvh, AccelOption::LeafSize), 4.0);
    EXPECT_EQ(d.split(AccelKind::KdTree), SplitMethod::Sah);
    EXPECT_FALSE(d.split(AccelKind::Grid));
    // The table's defaults say the same, for every structure reading a plain number.
    for (const StructureInfo& s : structures())
        for (const AccelOption option : s.options) {
            const OptionInfo& o = optionInfo(option);
            if (o.type == OptionType::Cells) continue;
            if (option == AccelOption::LeafSize && s.kind == AccelKind::Bvh) continue;  // above
            EXPECT_EQ(d.value(s.kind, option), o.defaultValue) << s.name << " " << o.key;
        }
}

TEST(StructureInfo, AnOptionSetReachesTheBuild) {
    const Scene s = loadScene("cornell");
    AccelOptions o;
    o.set(AccelOption::MaxDepth, 2);
    o.set(AccelOption::CIsect, 20);
    EXPECT_EQ(o.value(AccelKind::KdTree, AccelOption::CIsect), 20.0);
    EXPECT_EQ(o.value(AccelKind::Bvh, AccelOption::CIsect), 20.0);
    const BuildSummary kd = summarize(buildAccelerator(s, AccelKind::KdTree, {}, o));
    EXPECT_LE(kd.stats.maxDepth, 2u);
    o.set(AccelOption::LeafSize, 40);  // past the BVH's SAH limit of 16: the limit follows
    EXPECT_EQ(o.bvh.maxLeafSize, 40);
    o.set(AccelOption::LeafSize, 0);  // auto: the kd-tree's rule, the BVH's default 4
    EXPECT_EQ(o.kdtree.leafSize, 0);
    EXPECT_EQ(o.bvh.leafSize, 4);
    o.set(AccelOption::Mailbox, 0);
    EXPECT_FALSE(o.grid.mailbox);
    EXPECT_FALSE(o.kdtree.mailbox);
    o.set(AccelOption::Split, static_cast<int>(SplitMethod::Median));
    EXPECT_EQ(o.split(AccelKind::Bvh), SplitMethod::Median);
    EXPECT_EQ(summarize(buildAccelerator(s, AccelKind::Bvh, {}, o)).description, "bvh median");
}

TEST(StructureChoices, ListsInTheOrderGivenEachTreeOncePerSplit) {
    using R = std::vector<StructureChoice>;
    const auto three = parseStructureChoices("grid,kdtree,bvh", std::nullopt);
    ASSERT_TRUE(std::holds_alternative<R>(three));
    EXPECT_EQ(std::get<R>(three), (R{{AccelKind::Grid, std::nullopt},
                                     {AccelKind::KdTree, SplitMethod::Sah},
                                     {AccelKind::Bvh, SplitMethod::Sah}}));
    // One tree alone: the slides' comparison of its split methods.
    const auto kd = parseStructureChoices("kdtree", std::nullopt);
    ASSERT_TRUE(std::holds_alternative<R>(kd));
    EXPECT_EQ(std::get<R>(kd).size(), 3u);
    EXPECT_EQ(std::get<R>(kd)[1], (StructureChoice{AccelKind::KdTree, SplitMethod::Median}));
    const auto two = parseStructureChoices(" bvh , bruteforce", "midpoint,median,midpoint");
    ASSERT_TRUE(std::holds_alternative<R>(two));
    EXPECT_EQ(std::get<R>(two), (R{{AccelKind::Bvh, SplitMethod::Midpoint},
                                   {AccelKind::Bvh, SplitMethod::Median},
                                   {AccelKind::BruteForce, std::nullopt}}));
    EXPECT_EQ(choiceName(std::get<R>(two)[1]), "bvh median");
    EXPECT_EQ(choiceName(std::get<R>(two)[2]), "bruteforce");
}

TEST(StructureChoices, RefusesAnUnknownNameATwiceAndAnEmptyWord) {
    const auto msg = [](auto r) {
        return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : std::string();
    };
    EXPECT_EQ(msg(parseStructureChoices("grid,octree", std::nullopt)),
              "--accel grid,octree: expected a comma list of bruteforce, grid, kdtree or bvh "
              "(octree)");
    EXPECT_EQ(msg(parseStructureChoices("grid,grid", std::nullopt)),
              "--accel grid,grid: grid twice");
    EXPECT_NE(msg(parseStructureChoices("grid,", std::nullopt)).find("(an empty name)"),
              std::string::npos);
    EXPECT_EQ(msg(parseStructureChoices("kdtree", "sah,best", "accel", "split")),
              "split sah,best: expected a comma list of midpoint, median or sah (best)");
}

}  // namespace
}  // namespace raystep
