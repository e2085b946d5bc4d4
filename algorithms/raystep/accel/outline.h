#pragma once
// The static picture of a built structure, made once: its nodes' boxes by node id (the ids
// NodeEnter, NodeSkip and LeafMade name) with their depth and whether a leaf, the kd-tree's split
// planes, the grid's lines and cells. A view draws a structure from this without knowing its
// type; a new structure gives its outline here (one overload in outline.cpp: a new alternative of
// the variant fails to compile there, not silently in a view).
#include "raystep/accel/accel.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace raystep {

/// One node of a tree (or brute force's one leaf).
template <int N>
struct OutlineNode {
    BoxN<N> box;                   // kd-tree: its cell of space; BVH: its primitives' bounds
    std::uint32_t parent = kNoId;  // kNoId for the root
    std::uint32_t depth = 0;       // the root is 0 (as BuildNode and LeafMade count)
    std::uint32_t primitives = 0;  // leaves: the primitives listed
    bool leaf = false;
    std::optional<std::uint32_t> plane;  // kd-tree interior: its plane in `planes`
    int axis = -1;                       // interior: the axis its children are split along
    std::array<std::uint32_t, 2> children{kNoId, kNoId};  // interior: the left, the right
    std::uint32_t firstPrimitive = 0;  // leaves, in an outline with its primitives: leafPrimitives
};

/// A kd-tree node's split plane, within that node's box.
template <int N>
struct OutlinePlane {
    std::uint32_t node = 0;
    int axis = 0;
    double position = 0.0;
    BoxN<N> box;  // the node's box: the plane is its cross-section at `position`
    /// The plane's two ends (2D: a segment) or its lowest and highest corners (3D: a rectangle).
    std::pair<VecN<N, double>, VecN<N, double>> extent() const {
        VecN<N, double> lo = box.lo, hi = box.hi;
        lo[axis] = hi[axis] = position;
        return {lo, hi};
    }
};

/// The uniform grid: its box, resolution and the lines between cells.
template <int N>
struct OutlineGrid {
    GridSpec<N, double> spec;
    std::array<std::vector<double>, N> lines;  // per axis: lo + i * cellSize, i = 0 .. res
    /// The box of cell `c` (each index in 0 .. res - 1).
    BoxN<N> cellBox(const IVecN<N>& c) const {
        BoxN<N> b;
        for (int a = 0; a < N; ++a) {
            b.lo[a] = lines[a][c[a]];
            b.hi[a] = lines[a][c[a] + 1];
        }
        return b;
    }
    /// The cell holding point `p`, if it lies in the grid (a cell owns its lower faces).
    std::optional<IVecN<N>> cellAt(const VecN<N, double>& p) const;
    /// With OutlineDetail::Primitives: each cell's primitive ids, cell by cell with X fastest
    /// (cell k holds cellPrimitives[cellStart[k] .. cellStart[k + 1])); empty otherwise.
    std::vector<std::uint32_t> cellStart, cellPrimitives;
};

template <int N>
struct StructureOutline {
    AccelKind kind = AccelKind::BruteForce;
    BoxN<N> bounds;                       // what the structure covers (the root's box)
    std::vector<OutlineNode<N>> nodes;    // by node id; empty for the grid
    std::vector<OutlinePlane<N>> planes;  // the kd-tree's, parents before children
    std::optional<OutlineGrid<N>> grid;   // the grid's only
    bool overlapping = false;             // boxes may overlap (the BVH): draw them all, by depth
    std::uint32_t maxDepth = 0;
    /// With OutlineDetail::Primitives: every leaf's primitive ids, a leaf's at its
    /// firstPrimitive, `primitives` of them (a view needs no ids, and a big model's are many).
    std::vector<std::uint32_t> leafPrimitives;
    std::span<const std::uint32_t> primitivesOf(std::uint32_t id) const {
        const OutlineNode<N>& n = nodes[id];
        if (!n.leaf || leafPrimitives.empty()) return {};
        return {leafPrimitives.data() + n.firstPrimitive, n.primitives};
    }
    /// The box of node `id` (NodeEnter's node), if there is one.
    const BoxN<N>* nodeBox(std::uint32_t id) const {
        return id < nodes.size() ? &nodes[id].box : nullptr;
    }
};

/// What an outline holds besides the boxes: the leaves' primitive ids too (a practice's prompt
/// names them), or not (a view's).
enum class OutlineDetail { Boxes, Primitives };
/// The outline of a built structure. O(nodes): a view makes it once per structure, not per frame.
StructureOutline<3> outline(const Accelerator& accel, OutlineDetail detail = OutlineDetail::Boxes);
StructureOutline<2> outline(const Accelerator2D& accel,
                            OutlineDetail detail = OutlineDetail::Boxes);

extern template struct OutlineGrid<2>;
extern template struct OutlineGrid<3>;

}  // namespace raystep
