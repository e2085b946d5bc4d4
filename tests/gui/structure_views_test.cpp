// The views draw any structure from the session's outline: the outline is made once per
// structure (the same object while the cursor moves, a new one with a new structure), and the 3D
// view draws a BVH's walk as the 2D view does (every box entered, the current one in the current
// node's colour and filled, a skipped one thin and not filled). The scene is made here: two unit
// spheres at x = -2 and x = 2, so every box is known by hand.
#include "session.h"
#include "vtk_actors.h"

#include "course/palette.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace raystep::gui {
namespace {

/// Two unit spheres on the x axis, at -2 and 2; the eye above the left one, looking down -z at
/// its centre through the one pixel of a 1x1 image (its ray: x = -2, y = 0).
Scene twoSpheres() {
    Scene s;
    s.name = "two spheres";
    s.materials.push_back(Material{});
    s.spheres.push_back({Vec3(-2, 0, 0), 1.0, 0});
    s.spheres.push_back({Vec3(2, 0, 0), 1.0, 0});
    s.camera.eye = Vec3(-2, 0, 10);
    s.camera.lookAt = Vec3(-2, 0, 0);
    s.settings.width = s.settings.height = 1;
    return s;
}

AccelOptions oneSpherePerLeaf() {
    AccelOptions o;
    // Midpoint on x (the longest axis) at 0, between the centroids -2 and 2: one leaf each.
    o.bvh.split = SplitMethod::Midpoint;
    o.bvh.leafSize = 1;
    return o;
}

using Point = std::array<long long, 3>;  // a point in thousandths (exact for these boxes)
using Edge = std::pair<Point, Point>;
Point key(const double* p) {
    return {std::llround(p[0] * 1000), std::llround(p[1] * 1000), std::llround(p[2] * 1000)};
}
Edge edge(Point a, Point b) {
    return a < b ? Edge{a, b} : Edge{b, a};
}
/// A box's 12 edges (lo, hi in scene units).
std::set<Edge> boxEdges(Vec3 lo, Vec3 hi) {
    std::set<Edge> out;
    const auto corner = [&](int k) {
        const double p[3] = {k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
        return key(p);
    };
    for (int a = 0; a < 8; ++a)
        for (int b = a + 1; b < 8; ++b)
            if (std::popcount(unsigned(a ^ b)) == 1) out.insert(edge(corner(a), corner(b)));
    return out;
}

/// What the trace's actors hold: each line segment with its colour and its actor's width, and
/// the quads of the filled actors with their colour.
struct Drawn {
    struct Line {
        std::array<int, 3> colour;
        double width;
    };
    std::multimap<Edge, Line> lines;
    std::multimap<std::array<int, 3>, std::set<Point>> quads;  // a filled quad's corners
};
Drawn drawn(const PropSet& set) {
    Drawn d;
    for (const auto& prop : set.props) {
        auto* actor = vtkActor::SafeDownCast(prop);
        if (!actor || !actor->GetMapper()) continue;
        auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputAsDataSet());
        if (!poly) continue;
        double rgb[3];
        actor->GetProperty()->GetColor(rgb);
        const std::array<int, 3> own{int(std::lround(rgb[0] * 255)), int(std::lround(rgb[1] * 255)),
                                     int(std::lround(rgb[2] * 255))};
        auto* colours = vtkUnsignedCharArray::SafeDownCast(poly->GetCellData()->GetScalars());
        vtkNew<vtkIdList> ids;
        vtkIdType cell = 0;
        auto* lines = poly->GetLines();
        lines->InitTraversal();
        while (lines->GetNextCell(ids)) {
            if (ids->GetNumberOfIds() == 2) {
                std::array<int, 3> c = own;
                if (colours)
                    for (int k = 0; k < 3; ++k) c[k] = colours->GetTypedComponent(cell, k);
                d.lines.insert(
                    {edge(key(poly->GetPoint(ids->GetId(0))), key(poly->GetPoint(ids->GetId(1)))),
                     {c, actor->GetProperty()->GetLineWidth()}});
            }
            ++cell;
        }
        auto* polys = poly->GetPolys();
        polys->InitTraversal();
        while (polys->GetNextCell(ids)) {
            std::set<Point> corners;
            for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
                corners.insert(key(poly->GetPoint(ids->GetId(k))));
            d.quads.insert({own, corners});
        }
    }
    return d;
}

std::array<int, 3> rgbOf(StructureRole r) {
    const PaletteColour& c = structureColour(r);
    return {c.r, c.g, c.b};
}

/// The face x = `x` of the box lo..hi, as a quad's corner set.
std::set<Point> faceAtX(Vec3 lo, Vec3 hi, double x) {
    std::set<Point> out;
    for (const double y : {lo.y, hi.y})
        for (const double z : {lo.z, hi.z}) {
            const double p[3] = {x, y, z};
            out.insert(key(p));
        }
    return out;
}

TEST(StructureViews, TheThreeDBvhIsDrawnAtARaysStepAsTheTwoDViewDrawsIt) {
    Session s;
    s.adopt(Session::prepare(twoSpheres(), AccelKind::Bvh, oneSpherePerLeaf()));
    s.tracePixel(0, 0, 1, 1);
    ASSERT_GT(s.size(), 0u);
    s.setCursor(s.size());  // the whole walk: the left leaf entered last, the right one skipped
    ASSERT_EQ(s.state().nodesEntered.size(), 2u);
    ASSERT_EQ(s.state().nodesSkipped.size(), 1u);
    PropSet trace, eye;
    traceProps(s, 4.0, trace, eye);
    const Drawn d = drawn(trace);

    // By hand: the root bounds both spheres, [-3, 3] x [-1, 1] x [-1, 1]; the left leaf is the
    // sphere at -2, [-3, -1] x ...; the right leaf, [1, 3] x ..., is missed by the ray x = -2.
    const Vec3 rootLo(-3, -1, -1), rootHi(3, 1, 1), leftLo(-3, -1, -1), leftHi(-1, 1, 1),
        rightLo(1, -1, -1), rightHi(3, 1, 1);
    const auto violet = rgbOf(StructureRole::KdNode);
    // Entered: the root in a grey (not the current colour), the current leaf in violet, at
    // one width; the skipped leaf thinner and in a grey.
    double enteredWidth = 0;
    for (const Edge& e : boxEdges(leftLo, leftHi)) {
        bool current = false;
        for (auto [it, end] = d.lines.equal_range(e); it != end; ++it)
            if (it->second.colour == violet) {
                current = true;
                enteredWidth = it->second.width;
            }
        EXPECT_TRUE(current) << "an edge of the current leaf is not violet";
    }
    // The root's edges at y, z = +-1 from x = -3 to 3 (its x edges): grey, as wide.
    for (const Edge& e : boxEdges(rootLo, rootHi)) {
        if (e.first[0] == e.second[0]) continue;  // a short edge shared with a leaf's face
        const auto [it, end] = d.lines.equal_range(e);
        ASSERT_NE(it, end) << "a root edge is missing";
        const auto c = it->second.colour;
        EXPECT_NE(c, violet);
        EXPECT_TRUE(c[0] == c[1] && std::abs(c[2] - c[1]) <= 20) << c[0] << "," << c[1];
        EXPECT_EQ(it->second.width, enteredWidth);
    }
    for (const Edge& e : boxEdges(rightLo, rightHi)) {
        if (e.first[0] == 3000 && e.second[0] == 3000) continue;  // on the root's face x = 3
        const auto [it, end] = d.lines.equal_range(e);
        ASSERT_NE(it, end) << "a skipped leaf's edge is missing";
        for (auto k = it; k != end; ++k) {
            EXPECT_NE(k->second.colour, violet);
            EXPECT_LT(k->second.width, enteredWidth);
        }
    }
    // Filled: the current leaf's six faces in violet, nothing of the skipped leaf.
    int currentFaces = 0;
    for (const auto& [colour, corners] : d.quads) {
        EXPECT_NE(corners, faceAtX(rightLo, rightHi, 1)) << "the skipped leaf is filled";
        if (colour == violet &&
            (corners == faceAtX(leftLo, leftHi, -3) || corners == faceAtX(leftLo, leftHi, -1)))
            ++currentFaces;
    }
    EXPECT_EQ(currentFaces, 2);  // its two faces across x (the four others not looked for)
}

TEST(StructureViews, TheThreeDBvhBuildShowsTheNodeBeingSplitAsTheKdTreesDoes) {
    for (const AccelKind kind : {AccelKind::Bvh, AccelKind::KdTree}) {
        Session s;
        AccelOptions o = oneSpherePerLeaf();
        o.kdtree.split = SplitMethod::Midpoint;
        o.kdtree.leafSize = 1;
        s.adopt(Session::prepare(twoSpheres(), kind, o));
        s.recordBuild();
        ASSERT_TRUE(s.showingBuild());
        // Right after the first event, the root's BuildNode: the node being split is the root,
        // [-3, 3] x [-1, 1] x [-1, 1] for both (the spheres' bounds), in the current colour.
        s.setCursor(1);
        ASSERT_TRUE(s.state().buildNode.has_value());
        PropSet trace, eye;
        traceProps(s, 4.0, trace, eye);
        const Drawn d = drawn(trace);
        for (const Edge& e : boxEdges(Vec3(-3, -1, -1), Vec3(3, 1, 1))) {
            bool violet = false;
            for (auto [it, end] = d.lines.equal_range(e); it != end; ++it)
                violet |= it->second.colour == rgbOf(StructureRole::KdNode);
            EXPECT_TRUE(violet) << structureLabel(kind);
        }
    }
}

TEST(StructureViews, TheSessionMakesTheOutlineOncePerStructure) {
    Session s;
    s.adopt(Session::prepare(twoSpheres(), AccelKind::Bvh, oneSpherePerLeaf()));
    const StructureOutline<3>* bvh = s.outline3D();
    ASSERT_NE(bvh, nullptr);
    EXPECT_EQ(s.outline2D(), nullptr);
    // Root and two leaves (one sphere each).
    EXPECT_EQ(bvh->nodes.size(), 3u);
    s.tracePixel(0, 0, 1, 1);
    for (std::size_t c = 0; c <= s.size(); ++c) {
        s.setCursor(c);
        EXPECT_EQ(s.outline3D(), bvh);
    }
    // A structure switch (the live controls', the tool bar's): a new outline, of the new kind.
    const SceneRef before = s.sceneRef();  // kept, so its memory is not reused
    s.adopt(Session::rebuild(before, AccelKind::Grid, {}));
    ASSERT_NE(s.outline3D(), nullptr);
    EXPECT_NE(s.outline3D(), bvh);
    EXPECT_TRUE(s.outline3D()->grid.has_value());
    EXPECT_TRUE(s.outline3D()->nodes.empty());
    // 2D: the same, from the 2D outline.
    Scene2D flat;
    flat.name = "one circle";
    flat.circles.push_back({Vec2(0.5, 0.5), 0.25});
    s.adopt(Session::prepare(flat, AccelKind::KdTree));
    EXPECT_EQ(s.outline3D(), nullptr);
    const StructureOutline<2>* kd = s.outline2D();
    ASSERT_NE(kd, nullptr);
    EXPECT_EQ(kd->kind, AccelKind::KdTree);
    s.setCursor(0);
    EXPECT_EQ(s.outline2D(), kd);
}

}  // namespace
}  // namespace raystep::gui
