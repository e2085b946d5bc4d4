// The outline against the structure it came from: every node box equals the node's bounds
// computed here (BVH: the union of its primitives' boxes; kd-tree: the root box cut by the splits
// on the way down), depths and parents by a recursion of the test's own, the grid's lines at
// lo + i * cellSize, and the node ids NodeEnter names are the outline's.
#include "raystep/accel/outline.h"
#include "random_scene2d.h"
#include "raystep/base/rng.h"
#include "raystep/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace raystep {
namespace {

// Primitive boxes written out here (not Scene::primitiveBounds).
BoxN<2> boxOf(const Scene2D& s, std::uint32_t p) {
    BoxN<2> b;
    if (s.isCircle(p)) {
        const Circle2& c = s.circles[p];
        b.lo = c.center - Vec2(c.radius);
        b.hi = c.center + Vec2(c.radius);
    } else {
        const Segment2& g = s.segments[p - s.circles.size()];
        b.lo = glm::min(g.a, g.b);
        b.hi = glm::max(g.a, g.b);
    }
    return b;
}
BoxN<3> boxOf(const Scene& s, std::uint32_t p) {
    BoxN<3> b;
    if (s.isSphere(p)) {
        const Sphere& sp = s.spheres[p];
        b.lo = sp.center - Vec3(sp.radius);
        b.hi = sp.center + Vec3(sp.radius);
    } else {
        const Triangle& t = s.triangle(p);
        b.lo = glm::min(t.a, glm::min(t.b, t.c));
        b.hi = glm::max(t.a, glm::max(t.b, t.c));
    }
    return b;
}
template <int N>
BoxN<N> unite(BoxN<N> a, const BoxN<N>& b) {
    for (int i = 0; i < N; ++i) {
        a.lo[i] = std::min(a.lo[i], b.lo[i]);
        a.hi[i] = std::max(a.hi[i], b.hi[i]);
    }
    return a;
}
template <int N>
void expectBox(const BoxN<N>& got, const BoxN<N>& want, const std::string& what) {
    for (int i = 0; i < N; ++i) {
        EXPECT_EQ(got.lo[i], want.lo[i]) << what << " lo[" << i << "]";
        EXPECT_EQ(got.hi[i], want.hi[i]) << what << " hi[" << i << "]";
    }
}

Scene2D randomScene2D(int count, std::uint64_t seed) {
    return raystep::randomScene2D(count, seed, 7);
}

/// The BVH's nodes against the test's recursion: each box the union of the boxes of the
/// primitives its subtree's leaves list.
template <typename SceneT, typename Prims>
void checkBvh(const SceneT& scene, const Bvh<Prims>& bvh, const StructureOutline<Prims::N>& o) {
    constexpr int N = Prims::N;
    ASSERT_EQ(o.kind, AccelKind::Bvh);
    ASSERT_EQ(o.nodes.size(), bvh.nodes().size());
    EXPECT_TRUE(o.overlapping);
    EXPECT_TRUE(o.planes.empty());
    EXPECT_FALSE(o.grid);
    std::size_t seen = 0;
    std::uint32_t deepest = 0;
    const std::function<BoxN<N>(std::uint32_t, std::uint32_t, std::uint32_t)> visit =
        [&](std::uint32_t id, std::uint32_t parent, std::uint32_t depth) {
            ++seen;
            deepest = std::max(deepest, depth);
            const BvhNode<N>& n = bvh.nodes()[id];
            BoxN<N> box;
            if (n.count > 0) {
                box = boxOf(scene, bvh.primIds()[n.index]);
                for (std::uint32_t k = 1; k < n.count; ++k)
                    box = unite(box, boxOf(scene, bvh.primIds()[n.index + k]));
                EXPECT_EQ(o.nodes[id].primitives, n.count);
            } else {
                box = unite(visit(id + 1, id, depth + 1), visit(n.index, id, depth + 1));
            }
            const std::string what = "BVH node " + std::to_string(id);
            expectBox<N>(o.nodes[id].box, box, what);
            EXPECT_EQ(o.nodes[id].leaf, n.count > 0) << what;
            EXPECT_EQ(o.nodes[id].parent, parent) << what;
            EXPECT_EQ(o.nodes[id].depth, depth) << what;
            return box;
        };
    const BoxN<N> root = visit(0, kNoId, 0);
    EXPECT_EQ(seen, o.nodes.size());  // every node reached once: the ids are the tree's
    expectBox<N>(o.bounds, root, "BVH bounds");
    EXPECT_EQ(o.maxDepth, deepest);
}

/// The kd-tree's nodes against the root box (the union of every primitive's) cut by the splits
/// on the way down; every interior node's plane.
template <typename SceneT, typename Prims>
void checkKdTree(const SceneT& scene, const KdTree<Prims>& kd,
                 const StructureOutline<Prims::N>& o) {
    constexpr int N = Prims::N;
    ASSERT_EQ(o.kind, AccelKind::KdTree);
    ASSERT_EQ(o.nodes.size(), kd.nodes().size());
    EXPECT_FALSE(o.overlapping);
    BoxN<N> all = boxOf(scene, 0);
    for (std::uint32_t p = 1; p < scene.primitiveCount(); ++p) all = unite(all, boxOf(scene, p));
    expectBox<N>(o.bounds, all, "kd-tree bounds");
    std::size_t seen = 0, interior = 0;
    const std::function<void(std::uint32_t, BoxN<N>, std::uint32_t, std::uint32_t)> visit =
        [&](std::uint32_t id, BoxN<N> box, std::uint32_t parent, std::uint32_t depth) {
            ++seen;
            const KdNode& n = kd.nodes()[id];
            const std::string what = "kd node " + std::to_string(id);
            expectBox<N>(o.nodes[id].box, box, what);
            EXPECT_EQ(o.nodes[id].leaf, n.leaf()) << what;
            EXPECT_EQ(o.nodes[id].parent, parent) << what;
            EXPECT_EQ(o.nodes[id].depth, depth) << what;
            if (n.leaf()) {
                EXPECT_EQ(o.nodes[id].primitives, n.count) << what;
                EXPECT_FALSE(o.nodes[id].plane) << what;
                return;
            }
            ++interior;
            ASSERT_TRUE(o.nodes[id].plane) << what;
            const OutlinePlane<N>& plane = o.planes[*o.nodes[id].plane];
            EXPECT_EQ(plane.node, id);
            EXPECT_EQ(plane.axis, n.axis);
            EXPECT_EQ(plane.position, n.split);
            expectBox<N>(plane.box, box, what + "'s plane");
            BoxN<N> left = box, right = box;
            left.hi[n.axis] = n.split;
            right.lo[n.axis] = n.split;
            visit(id + 1, left, id, depth + 1);
            visit(n.index, right, id, depth + 1);
        };
    visit(0, all, kNoId, 0);
    EXPECT_EQ(seen, o.nodes.size());
    EXPECT_EQ(interior, o.planes.size());
}

TEST(Outline, BvhBoxesAreTheirPrimitivesUnion2D) {
    const Scene2D s = randomScene2D(80, 3);
    for (const SplitMethod m : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
        AccelOptions options;
        options.setSplit(m);
        const Accelerator2D accel = buildAccelerator2D(s, AccelKind::Bvh, options);
        checkBvh(s, std::get<Bvh<Scene2DPrims>>(accel), outline(accel));
    }
}

TEST(Outline, BvhBoxesAreTheirPrimitivesUnion3D) {
    for (const char* name : {"default", "whitted", "cornell"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(name);
        const Accelerator accel = buildAccelerator(s, AccelKind::Bvh);
        checkBvh(s, std::get<Bvh3>(accel), outline(accel));
    }
}

TEST(Outline, KdTreeBoxesAreTheRootCutOnTheWayDown) {
    const Scene2D s2 = randomScene2D(80, 11);
    for (const SplitMethod m : {SplitMethod::Midpoint, SplitMethod::Median, SplitMethod::Sah}) {
        AccelOptions options;
        options.setSplit(m);
        const Accelerator2D a2 = buildAccelerator2D(s2, AccelKind::KdTree, options);
        checkKdTree(s2, std::get<KdTree<Scene2DPrims>>(a2), outline(a2));
    }
    for (const char* name : {"default", "whitted", "cornell"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(name);
        const Accelerator a3 = buildAccelerator(s, AccelKind::KdTree);
        checkKdTree(s, std::get<KdTree3>(a3), outline(a3));
    }
}

TEST(Outline, TheLectureKdTreeHasPlanesInsideTheirNodes) {
    // lecture-kdtree, the 2D scene the slides build: the plane's ends lie on its node's box.
    const auto any = loadAnyScene("lecture-kdtree");
    const Scene2D& s = std::get<Scene2D>(any);
    const Accelerator2D accel = buildAccelerator2D(s, AccelKind::KdTree);
    const StructureOutline<2> o = outline(accel);
    checkKdTree(s, std::get<KdTree<Scene2DPrims>>(accel), o);
    ASSERT_FALSE(o.planes.empty());
    for (const OutlinePlane<2>& p : o.planes) {
        const auto [a, b] = p.extent();
        const int other = 1 - p.axis;
        EXPECT_EQ(a[p.axis], p.position);
        EXPECT_EQ(b[p.axis], p.position);
        EXPECT_EQ(a[other], p.box.lo[other]);
        EXPECT_EQ(b[other], p.box.hi[other]);
    }
}

TEST(Outline, GridLinesLieAtLoPlusICellSize) {
    // lecture-grid names the grid the slides draw.
    const auto any = loadAnyScene("lecture-grid");
    const Scene2D& s = std::get<Scene2D>(any);
    ASSERT_TRUE(s.gridRes);
    const Accelerator2D accel = buildAccelerator2D(s, AccelKind::Grid);
    const auto& spec = std::get<UniformGridT<Scene2DPrims>>(accel).spec();
    const StructureOutline<2> o = outline(accel);
    ASSERT_EQ(o.kind, AccelKind::Grid);
    ASSERT_TRUE(o.grid);
    EXPECT_TRUE(o.nodes.empty());
    for (int a = 0; a < 2; ++a) {
        EXPECT_EQ(o.grid->spec.res[a], (*s.gridRes)[a]);
        ASSERT_EQ(o.grid->lines[a].size(), std::size_t((*s.gridRes)[a]) + 1);
        const double cell = (spec.hi[a] - spec.lo[a]) / (*s.gridRes)[a];
        for (int i = 0; i <= (*s.gridRes)[a]; ++i)
            EXPECT_EQ(o.grid->lines[a][i], spec.lo[a] + i * cell) << "axis " << a << " line " << i;
    }
    expectBox<2>(o.bounds, BoxN<2>{spec.lo, spec.hi}, "grid bounds");
    // A cell's box between its lines; a point in it maps back to it.
    const IVecN<2> c(1, 2);
    const BoxN<2> cb = o.grid->cellBox(c);
    EXPECT_EQ(cb.lo.x, o.grid->lines[0][1]);
    EXPECT_EQ(cb.hi.x, o.grid->lines[0][2]);
    EXPECT_EQ(cb.lo.y, o.grid->lines[1][2]);
    EXPECT_EQ(cb.hi.y, o.grid->lines[1][3]);
    EXPECT_EQ(o.grid->cellAt(0.5 * (cb.lo + cb.hi)), std::optional<IVecN<2>>(c));
    EXPECT_FALSE(o.grid->cellAt(spec.lo - Vec2(1.0)));
}

TEST(Outline, GridLines3DAtAnExplicitResolution) {
    const Scene s = loadScene("default");
    AccelOptions options;
    options.grid.res = std::array<int, 3>{3, 5, 2};
    const Accelerator accel = buildAccelerator(s, AccelKind::Grid, {}, options);
    const auto& spec = std::get<UniformGrid>(accel).spec();
    const StructureOutline<3> o = outline(accel);
    ASSERT_TRUE(o.grid);
    const int res[3] = {3, 5, 2};
    for (int a = 0; a < 3; ++a) {
        ASSERT_EQ(o.grid->lines[a].size(), std::size_t(res[a]) + 1);
        const double cell = (spec.hi[a] - spec.lo[a]) / res[a];
        for (int i = 0; i <= res[a]; ++i) EXPECT_EQ(o.grid->lines[a][i], spec.lo[a] + i * cell);
    }
}

TEST(Outline, BruteForceIsOneLeafOverEverything) {
    const Scene2D s = randomScene2D(10, 4);
    const Accelerator2D accel = buildAccelerator2D(s, AccelKind::BruteForce);
    const StructureOutline<2> o = outline(accel);
    ASSERT_EQ(o.nodes.size(), 1u);
    EXPECT_TRUE(o.nodes[0].leaf);
    EXPECT_EQ(o.nodes[0].primitives, 10u);
    BoxN<2> all = boxOf(s, 0);
    for (std::uint32_t p = 1; p < 10; ++p) all = unite(all, boxOf(s, p));
    expectBox<2>(o.nodes[0].box, all, "brute force");
}

TEST(Outline, NodeEnterNamesTheOutlinesNodes) {
    // The ids a traversal records are the outline's: where a ray enters a node (its tNear) lies
    // on that node's box, for the BVH and the kd-tree.
    const Scene2D s = randomScene2D(60, 8);
    for (const AccelKind kind : {AccelKind::Bvh, AccelKind::KdTree}) {
        const Accelerator2D accel = buildAccelerator2D(s, kind);
        const StructureOutline<2> o = outline(accel);
        Pcg32 rng(21, 2);
        std::size_t entered = 0;
        for (int i = 0; i < 50; ++i) {
            Ray2 ray;
            ray.origin = Vec2(-5.0, rng.uniform() * 10);
            ray.dir = glm::normalize(Vec2(1.0, rng.uniform() - 0.5));
            EventLog log;
            traceRay2D(accel, ray, log);
            for (const Event& e : log.events()) {
                const auto* n = std::get_if<NodeEnter>(&e);
                if (!n) continue;
                ++entered;
                const BoxN<2>* box = o.nodeBox(n->node);
                ASSERT_NE(box, nullptr);
                const Vec2 p = ray.origin + n->tNear * ray.dir;
                for (int a = 0; a < 2; ++a) {
                    const double tol = 1e-9 * (1 + std::abs(p[a]));
                    EXPECT_GE(p[a], box->lo[a] - tol) << accelKindName(kind) << " " << n->node;
                    EXPECT_LE(p[a], box->hi[a] + tol) << accelKindName(kind) << " " << n->node;
                }
            }
        }
        EXPECT_GT(entered, 50u) << accelKindName(kind);
    }
}

}  // namespace
}  // namespace raystep

namespace raystep {
namespace {

// With OutlineDetail::Primitives each leaf lists its primitives: every primitive in some leaf,
// each inside (BVH) or meeting (kd-tree) its leaf's box; an interior node's children are the
// nodes whose parent it is, left first; a kd node's axis is its plane's. Without, no ids.
TEST(Outline, LeavesListTheirPrimitivesAndNodesTheirChildren) {
    const Scene2D s = randomScene2D(40, 5);
    for (const AccelKind kind : {AccelKind::KdTree, AccelKind::Bvh, AccelKind::BruteForce}) {
        SCOPED_TRACE(static_cast<int>(kind));
        const Accelerator2D accel = buildAccelerator2D(s, kind);
        EXPECT_TRUE(outline(accel).leafPrimitives.empty());
        const StructureOutline<2> o = outline(accel, OutlineDetail::Primitives);
        std::vector<int> seen(s.primitiveCount(), 0);
        for (std::uint32_t id = 0; id < o.nodes.size(); ++id) {
            const OutlineNode<2>& n = o.nodes[id];
            if (!n.leaf) {
                EXPECT_EQ(n.children[0], id + 1);
                for (const std::uint32_t c : n.children) {
                    ASSERT_LT(c, o.nodes.size());
                    EXPECT_EQ(o.nodes[c].parent, id);
                }
                if (n.plane) EXPECT_EQ(n.axis, o.planes[*n.plane].axis);
                EXPECT_TRUE(n.axis == 0 || n.axis == 1);
                EXPECT_TRUE(o.primitivesOf(id).empty());
                continue;
            }
            const auto prims = o.primitivesOf(id);
            EXPECT_EQ(prims.size(), n.primitives);
            for (const std::uint32_t p : prims) {
                ASSERT_LT(p, s.primitiveCount());
                ++seen[p];
                const BoxN<2> b = boxOf(s, p);
                for (int a = 0; a < 2; ++a) {
                    EXPECT_LE(b.lo[a], n.box.hi[a]);
                    EXPECT_GE(b.hi[a], n.box.lo[a]);
                    if (kind == AccelKind::Bvh) {
                        EXPECT_GE(b.lo[a], n.box.lo[a]);
                        EXPECT_LE(b.hi[a], n.box.hi[a]);
                    }
                }
            }
        }
        for (std::uint32_t p = 0; p < s.primitiveCount(); ++p) {
            EXPECT_GE(seen[p], 1) << "primitive " << p << " in no leaf";
            if (kind != AccelKind::KdTree) EXPECT_EQ(seen[p], 1) << "primitive " << p;
        }
    }
}

}  // namespace
}  // namespace raystep
