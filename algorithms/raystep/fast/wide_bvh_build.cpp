// The wide BVH's build: a binary tree by binned SAH over the primitives' centres (the teaching
// BVH's split, accel/bvh.cpp), then each node given four children by opening its largest
// interior grandchildren, and the leaves' triangles packed four to a block.
#include "raystep/fast/wide_bvh.h"

#include "raystep/base/timer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace raystep {

namespace {

/// The nearest float at or below x (lo) or at or above it (hi): the float box holds the double one.
float floatDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float floatUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

/// Blocks a leaf of n triangles takes: the SAH counts what a ray pays, four triangles a test.
double blocksOf(std::uint32_t n) {
    return std::ceil(n / 4.0);
}

bool finite(const Vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
bool primitiveFinite(const Scene& scene, std::uint32_t p) {
    if (scene.isSphere(p)) {
        const Sphere& s = scene.spheres[p];
        return finite(s.center) && std::isfinite(s.radius);
    }
    const Triangle& t = scene.triangle(p);
    return finite(t.a) && finite(t.b) && finite(t.c);
}

struct Ref {
    Bounds3 box;
    Vec3 centre;
    std::uint32_t prim;
};

/// The binary tree the build makes first.
struct BinaryNode {
    Bounds3 box;
    std::int32_t left = -1, right = -1;  // -1: a leaf
    std::uint32_t begin = 0, count = 0;  // a leaf's refs
    bool leaf() const { return left < 0; }
};

// Past this depth a node is cut at its median: the traversal's stack holds 3 entries per level.
constexpr int kMaxBinaryDepth = 60;

class BinaryBuilder {
  public:
    BinaryBuilder(std::vector<Ref>& refs, const WideBvhOptions& o)
        : refs_(refs), o_(o), progress_(o.progress) {}

    std::vector<BinaryNode> build() {
        if (!refs_.empty()) node(0, static_cast<std::uint32_t>(refs_.size()), 0);
        return std::move(nodes_);
    }

  private:
    std::int32_t node(std::uint32_t begin, std::uint32_t end, int depth) {
        const auto id = static_cast<std::int32_t>(nodes_.size());
        nodes_.emplace_back();
        Bounds3 box, centres;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.extend(refs_[i].box);
            centres.extend(refs_[i].centre);
        }
        nodes_[id].box = box;
        const std::uint32_t n = end - begin;
        const std::uint32_t mid = split(begin, end, box, centres, depth);
        if (mid == begin) {
            nodes_[id].begin = begin;
            nodes_[id].count = n;
            progress_.leafDone();
            return id;
        }
        std::int32_t l = -1, r = -1;
        progress_.child(double(mid - begin) / n, [&] { l = node(begin, mid, depth + 1); });
        progress_.child(double(end - mid) / n, [&] { r = node(mid, end, depth + 1); });
        nodes_[id].left = l;
        nodes_[id].right = r;
        return id;
    }

    /// Where [begin, end) is cut (refs reordered), or begin for a leaf.
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const Bounds3& box,
                        const Bounds3& centres, int depth) {
        const std::uint32_t n = end - begin;
        if (n <= 4) return begin;  // one block: nothing cheaper
        const int axis = centres.longestAxis();
        const double extent = centres.hi[axis] - centres.lo[axis];
        if (!(extent > 0.0) || depth >= kMaxBinaryDepth) {
            // Every centre at one point (or too deep): halves by count, unless it fits a leaf.
            if (n <= static_cast<std::uint32_t>(o_.maxLeafSize) && depth < kMaxBinaryDepth)
                return begin;
            return median(begin, end, axis);
        }
        // Binned SAH on each axis whose centres spread: the cheapest plane of the three.
        const int bins = std::max(2, o_.bins);
        double bestCost = std::numeric_limits<double>::infinity();
        int bestAxis = -1, bestBin = 0;
        for (int a = 0; a < 3; ++a) {
            const double lo = centres.lo[a], ext = centres.hi[a] - centres.lo[a];
            if (!(ext > 0.0)) continue;
            std::vector<Bounds3> binBox(bins);
            std::vector<std::uint32_t> binCount(bins, 0);
            const double scale = bins / ext;
            for (std::uint32_t i = begin; i < end; ++i) {
                const int b = binOf(refs_[i].centre[a], lo, scale, bins);
                binBox[b].extend(refs_[i].box);
                ++binCount[b];
            }
            // Areas and counts right of each plane, swept from the right.
            std::vector<double> rightArea(bins, 0.0);
            std::vector<std::uint32_t> rightCount(bins, 0);
            Bounds3 acc;
            std::uint32_t cnt = 0;
            for (int b = bins - 1; b > 0; --b) {
                acc.extend(binBox[b]);
                cnt += binCount[b];
                rightArea[b] = acc.area();
                rightCount[b] = cnt;
            }
            acc = Bounds3{};
            cnt = 0;
            for (int b = 1; b < bins; ++b) {  // plane between bins b-1 and b
                acc.extend(binBox[b - 1]);
                cnt += binCount[b - 1];
                if (cnt == 0 || rightCount[b] == 0) continue;
                const double cost =
                    acc.area() * blocksOf(cnt) + rightArea[b] * blocksOf(rightCount[b]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = a;
                    bestBin = b;
                }
            }
        }
        const double area = box.area();
        const double leafCost = o_.cIsect * blocksOf(n);
        const double splitCost = o_.cTrav + (area > 0.0 ? o_.cIsect * bestCost / area : 0.0);
        if (bestAxis < 0)
            return n <= static_cast<std::uint32_t>(o_.maxLeafSize) ? begin
                                                                   : median(begin, end, axis);
        if (n <= static_cast<std::uint32_t>(o_.maxLeafSize) && leafCost <= splitCost) return begin;
        const double lo = centres.lo[bestAxis];
        const double scale = bins / (centres.hi[bestAxis] - lo);
        const auto mid = std::partition(
            refs_.begin() + begin, refs_.begin() + end,
            [&](const Ref& r) { return binOf(r.centre[bestAxis], lo, scale, bins) < bestBin; });
        const auto m = static_cast<std::uint32_t>(mid - refs_.begin());
        if (m == begin || m == end) return median(begin, end, bestAxis);
        return m;
    }

