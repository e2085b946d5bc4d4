#include "raystep/render/tracer.h"

#include "raystep/render/shading.h"

#include <cmath>

namespace raystep {

Vec3 spawnRayOrigin(const SurfacePoint& sp, const Vec3& n, const Vec3& w, Precision precision,
                    RayOffsetMethod method) {
    if (method == RayOffsetMethod::Epsilon)
        return sp.p + (glm::dot(w, n) < 0.0 ? -kFixedRayEpsilon : kFixedRayEpsilon) * n;
    // In the precision the next ray will be tested in: its rounding is what must be cleared.
    if (precision == Precision::Float) {
        const PointWithError<float> pe{glm::vec3(sp.p), glm::vec3(sp.error)};
        return Vec3(offsetRayOrigin<float>(pe, glm::vec3(n), glm::vec3(w)));
    }
    return offsetRayOrigin<double>({sp.p, sp.error}, n, w);
}

Color Tracer::trace(const Ray& ray, RayKind kind, int depth, Pcg32& rng,
                    RayCounters& counters) const {
    NullRecorder rec;
    return trace(ray, kind, depth, kNoId, false, rng, counters, rec);
}

namespace {
/// Records one weighted shading term (only when recording).
template <typename Rec>
void recordTerm(Rec& rec, std::uint32_t ray, ShadingTermKind term, std::uint32_t light,
                const Color& c) {
    if constexpr (Rec::kEnabled) rec(ShadingTerm{ray, term, light, {c.x, c.y, c.z}});
}
}  // namespace

template <typename Rec>
Color Tracer::trace(const Ray& ray, RayKind kind, int depth, std::uint32_t parent,
                    bool diffuseBranched, Pcg32& rng, RayCounters& counters, Rec& rec) const {
    ++counters[kind];
    const std::uint32_t rayId = rec.beginRay(ray, kind, depth, parent);
    std::optional<Hit> hit;
    if constexpr (Rec::kEnabled)
        hit = intersect(query_.recording(), ray, counters.traversal, rec, rayId);
    else
        hit = query_.intersect(ray, counters.traversal);
    if (!hit) {
        if constexpr (Rec::kEnabled) rec(RayMiss{rayId});
        return scene_.background;
    }
    if constexpr (Rec::kEnabled) rec(RayHit{rayId, hit->prim, hit->t, hit->u, hit->v});
    return shade(ray, rayId, *hit, depth, diffuseBranched, rng, counters, rec);
}

template <typename Rec>
Color Tracer::shade(const Ray& ray, std::uint32_t rayId, const Hit& hit, int depth,
                    bool diffuseBranched, Pcg32& rng, RayCounters& counters, Rec& rec) const {
    const Material& m = scene_.materialOf(hit.prim);
    const KernelOptions& kernels = query_.kernels();
    const SurfacePoint sp = scene_.surfacePoint(hit, ray, kernels.precision);
    const Vec3& p = sp.p;
    const Vec3 outward = scene_.normalAt(hit, p);
    const Vec3 d = glm::normalize(ray.dir);
    const bool entering = glm::dot(d, outward) < 0.0;
    const Vec3 n = entering ? outward : -outward;  // faces the incoming ray
    const Vec3 toViewer = -d;
    const Color kd = m.diffuseAt(p);
    const auto originFor = [&](const Vec3& dir) {
        return spawnRayOrigin(sp, n, dir, kernels.precision, settings_.rayOffset);
    };

    // Ambient stands in for indirect light; when diffuse bounces compute it, it must go.
    Color radiance = settings_.diffuseSamples > 0 ? Color(0.0) : scene_.ambient * kd;
    recordTerm(rec, rayId, ShadingTermKind::Ambient, kNoId, radiance);

    // Local model: a shadow ray per light, then Phong's diffuse and specular terms.
    for (std::uint32_t li = 0; li < scene_.lights.size(); ++li) {
        const PointLight& light = scene_.lights[li];
        Vec3 toLight = light.position - p;
        if (!(glm::length(toLight) > 0.0)) continue;
        toLight = glm::normalize(toLight);
        if (glm::dot(n, toLight) <= 0.0) continue;  // light behind the surface: no ray needed
        const Vec3 origin = originFor(toLight);
        const double dist = glm::length(light.position - origin);
        ++counters[RayKind::Shadow];
        const Ray shadow{origin, toLight, 0.0, dist};
        const std::uint32_t shadowId = rec.beginRay(shadow, RayKind::Shadow, depth + 1, rayId);
        std::size_t shadowFrom = 0;  // the shadow ray's first event after its RayBegin
        if constexpr (Rec::kEnabled) shadowFrom = rec.events().size();
        bool blocked = false;
        if constexpr (Rec::kEnabled)
            blocked = occluded(query_.recording(), shadow, counters.traversal, rec, shadowId);
        else
            blocked = query_.occluded(shadow, counters.traversal);
        if (blocked) {
            if constexpr (Rec::kEnabled)
                rec(blockedBy(rec.events(), shadowId, shadowFrom, rec.events().size()));
            continue;
        }
        if constexpr (Rec::kEnabled) rec(RayMiss{shadowId});
        const PhongTerms t = phong(n, toLight, toViewer, light.intensity, kd, m.ks, m.n);
        recordTerm(rec, rayId, ShadingTermKind::Diffuse, li, t.diffuse);
        recordTerm(rec, rayId, ShadingTermKind::Specular, li, t.specular);
        radiance += t.diffuse + t.specular;
    }

    if (depth >= settings_.bounces) return radiance;

    const auto traceChild = [&](const Vec3& dir, RayKind kind, bool branched) {
        return trace(Ray{originFor(dir), dir, 0.0, kInfinity}, kind, depth + 1, rayId, branched,
                     rng, counters, rec);
    };
    // Reflection ray: one ray in, one ray out.
    if (!isBlack(m.reflect)) {
        const Color c = m.reflect * traceChild(reflect(d, n), RayKind::Reflection, diffuseBranched);
        recordTerm(rec, rayId, ShadingTermKind::Reflected, kNoId, c);
        radiance += c;
    }
    // Transparency ray by Snell's law; past the critical angle all of it reflects.
    if (!isBlack(m.transparency)) {
        const double eta = entering ? 1.0 / m.ior : m.ior;
        Color c;
        if (const auto t = refract(d, n, eta))
            c = m.transparency * traceChild(*t, RayKind::Refraction, diffuseBranched);
        else
            c = m.transparency * traceChild(reflect(d, n), RayKind::Reflection, diffuseBranched);
        recordTerm(rec, rayId, ShadingTermKind::Transmitted, kNoId, c);
        radiance += c;
    }
    // Diffuse bounces: one ray in, infinitely many out, estimated with random directions.
    // Cosine-weighted directions make the estimate of the Lambertian integral kd * mean(L).
    if (settings_.diffuseSamples > 0 && !isBlack(kd)) {
        const int count = diffuseBranched ? 1 : settings_.diffuseSamples;
        Color sum(0.0);
        for (int i = 0; i < count; ++i) {
            const double u1 = rng.uniform();
            const double u2 = rng.uniform();
            sum += traceChild(cosineSampleHemisphere(n, u1, u2), RayKind::Diffuse, true);
        }
        const Color c = kd * sum / static_cast<double>(count);
        recordTerm(rec, rayId, ShadingTermKind::DiffuseBounce, kNoId, c);
        radiance += c;
    }
    return radiance;
}

Color Tracer::renderPixel(int x, int y, const RenderOptions& options, RayCounters& counters) const {
    NullRecorder rec;
    return pixel(x, y, options, counters, rec);
}

Color Tracer::renderPixel(int x, int y, const RenderOptions& options, RayCounters& counters,
                          EventLog& log) const {
    log.setDims(3);
    const Color c = pixel(x, y, options, counters, log);
    log(PixelResult{static_cast<std::uint32_t>(x),
                    static_cast<std::uint32_t>(y),
                    static_cast<std::uint32_t>(options.width),
                    static_cast<std::uint32_t>(options.height),
                    {c.x, c.y, c.z}});
    return c;
}

template <typename Rec>
void Tracer::samples(int x, int y, int from, int to, const RenderOptions& options, Pcg32& rng,
                     Color& sum, RayCounters& counters, Rec& rec) const {
    const Camera& cam = options.camera ? *options.camera : scene_.camera;
    const auto generateRay = [&](double px, double py) {
        return camera_ ? (*camera_)(px, py)
                       : cam.generateRay(px, py, options.width, options.height);
    };
    if (options.spp == 1) {
        if (from > 0 || to < 1) return;  // the one sample is sample 0
        sum += trace(generateRay(x + 0.5, y + 0.5), RayKind::Primary, 0, kNoId, false, rng,
                     counters, rec);
        return;
    }
    // Jittered sampling: the pixel is cut into a near-square grid of strata, one sample in each.
    const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(options.spp))));
    const int rows = (options.spp + cols - 1) / cols;
    for (int s = from; s < to; ++s) {
        const double jx = ((s % cols) + rng.uniform()) / cols;
        const double jy = ((s / cols) + rng.uniform()) / rows;
        sum += trace(generateRay(x + jx, y + jy), RayKind::Primary, 0, kNoId, false, rng, counters,
                     rec);
    }
}

