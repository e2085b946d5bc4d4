#pragma once
// The drawing pieces the 3D view's actors are made of (vtk_actors.cpp, vtk_scene_actors.cpp):
// palette colours, wide coloured lines, translucent faces, spheres. Internal to those files.
#include "course/palette.h"

#include "raystep/base/math.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace raystep::gui::vtkdraw {

/// A palette colour (course/palette.h, the one table) as VTK's cell colour.
struct Rgb {
    unsigned char c[3];
    explicit Rgb(const PaletteColour& p) : c{p.r, p.g, p.b} {}
    Rgb(unsigned char r, unsigned char g, unsigned char b) : c{r, g, b} {}
    operator const unsigned char*() const { return c; }
};

inline double maxComponent(const Color& c) {
    return std::max({c.x, c.y, c.z});
}

inline vtkSmartPointer<vtkActor> actorOf(vtkPolyData* poly, bool scalars) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    mapper->SetScalarVisibility(scalars);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

/// Coloured segments, drawn as wide lines in flat colour: lines of one pixel vanish on a
/// projector, and unlit lines keep the palette's colour exactly (what the legend names).
class Segments {
  public:
    Segments() { colours_->SetNumberOfComponents(3); }
    void add(const Vec3& a, const Vec3& b, const unsigned char* colour) {
        if (!(glm::length(b - a) > 0) || !std::isfinite(glm::length(b - a))) return;
        const vtkIdType ids[2] = {points_->InsertNextPoint(a.x, a.y, a.z),
                                  points_->InsertNextPoint(b.x, b.y, b.z)};
        lines_->InsertNextCell(2, ids);
        colours_->InsertNextTypedTuple(colour);
    }
    void box(const Vec3& lo, const Vec3& hi, const unsigned char* colour) {
        const auto corner = [&](int k) {
            return Vec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        };
        static const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                         {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        for (const auto& e : edges) add(corner(e[0]), corner(e[1]), colour);
    }
    void loop(const std::array<Vec3, 4>& c, const unsigned char* colour) {
        for (int k = 0; k < 4; ++k) add(c[k], c[(k + 1) % 4], colour);
    }
    /// A circle of radius r about `centre` in the plane spanned by unit vectors u, v.
    void circle(const Vec3& centre, double r, const Vec3& u, const Vec3& v,
                const unsigned char* colour) {
        constexpr int n = 48;
        for (int k = 0; k < n; ++k) {
            const double a0 = 2 * std::numbers::pi * k / n, a1 = 2 * std::numbers::pi * (k + 1) / n;
            add(centre + r * (std::cos(a0) * u + std::sin(a0) * v),
                centre + r * (std::cos(a1) * u + std::sin(a1) * v), colour);
        }
    }
    bool empty() const { return lines_->GetNumberOfCells() == 0; }
    /// Lines `pixels` wide whatever the zoom, shaded as tubes by VTK.
    vtkSmartPointer<vtkActor> tubes(double pixels) const {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points_);
        poly->SetLines(lines_);
        poly->GetCellData()->SetScalars(colours_);
        auto actor = actorOf(poly, true);
        actor->GetProperty()->SetLineWidth(pixels);
        actor->GetProperty()->SetRenderLinesAsTubes(true);
        actor->GetProperty()->LightingOff();
        return actor;
    }

    /// The same lines as a dark outline `pixels` wide, drawn flat under the tubes: a ray keeps
    /// its edge over a floor of its own colour (the red and yellow checker). Flat lines lie at
    /// the tube's axis, behind its near surface: the tube is drawn over its outline.
    vtkSmartPointer<vtkActor> outline(double pixels) const {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points_);
        poly->SetLines(lines_);
        auto actor = actorOf(poly, false);
        actor->GetProperty()->SetColor(0.08, 0.08, 0.1);
        actor->GetProperty()->SetLineWidth(pixels);
        actor->GetProperty()->LightingOff();
        return actor;
    }

  private:
    vtkNew<vtkPoints> points_;
    vtkNew<vtkCellArray> lines_;
    vtkNew<vtkUnsignedCharArray> colours_;
};

/// Translucent faces (voxels, planes, the image plane) of one colour and opacity.
class Faces {
  public:
    void quad(const std::array<Vec3, 4>& c) {
        vtkIdType ids[4];
        for (int k = 0; k < 4; ++k) ids[k] = points_->InsertNextPoint(c[k].x, c[k].y, c[k].z);
        polys_->InsertNextCell(4, ids);
    }
    void box(const Vec3& lo, const Vec3& hi) {
        for (int axis = 0; axis < 3; ++axis)
            for (const double at : {lo[axis], hi[axis]}) quad(planeCorners(lo, hi, axis, at));
    }
    /// The same six faces wound with their fronts outwards (planeCorners' turn about +axis),
    /// for an actor that culls fronts: only the far walls are drawn, behind what is inside.
    void boxOutwards(const Vec3& lo, const Vec3& hi) {
        for (int axis = 0; axis < 3; ++axis) {
            auto low = planeCorners(lo, hi, axis, lo[axis]);
            std::swap(low[1], low[3]);
            quad(low);
            quad(planeCorners(lo, hi, axis, hi[axis]));
        }
    }
    static std::array<Vec3, 4> planeCorners(const Vec3& lo, const Vec3& hi, int axis, double at) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::array<Vec3, 4> c;
        for (int k = 0; k < 4; ++k) {
            c[k][axis] = at;
            c[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
            c[k][v] = (k >= 2) ? hi[v] : lo[v];
        }
        return c;
    }
    bool empty() const { return polys_->GetNumberOfCells() == 0; }
    vtkSmartPointer<vtkActor> actor(const PaletteColour& colour, double opacity) const {
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points_);
        poly->SetPolys(polys_);
        auto a = actorOf(poly, false);
        a->GetProperty()->SetColor(colour.r / 255.0, colour.g / 255.0, colour.b / 255.0);
        a->GetProperty()->SetOpacity(opacity);
        a->GetProperty()->LightingOff();
        return a;
    }

  private:
    vtkNew<vtkPoints> points_;
    vtkNew<vtkCellArray> polys_;
};

inline vtkSmartPointer<vtkActor> sphereActor(const Vec3& centre, double radius, int resolution) {
    vtkNew<vtkSphereSource> src;
    src->SetCenter(centre.x, centre.y, centre.z);
    src->SetRadius(radius);
    src->SetThetaResolution(2 * resolution);
    src->SetPhiResolution(resolution);
    src->Update();
    return actorOf(src->GetOutput(), false);
}

}  // namespace raystep::gui::vtkdraw