    static int binOf(double c, double lo, double scale, int bins) {
        return std::clamp(static_cast<int>((c - lo) * scale), 0, bins - 1);
    }

    std::uint32_t median(std::uint32_t begin, std::uint32_t end, int axis) {
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(
            refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
            [axis](const Ref& a, const Ref& b) { return a.centre[axis] < b.centre[axis]; });
        return mid;
    }

    std::vector<Ref>& refs_;
    const WideBvhOptions& o_;
    std::vector<BinaryNode> nodes_;
    BuildProgress progress_;
};

}  // namespace

/// Turns the binary tree into four-wide nodes and packed leaves.
class WideBvhCollapse {
  public:
    WideBvhCollapse(WideBvh& out, const Scene& scene, const std::vector<Ref>& refs,
                    const std::vector<BinaryNode>& bin)
        : out_(out), scene_(scene), refs_(refs), bin_(bin) {}

    /// The child encoding of binary node `b`: a node index, or ~leaf.
    std::int32_t emit(std::int32_t b, std::uint32_t depth) {
        out_.stats_.maxDepth = std::max(out_.stats_.maxDepth, depth);
        if (bin_[b].leaf()) return ~leaf(bin_[b]);
        // Open the interior child of largest area until there are four (pbrt's and Embree's rule:
        // a ray most likely enters the largest box, so its children are the ones to test at once).
        std::array<std::int32_t, 4> kids{bin_[b].left, bin_[b].right, -1, -1};
        int count = 2;
        while (count < 4) {
            int widest = -1;
            double area = -1.0;
            for (int i = 0; i < count; ++i)
                if (!bin_[kids[i]].leaf() && bin_[kids[i]].box.area() > area) {
                    area = bin_[kids[i]].box.area();
                    widest = i;
                }
            if (widest < 0) break;
            const BinaryNode& w = bin_[kids[widest]];
            kids[widest] = w.left;
            kids[count++] = w.right;
        }
        return makeNode(kids.data(), count, depth);
    }

    /// The root: always a node, so the traversal starts at one (a scene of a few primitives is
    /// a node with one leaf).
    std::int32_t root() {
        if (!bin_[0].leaf()) return emit(0, 0);
        const std::int32_t only = 0;
        return makeNode(&only, 1, 0);
    }