void Tracer::addSamples(int x, int y, int from, int to, const RenderOptions& options, Pcg32& rng,
                        Color& sum, RayCounters& counters) const {
    NullRecorder rec;
    samples(x, y, from, to, options, rng, sum, counters, rec);
}

template <typename Rec>
Color Tracer::pixel(int x, int y, const RenderOptions& options, RayCounters& counters,
                    Rec& rec) const {
    const auto pixelIndex = static_cast<std::uint64_t>(y) * options.width + x;
    Pcg32 rng(options.seed, pixelIndex);
    Color sum(0.0);
    samples(x, y, 0, options.spp, options, rng, sum, counters, rec);
    return sum / static_cast<double>(options.spp);
}

Color tracePixelEvents(const Scene& scene, const Accelerator& accel, int x, int y, int width,
                       int height, EventLog& log) {
    RenderOptions opt;
    opt.width = width;
    opt.height = height;
    opt.trace.bounces = scene.settings.bounces;
    opt.trace.diffuseSamples = scene.settings.diffuseSamples;
    const Tracer tracer(scene, accel, opt.trace);
    RayCounters counters;
    return tracer.renderPixel(x, y, opt, counters, log);
}

Color tracePixelEvents(const Scene& scene, const Accelerator& accel, const Camera& camera,
                       const TraceSettings& settings, int x, int y, int width, int height,
                       EventLog& log) {
    RenderOptions opt;
    opt.width = width;
    opt.height = height;
    opt.trace = settings;
    opt.camera = camera;
    const Tracer tracer(scene, accel, opt.trace);
    RayCounters counters;
    return tracer.renderPixel(x, y, opt, counters, log);
}

}  // namespace raystep
