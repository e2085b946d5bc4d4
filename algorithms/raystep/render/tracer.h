#pragma once
// The lecture's algorithm: primary rays, local Phong model with a shadow ray per light,
// reflection and transparency rays, and Monte Carlo diffuse bounces (colour bleeding).
#include "raystep/accel/accel.h"
#include "raystep/base/rng.h"
#include "raystep/render/image.h"
#include "raystep/render/scene_query.h"
#include "raystep/scene/scene.h"

#include <array>
#include <functional>
#include <optional>

namespace raystep {

struct TraceSettings {
    int bounces = 5;         // depth of secondary rays: 0 = primary rays only (plus shadow rays)
    int diffuseSamples = 0;  // diffuse bounce rays at the first diffuse hit of a path; 0 = none
    RayOffsetMethod rayOffset = RayOffsetMethod::Robust;  // where secondary rays start
};

/// What an image is made with, in one pass (render()) or progressively (ProgressiveRender).
struct RenderOptions {
    int width = 640;
    int height = 480;
    int spp = 1;  // 1 = through the pixel centre; more = jittered strata over the pixel
    TraceSettings trace;
    int threads = 0;  // 0 = all cores
    std::uint64_t seed = 1;
    std::optional<Camera> camera;  // another camera than the scene's (the 3D view's)
    // Progressive passes (render.h): the first pass's block side (a power of two; 1 = no coarse
    // passes), and whether the samples then double 1, 2, 4 ... spp (else all spp in one pass).
    int firstBlock = 1;
    bool refine = false;
};

/// Everything one pixel (or one ray tree) cost.
struct RayCounters {
    std::array<std::uint64_t, kRayKindCount> rays{};  // indexed by RayKind
    TraversalCounters traversal;
    std::uint64_t& operator[](RayKind k) { return rays[static_cast<int>(k)]; }
    std::uint64_t operator[](RayKind k) const { return rays[static_cast<int>(k)]; }
    std::uint64_t totalRays() const {
        std::uint64_t n = 0;
        for (auto r : rays) n += r;
        return n;
    }
    RayCounters& operator+=(const RayCounters& o) {
        for (int i = 0; i < kRayKindCount; ++i) rays[i] += o.rays[i];
        traversal += o.traversal;
        return *this;
    }
};

/// Traces the ray tree of single rays; stateless apart from references, so threads share one.
class Tracer {
  public:
    /// `query` a teaching structure (what the recording overloads need) or the fast path.
    Tracer(const Scene& scene, SceneQuery query, TraceSettings settings)
        : scene_(scene), query_(query), settings_(settings) {}

    /// Radiance arriving along `ray` (a ray of `kind` at bounce `depth`).
    Color trace(const Ray& ray, RayKind kind, int depth, Pcg32& rng, RayCounters& counters) const;

    /// Adds samples [from, to) of pixel (x, y) to `sum`, drawn in order from `rng` (the pixel's
    /// own stream): the centre for 1 spp, else one jittered sample in each stratum of a
    /// near-square grid. Every render, in one pass or in many, samples a pixel through this.
    /// The camera and image size every later addSamples renders with, its frame computed once
    /// here rather than per ray (ProgressiveRender's options do not change during a render).
    void fixCamera(const Camera& camera, int width, int height) {
        camera_.emplace(camera, width, height);
    }
    void addSamples(int x, int y, int from, int to, const RenderOptions& options, Pcg32& rng,
                    Color& sum, RayCounters& counters) const;
    /// Radiance of pixel (x, y) averaged over `spp` samples, with that pixel's own random stream.
    Color renderPixel(int x, int y, const RenderOptions& options, RayCounters& counters) const;
    /// The same pixel with its whole ray tree recorded into `log`: every ray, DDA step, node,
    /// test, hit and shading term, then the pixel's colour. Same colour as renderPixel.
    Color renderPixel(int x, int y, const RenderOptions& options, RayCounters& counters,
                      EventLog& log) const;

  private:
    template <typename Rec>
    void samples(int x, int y, int from, int to, const RenderOptions& options, Pcg32& rng,
                 Color& sum, RayCounters& counters, Rec& rec) const;
    template <typename Rec>
    Color pixel(int x, int y, const RenderOptions& options, RayCounters& counters, Rec& rec) const;
    template <typename Rec>
    Color trace(const Ray& ray, RayKind kind, int depth, std::uint32_t parent, bool diffuseBranched,
                Pcg32& rng, RayCounters& counters, Rec& rec) const;
    template <typename Rec>
    Color shade(const Ray& ray, std::uint32_t rayId, const Hit& hit, int depth,
                bool diffuseBranched, Pcg32& rng, RayCounters& counters, Rec& rec) const;

    const Scene& scene_;
    SceneQuery query_;
    TraceSettings settings_;
    std::optional<CameraRays> camera_;  // fixCamera's
};

/// Records pixel (x, y) of a width x height image of the scene as its settings say (bounces,
/// diffuse samples; one sample through the pixel's centre): the app's click, the course's pixels.
Color tracePixelEvents(const Scene& scene, const Accelerator& accel, int x, int y, int width,
                       int height, EventLog& log);
/// The same pixel seen by another camera, with other trace settings (the app's own view).
Color tracePixelEvents(const Scene& scene, const Accelerator& accel, const Camera& camera,
                       const TraceSettings& settings, int x, int y, int width, int height,
                       EventLog& log);

/// Origin of a secondary ray leaving the surface point `sp` (unit normal n, either side) in
/// direction w: past the point's error box (robust) or a fixed 1e-4 along the normal (epsilon).
Vec3 spawnRayOrigin(const SurfacePoint& sp, const Vec3& n, const Vec3& w, Precision precision,
                    RayOffsetMethod method);

}  // namespace raystep