  private:
    /// A node of binary nodes kids[0..count), its children emitted after it.
    std::int32_t makeNode(const std::int32_t* kids, int count, std::uint32_t depth) {
        const auto id = static_cast<std::int32_t>(out_.nodes_.size());
        out_.nodes_.emplace_back();
        WideBvh::Node node{};
        for (int i = 0; i < 4; ++i) {
            for (int a = 0; a < 3; ++a) {
                node.lo[a][i] = std::numeric_limits<float>::infinity();
                node.hi[a][i] = -std::numeric_limits<float>::infinity();
            }
            node.child[i] = WideBvh::kEmpty;
        }
        for (int i = 0; i < count; ++i) {
            const Bounds3& box = bin_[kids[i]].box;
            for (int a = 0; a < 3; ++a) {
                node.lo[a][i] = floatDown(box.lo[a]);
                node.hi[a][i] = floatUp(box.hi[a]);
            }
            node.child[i] = emit(kids[i], depth + 1);
        }
        out_.nodes_[id] = node;
        return id;
    }

    std::int32_t leaf(const BinaryNode& b) {
        WideBvh::Leaf leaf;
        leaf.firstBlock = static_cast<std::uint32_t>(out_.blocks_.size());
        leaf.firstSphere = static_cast<std::uint32_t>(out_.spherePrims_.size());
        WideBvh::Block block{};
        int lanes = 0;
        const auto flush = [&] {
            for (int l = lanes; l < 4; ++l) {
                block.prim[l] = WideBvh::kNoPrim;
                // An empty lane repeats lane 0's triangle: finite numbers, never reported.
                for (int v = 0; v < 3; ++v)
                    for (int a = 0; a < 3; ++a) block.v[v][a][l] = block.v[v][a][0];
            }
            out_.stats_.emptyLanes += 4 - lanes;
            out_.blocks_.push_back(block);
            lanes = 0;
        };
        for (std::uint32_t i = b.begin; i < b.begin + b.count; ++i) {
            const std::uint32_t p = refs_[i].prim;
            if (scene_.isSphere(p)) {
                const Sphere& s = scene_.spheres[p];
                out_.spherePrims_.push_back(p);
                out_.spheres_.push_back(
                    {{float(s.center.x), float(s.center.y), float(s.center.z)}, float(s.radius)});
                continue;
            }
            const Triangle& t = scene_.triangle(p);
            const Vec3* v[3] = {&t.a, &t.b, &t.c};
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a) block.v[k][a][lanes] = static_cast<float>((*v[k])[a]);
            block.prim[lanes] = p;
            if (++lanes == 4) flush();
        }
        if (lanes > 0) flush();
        leaf.blocks = static_cast<std::uint32_t>(out_.blocks_.size()) - leaf.firstBlock;
        leaf.spheres = static_cast<std::uint32_t>(out_.spherePrims_.size()) - leaf.firstSphere;
        out_.leaves_.push_back(leaf);
        return static_cast<std::int32_t>(out_.leaves_.size() - 1);
    }

    WideBvh& out_;
    const Scene& scene_;
    const std::vector<Ref>& refs_;
    const std::vector<BinaryNode>& bin_;
};

WideBvh::WideBvh(const Scene& scene, const WideBvhOptions& options) : scene_(&scene) {
    const ScopedTimer timer(stats_.buildMs);
    std::vector<Ref> refs;
    refs.reserve(scene.primitiveCount());
    for (std::uint32_t p = 0; p < scene.primitiveCount(); ++p) {
        // A primitive with a NaN or infinite coordinate cannot be boxed, nor hit: its own
        // coordinates are checked, as a box's min and max would drop a NaN.
        if (!primitiveFinite(scene, p)) continue;
        const Bounds3 b = scene.primitiveBounds(p);
        refs.push_back({b, b.centroid(), p});
    }
    const std::vector<BinaryNode> bin = BinaryBuilder(refs, options).build();
    if (!bin.empty()) root_ = WideBvhCollapse(*this, scene, refs, bin).root();
    stats_.nodes = static_cast<std::uint32_t>(nodes_.size());
    stats_.leaves = static_cast<std::uint32_t>(leaves_.size());
    stats_.blocks = static_cast<std::uint32_t>(blocks_.size());
    stats_.bytes = nodes_.size() * sizeof(Node) + leaves_.size() * sizeof(Leaf) +
                   blocks_.size() * sizeof(Block) +
                   spherePrims_.size() * (sizeof(std::uint32_t) + sizeof(FloatSphere));
}

}  // namespace raystep
