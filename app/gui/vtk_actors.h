#pragma once
// What the 3D view puts in its VTK renderer, apart from the widget that hosts it (vtk_view.h):
// the scene as a rasterizer honestly draws it (materials, the scene's point lights, the checker
// as a texture), and the recorded trace at the cursor (rays as tubes, hits, the eye with its image
// plane and traced pixel, the structure's boxes, voxels and planes).
#include "session.h"

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

class vtkProp;
class vtkRenderer;

namespace raystep::gui {

/// Actors the view adds and removes as a group.
struct PropSet {
    std::vector<vtkSmartPointer<vtkProp>> props;
    void addTo(vtkRenderer* r) const;
    void removeFrom(vtkRenderer* r);
};

/// The scene's primitives (spheres and triangles grouped by material) and its point lights as
/// positional vtkLights; the light glyphs. Replaces every light of `r`.
PropSet sceneProps(vtkRenderer* r, const Scene& s);

/// The trace at the session's cursor: `eye` gets the eye, its frustum and the image plane (hidden
/// when the view looks from the eye); `trace` the rays (`linePx` wide), hits, structure and tested
/// primitives.
void traceProps(const Session& session, double linePx, PropSet& trace, PropSet& eye);

/// Points around what a lecture points at: the eye, the whole recorded ray tree, the spheres,
/// the grid's box and the parts of the larger geometry (floors, walls) near them.
std::vector<Vec3> pointsThatMatter(const Session& session);
/// Their bounding box.
Bounds3 boundsThatMatter(const Session& session);

/// Each primitive's centre (spheres first, then triangles: the ids the exercises name).
std::vector<Vec3> primitiveCentres(const Scene& s);

}  // namespace raystep::gui
