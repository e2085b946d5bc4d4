// The outline of each structure: one function per structure, chosen by std::visit.
#include "raystep/accel/outline.h"

#include <algorithm>
#include <cmath>

namespace raystep {

template <int N>
std::optional<IVecN<N>> OutlineGrid<N>::cellAt(const VecN<N, double>& p) const {
    IVecN<N> c;
    for (int a = 0; a < N; ++a) {
        const double f = std::floor((p[a] - spec.lo[a]) / spec.cellSize(a));
        if (!(f >= 0 && f < spec.res[a])) return std::nullopt;
        c[a] = static_cast<int>(f);
    }
    return c;
}
template struct OutlineGrid<2>;
template struct OutlineGrid<3>;

namespace {

template <typename Prims>
BoxN<Prims::N> primitivesBounds(const Prims& prims) {
    BoxN<Prims::N> b;
    for (std::uint32_t p = 0; p < prims.count(); ++p) b.extend(prims.bounds(p));
    return b;
}

/// A leaf's primitive ids into the outline, when it lists them.
template <int N>
void listPrimitives(StructureOutline<N>& o, OutlineNode<N>& leaf, OutlineDetail detail,
                    std::span<const std::uint32_t> ids) {
    if (detail != OutlineDetail::Primitives) return;
    leaf.firstPrimitive = static_cast<std::uint32_t>(o.leafPrimitives.size());
    o.leafPrimitives.insert(o.leafPrimitives.end(), ids.begin(), ids.end());
}

template <typename Prims>
StructureOutline<Prims::N> outlineOf(const BruteForceT<Prims>& bf, OutlineDetail detail) {
    // One leaf holding everything: the slides' RaySceneIntersection.
    StructureOutline<Prims::N> o;
    o.kind = AccelKind::BruteForce;
    o.bounds = primitivesBounds(bf.primitives());
    OutlineNode<Prims::N> root;
    root.box = o.bounds;
    root.leaf = true;
    root.primitives = bf.primitives().count();
    std::vector<std::uint32_t> all(root.primitives);
    for (std::uint32_t p = 0; p < root.primitives; ++p) all[p] = p;
    listPrimitives<Prims::N>(o, root, detail, all);
    o.nodes.push_back(root);
    return o;
}

template <typename Prims>
StructureOutline<Prims::N> outlineOf(const UniformGridT<Prims>& g, OutlineDetail detail) {
    constexpr int N = Prims::N;
    StructureOutline<N> o;
    o.kind = AccelKind::Grid;
    OutlineGrid<N> grid;
    grid.spec = g.spec();
    // lo + i * cellSize, as the views draw them (equal to the DDA's boundaries on the lecture's
    // grids, whose cells have exact binary sizes).
    for (int a = 0; a < N; ++a)
        for (int i = 0; i <= grid.spec.res[a]; ++i)
            grid.lines[a].push_back(grid.spec.lo[a] + i * grid.spec.cellSize(a));
    o.bounds.lo = grid.spec.lo;
    o.bounds.hi = grid.spec.hi;
    if (detail == OutlineDetail::Primitives) {
        // X fastest, as the grid stores its cells.
        IVecN<N> c{0};
        grid.cellStart.push_back(0);
        for (bool more = true; more;) {
            for (std::uint32_t p : g.cell(c)) grid.cellPrimitives.push_back(p);
            grid.cellStart.push_back(static_cast<std::uint32_t>(grid.cellPrimitives.size()));
            int a = 0;
            while (a < N && ++c[a] == grid.spec.res[a]) c[a++] = 0;
            more = a < N;
        }
    }
    o.grid = std::move(grid);
    return o;
}

template <typename Prims>
StructureOutline<Prims::N> outlineOf(const KdTree<Prims>& kd, OutlineDetail detail) {
    constexpr int N = Prims::N;
    StructureOutline<N> o;
    o.kind = AccelKind::KdTree;
    o.bounds = kd.bounds();
    const auto& nodes = kd.nodes();
    o.nodes.resize(nodes.size());
    // forEachNode gives each node its box, parents first: a child's depth and parent are known
    // from its parent's, set when the parent was met.
    kd.forEachNode([&](std::uint32_t id, const KdNode& n, const BoxN<N>& box) {
        OutlineNode<N>& out = o.nodes[id];
        out.box = box;
        out.leaf = n.leaf();
        o.maxDepth = std::max(o.maxDepth, out.depth);
        if (out.leaf) {
            out.primitives = n.count;
            listPrimitives<N>(
                o, out, detail,
                std::span<const std::uint32_t>(kd.primIds()).subspan(n.index, n.count));
            return;
        }
        out.plane = static_cast<std::uint32_t>(o.planes.size());
        o.planes.push_back({id, n.axis, n.split, box});
        out.axis = n.axis;
        out.children = {id + 1, n.index};
        for (const std::uint32_t child : {id + 1, n.index}) {
            o.nodes[child].parent = id;
            o.nodes[child].depth = out.depth + 1;
        }
    });
    return o;
}

template <typename Prims>
StructureOutline<Prims::N> outlineOf(const Bvh<Prims>& bvh, OutlineDetail detail) {
    constexpr int N = Prims::N;
    StructureOutline<N> o;
    o.kind = AccelKind::Bvh;
    o.overlapping = true;
    const auto& nodes = bvh.nodes();
    o.nodes.resize(nodes.size());
    // The nodes are stored parents first (left child next, right child at `index`).
    for (std::uint32_t id = 0; id < nodes.size(); ++id) {
        OutlineNode<N>& out = o.nodes[id];
        out.box = nodes[id].bounds;
        out.leaf = nodes[id].leaf();
        o.maxDepth = std::max(o.maxDepth, out.depth);
        if (out.leaf) {
            out.primitives = nodes[id].count;
            listPrimitives<N>(o, out, detail,
                              std::span<const std::uint32_t>(bvh.primIds())
                                  .subspan(nodes[id].index, nodes[id].count));
            continue;
        }
        out.axis = nodes[id].axis;
        out.children = {id + 1, nodes[id].index};
        for (const std::uint32_t child : {id + 1, nodes[id].index}) {
            o.nodes[child].parent = id;
            o.nodes[child].depth = out.depth + 1;
        }
    }
    if (!nodes.empty()) o.bounds = nodes[0].bounds;
    return o;
}

template <typename Prims>
StructureOutline<Prims::N> outlineT(const AcceleratorT<Prims>& accel, OutlineDetail detail) {
    return std::visit([&](const auto& a) { return outlineOf(a, detail); }, accel);
}

}  // namespace

StructureOutline<3> outline(const Accelerator& accel, OutlineDetail detail) {
    return outlineT<ScenePrims>(accel, detail);
}
StructureOutline<2> outline(const Accelerator2D& accel, OutlineDetail detail) {
    return outlineT<Scene2DPrims>(accel, detail);
}

}  // namespace raystep
