// raystep_accuracy: the accuracy side of the speed/accuracy trade (docs/accuracy.md).
// For every kernel and precision: the crack rate through shared edges and vertices of a closed
// mesh, the error of t against exact arithmetic, and shadow acne and light leaks across scene
// scales for each ray-offset strategy; and whole renders of the stadium scaled by 1e5.
// Usage: raystep_accuracy [--rays N] [--out FILE.json] [--images DIR]
#include "exact.h"

#include "raystep/accel/accel.h"
#include "raystep/base/rng.h"
#include "raystep/geometry/kernels.h"
#include "raystep/render/image.h"
#include "raystep/render/render.h"
#include "raystep/scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <string>

namespace {

using namespace raystep;
using D3 = glm::dvec3;
using nlohmann::ordered_json;

constexpr std::array kTriangleMethods = {TriangleMethod::Plane, TriangleMethod::MollerTrumbore,
                                         TriangleMethod::Watertight};
constexpr std::array kSphereMethods = {SphereMethod::Textbook, SphereMethod::Stable};
constexpr std::array kPrecisions = {Precision::Float, Precision::Double};

void progress(const std::string& what) {
    std::fprintf(stderr, "raystep_accuracy: %s\n", what.c_str());
}

D3 randomUnit(Pcg32& rng) {
    for (;;) {
        const D3 v(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1.0) return v / l;
    }
}

template <typename T>
bool hitsTriangle(TriangleMethod m, const D3& o, const D3& d, const D3& a, const D3& b,
                  const D3& c) {
    using V = TVec3<T>;
    return intersectTriangle<T>(m, V(o), V(d), V(a), V(b), V(c), T(0),
                                std::numeric_limits<T>::infinity())
        .has_value();
}

bool hitsTriangle(Precision p, TriangleMethod m, const D3& o, const D3& d, const D3& a, const D3& b,
                  const D3& c) {
    return p == Precision::Float ? hitsTriangle<float>(m, o, d, a, b, c)
                                 : hitsTriangle<double>(m, o, d, a, b, c);
}

// --------------------------------------------------------------------------------------------
// Crack rate

/// A closed mesh: an icosahedron subdivided twice (320 triangles) on a unit sphere, turned and
/// moved so that no coordinate is round.
struct Mesh {
    std::vector<D3> v;
    std::vector<std::array<int, 3>> f;
};

Mesh icosphere() {
    const double g = (1 + std::sqrt(5.0)) / 2;
    Mesh m;
    for (D3 p :
         {D3(-1, g, 0), D3(1, g, 0), D3(-1, -g, 0), D3(1, -g, 0), D3(0, -1, g), D3(0, 1, g),
          D3(0, -1, -g), D3(0, 1, -g), D3(g, 0, -1), D3(g, 0, 1), D3(-g, 0, -1), D3(-g, 0, 1)})
        m.v.push_back(glm::normalize(p));
    m.f = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
           {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
           {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < 2; ++level) {
        std::map<std::pair<int, int>, int> mid;
        const auto midpoint = [&](int i, int j) {
            const auto key = std::minmax(i, j);
            if (auto it = mid.find(key); it != mid.end()) return it->second;
            m.v.push_back(glm::normalize(m.v[i] + m.v[j]));
            return mid[key] = static_cast<int>(m.v.size() - 1);
        };
        std::vector<std::array<int, 3>> faces;
        for (const auto& f : m.f) {
            const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
            faces.insert(faces.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
        }
        m.f = faces;
    }
    const glm::dmat3 rot(D3(0.36, 0.48, -0.8), D3(-0.8, 0.6, 0.0), D3(0.48, 0.64, 0.6));
    for (D3& p : m.v) p = rot * p * 1.7 + D3(0.3131, -0.2717, 0.1913);
    return m;
}

ordered_json measureCracks(int rays) {
    const Mesh m = icosphere();
    const D3 centre(0.3131, -0.2717, 0.1913);
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    std::vector<std::vector<int>> vertexFaces(m.v.size());
    for (int fi = 0; fi < static_cast<int>(m.f.size()); ++fi)
        for (int k = 0; k < 3; ++k) {
            edgeFaces[std::minmax(m.f[fi][k], m.f[fi][(k + 1) % 3])].push_back(fi);
            vertexFaces[m.f[fi][k]].push_back(fi);
        }
    const std::vector<std::pair<std::pair<int, int>, std::vector<int>>> edges(edgeFaces.begin(),
                                                                              edgeFaces.end());
    const auto frontFacing = [&](const std::vector<int>& faces, const D3& o) {
        for (int fi : faces) {
            const auto& f = m.f[fi];
            if (glm::dot(glm::cross(m.v[f[1]] - m.v[f[0]], m.v[f[2]] - m.v[f[0]]), o - m.v[f[0]]) <=
                0)
                return false;
        }
        return true;
    };
    // counts[precision][method] = {edge cracks, vertex cracks}
    std::map<std::string, std::array<long, 2>> cracks;
    std::map<std::string, long> offSurface;  // rays that rounding moved off the mesh
    long edgeRays = 0, vertexRays = 0;
    Pcg32 rng(1234, 1);
    for (int i = 0; i < rays;) {
        const D3 o = centre + randomUnit(rng) * (1.7 * (2.0 + 8.0 * rng.uniform()));
        const bool vertex = i % 4 == 0;
        const std::vector<int>* faces;
        D3 target;
        if (vertex) {
            const int vi = static_cast<int>(rng.uniform() * m.v.size());
            faces = &vertexFaces[vi];
            target = m.v[vi];
        } else {
            const auto& e = edges[static_cast<std::size_t>(rng.uniform() * edges.size())];
            faces = &e.second;
            target = m.v[e.first.first] +
                     (0.02 + 0.96 * rng.uniform()) * (m.v[e.first.second] - m.v[e.first.first]);
        }
        if (!frontFacing(*faces, o)) continue;  // the ray must enter the solid right there
        ++i;
        (vertex ? vertexRays : edgeRays)++;
        const D3 d = target - o;
        const auto hitsAny = [&](Precision p, TriangleMethod tm, const std::vector<int>& set) {
            for (int fi : set) {
                const auto& f = m.f[fi];
                if (hitsTriangle(p, tm, o, d, m.v[f[0]], m.v[f[1]], m.v[f[2]])) return true;
            }
            return false;
        };
        for (Precision p : kPrecisions)
            for (TriangleMethod tm : kTriangleMethods) {
                if (hitsAny(p, tm, *faces)) continue;
                // Rounding the ray to float can move it off a face seen nearly edge-on onto the
                // next one: that is a hit on the surface, not a crack. Look one ring further.
                std::vector<int> ring;
                for (int fi : *faces)
                    for (int k = 0; k < 3; ++k)
                        ring.insert(ring.end(), vertexFaces[m.f[fi][k]].begin(),
                                    vertexFaces[m.f[fi][k]].end());
                if (hitsAny(p, tm, ring)) continue;
                // A crack only if the ray the kernel saw (rounded to its precision) truly meets
                // the surface there: near a silhouette, rounding can move it off the mesh.
                const bool f = p == Precision::Float;
                const D3 ro = f ? D3(glm::vec3(o)) : o, rd = f ? D3(glm::vec3(d)) : d;
                const auto exactlyHits = [&](const std::vector<int>& set) {
                    for (int fi : set) {
                        const auto& tri = m.f[fi];
                        const D3 a = f ? D3(glm::vec3(m.v[tri[0]])) : m.v[tri[0]];
                        const D3 b = f ? D3(glm::vec3(m.v[tri[1]])) : m.v[tri[1]];
                        const D3 c = f ? D3(glm::vec3(m.v[tri[2]])) : m.v[tri[2]];
                        if (exact::triangle(ro, rd, a, b, c).hit) return true;
                    }
                    return false;
                };
                if (exactlyHits(*faces) || exactlyHits(ring)) {
                    cracks[std::string(name(tm)) + "/" + std::string(name(p))][vertex]++;
                } else
                    ++offSurface[std::string(name(tm)) + "/" + std::string(name(p))];
            }
    }
    ordered_json out = ordered_json::array();
    for (Precision p : kPrecisions)
        for (TriangleMethod tm : kTriangleMethods) {
            const auto& c = cracks[std::string(name(tm)) + "/" + std::string(name(p))];
            out.push_back({{"method", name(tm)},
                           {"precision", name(p)},
                           {"edge_rays", edgeRays},
                           {"vertex_rays", vertexRays},
                           {"edge_misses", c[0]},
                           {"vertex_misses", c[1]},
                           {"crack_rate", double(c[0] + c[1]) / double(edgeRays + vertexRays)},
                           {"rays_rounded_off_the_mesh",
                            offSurface[std::string(name(tm)) + "/" + std::string(name(p))]}});
        }
    return out;
}

// --------------------------------------------------------------------------------------------
// Error of t against exact arithmetic

struct ErrorStats {
    std::vector<double> rel;
    long misses = 0;
    ordered_json json(long total) {
        std::sort(rel.begin(), rel.end());
        const auto q = [&](double f) {
            return rel.empty() ? 0.0 : rel[std::min(rel.size() - 1, std::size_t(f * rel.size()))];
        };
        return {{"rays", total},
                {"wrong_misses", misses},
                {"median_rel_error", q(0.5)},
                {"p99_rel_error", q(0.99)},
                {"max_rel_error", rel.empty() ? 0.0 : rel.back()}};
    }
};

template <typename T>
D3 roundTo(const D3& v) {
    return D3(TVec3<T>(v));
}

ordered_json measureTriangleT(int rays) {
    ordered_json out = ordered_json::array();
    for (double scale : {1e-3, 1.0, 1e3, 1e6}) {
        std::map<std::string, ErrorStats> stats;
        Pcg32 rng(77, static_cast<std::uint64_t>(std::log10(scale) + 20));
        const D3 offset = D3(3.1, -2.3, 5.7) * scale;
        for (int i = 0; i < rays; ++i) {
            const D3 a = offset + D3(rng.uniform(), rng.uniform(), rng.uniform()) * scale;
            const D3 b = offset + D3(rng.uniform(), rng.uniform(), rng.uniform()) * scale;
            const D3 c = offset + D3(rng.uniform(), rng.uniform(), rng.uniform()) * scale;
            // Aim well inside (weights >= 0.05), so every method should hit.
            double u = 0.05 + 0.9 * rng.uniform(), v = 0.05 + 0.9 * rng.uniform();
            if (u + v > 0.95) u = 0.95 - u * 0.5, v = 0.95 - v * 0.5;
            const D3 target = (1 - u - v) * a + u * b + v * c;
            const D3 o = target + randomUnit(rng) * scale * (0.5 + 4 * rng.uniform());
            const D3 d = (target - o) * (0.25 + 2 * rng.uniform());
            for (Precision p : kPrecisions) {
                const bool f = p == Precision::Float;
                const D3 ro = f ? roundTo<float>(o) : o, rd = f ? roundTo<float>(d) : d;
                const D3 ra = f ? roundTo<float>(a) : a, rb = f ? roundTo<float>(b) : b,
                         rc = f ? roundTo<float>(c) : c;
                const exact::Reference ref = exact::triangle(ro, rd, ra, rb, rc);
                if (!ref.hit) continue;
                for (TriangleMethod tm : kTriangleMethods) {
                    ErrorStats& s = stats[std::string(name(tm)) + "/" + std::string(name(p))];
                    double t;
                    bool hit;
                    if (f) {
                        const auto h = intersectTriangle<float>(tm, glm::vec3(ro), glm::vec3(rd),
                                                                glm::vec3(ra), glm::vec3(rb),
                                                                glm::vec3(rc), 0.f, INFINITY);
                        hit = h.has_value();
                        t = hit ? h->t : 0;
                    } else {
                        const auto h =
                            intersectTriangle<double>(tm, ro, rd, ra, rb, rc, 0.0, INFINITY);
                        hit = h.has_value();
                        t = hit ? h->t : 0;
                    }
                    if (!hit) {
                        ++s.misses;
                        continue;
                    }
                    s.rel.push_back(std::abs(t - ref.t) / ref.t);
                }
            }
        }
        for (Precision p : kPrecisions)
            for (TriangleMethod tm : kTriangleMethods) {
                ordered_json j =
                    stats[std::string(name(tm)) + "/" + std::string(name(p))].json(rays);
                j["method"] = name(tm);
                j["precision"] = name(p);
                j["scale"] = scale;
                out.push_back(j);
            }
    }
    return out;
}

ordered_json measureSphereT(int rays) {
    ordered_json out = ordered_json::array();
    for (int k = 0; k <= 8; ++k) {
        const double distance = std::pow(10.0, k);
        std::map<std::string, ErrorStats> stats;
        Pcg32 rng(55, static_cast<std::uint64_t>(k));
        for (int i = 0; i < rays; ++i) {
            // A unit sphere `distance` away, the ray aimed within 0.9 radii of its centre.
            const D3 dir = randomUnit(rng);
            const D3 centre = dir * distance + D3(0.137, -0.291, 0.073);
            const D3 aim = centre + randomUnit(rng) * (0.9 * rng.uniform());
            const D3 o(0.0);
            const D3 d = aim - o;
            for (Precision p : kPrecisions) {
                const bool f = p == Precision::Float;
                const D3 rd = f ? roundTo<float>(d) : d, rc = f ? roundTo<float>(centre) : centre;
                const exact::Reference ref = exact::sphere(o, rd, rc, 1.0);
                if (!ref.hit) continue;
                for (SphereMethod sm : kSphereMethods) {
                    ErrorStats& s = stats[std::string(name(sm)) + "/" + std::string(name(p))];
                    std::optional<double> t;
                    if (f) {
                        if (auto h = intersectSphere<float>(sm, glm::vec3(o), glm::vec3(rd),
                                                            glm::vec3(rc), 1.f, 0.f, INFINITY))
                            t = *h;
                    } else {
                        t = intersectSphere<double>(sm, o, rd, rc, 1.0, 0.0, INFINITY);
                    }
                    if (!t) {
                        ++s.misses;
                        continue;
                    }
                    s.rel.push_back(std::abs(*t - ref.t) / ref.t);
                }
            }
        }
        for (Precision p : kPrecisions)
            for (SphereMethod sm : kSphereMethods) {
                ordered_json j =
                    stats[std::string(name(sm)) + "/" + std::string(name(p))].json(rays);
                j["method"] = name(sm);
                j["precision"] = name(p);
                j["distance"] = distance;
                out.push_back(j);
            }
    }
    return out;
}

// --------------------------------------------------------------------------------------------
// Shadow acne and light leaks across scales

/// A unit sphere resting on a floor, a light above, everything multiplied by `scale`.
Scene acneScene(double scale) {
    Scene s;
    s.materials.push_back(Material{});
    const double h = 20 * scale;
    s.triangles.push_back({D3(-h, 0, -h), D3(-h, 0, h), D3(h, 0, h), 0});
    s.triangles.push_back({D3(-h, 0, -h), D3(h, 0, h), D3(h, 0, -h), 0});
    s.spheres.push_back({D3(0, scale, 0), scale, 0});
    s.lights.push_back({D3(1.3, 7, 0.9) * scale, Color(1.0)});
    s.camera.eye = D3(0.5, 6, 5) * scale;
    s.camera.lookAt = D3(0.2, 0.3, 0.2) * scale;
    s.camera.fovDeg = 40;
    return s;
}

/// Exact visibility of the light from floor point q: does the segment q -> light miss the sphere?
/// Returns -1 when q is too close to the shadow's edge to call (the answer is not robust there).
int exactlyLit(const D3& q, const D3& light, const D3& centre, double r) {
    using B = exact::Big;
    const B dx = B(light.x) - B(q.x), dy = B(light.y) - B(q.y), dz = B(light.z) - B(q.z);
    const B fx = B(q.x) - B(centre.x), fy = B(q.y) - B(centre.y), fz = B(q.z) - B(centre.z);
    const B dd = dx * dx + dy * dy + dz * dz;
    B s = -(fx * dx + fy * dy + fz * dz) / dd;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    const B cx = fx + s * dx, cy = fy + s * dy, cz = fz + s * dz;
    const double dist = sqrt(cx * cx + cy * cy + cz * cz).convert_to<double>();
    if (std::abs(dist - r) < 1e-6 * r) return -1;
    return dist > r ? 1 : 0;
}

ordered_json measureAcne(int side) {
    ordered_json out = ordered_json::array();
    for (int k = -3; k <= 6; ++k) {
        const double scale = std::pow(10.0, k);
        const Scene scene = acneScene(scale);
        for (Precision p : kPrecisions)
            for (RayOffsetMethod om : {RayOffsetMethod::Epsilon, RayOffsetMethod::Robust}) {
                const KernelOptions kernels{p, SphereMethod::Stable, TriangleMethod::Watertight};
                const Accelerator accel = buildAccelerator(scene, AccelKind::BruteForce, kernels);
                long lit = 0, shadowed = 0, acne = 0, leaks = 0;
                TraversalCounters counters;
                for (int y = 0; y < side; ++y)
                    for (int x = 0; x < side; ++x) {
                        const Ray ray = scene.camera.generateRay(x + 0.5, y + 0.5, side, side);
                        const auto hit = intersect(accel, ray, counters);
                        if (!hit) continue;
                        const SurfacePoint sp = scene.surfacePoint(*hit, ray, p);
                        D3 n = scene.normalAt(*hit, sp.p);
                        if (glm::dot(n, ray.dir) > 0) n = -n;
                        const D3 toLight = glm::normalize(scene.lights[0].position - sp.p);
                        if (glm::dot(n, toLight) <= 0) continue;
                        // Truth: spheres cannot shadow their own lit side; the floor is
                        // shadowed only by the sphere.
                        int truth = 1;
                        if (!scene.isSphere(hit->prim))
                            truth = exactlyLit(sp.p, scene.lights[0].position,
                                               scene.spheres[0].center, scene.spheres[0].radius);
                        if (truth < 0) continue;
                        const D3 origin = spawnRayOrigin(sp, n, toLight, p, om);
                        const double dist = glm::length(scene.lights[0].position - origin);
                        const bool blocked =
                            occluded(accel, Ray{origin, toLight, 0.0, dist}, counters);
                        if (truth == 1) {
                            ++lit;
                            acne += blocked;
                        } else {
                            ++shadowed;
                            leaks += !blocked;
                        }
                    }
                out.push_back({{"scale", scale},
                               {"precision", name(p)},
                               {"ray_offset", name(om)},
                               {"lit_points", lit},
                               {"shadowed_points", shadowed},
                               {"acne_share", lit ? double(acne) / lit : 0.0},
                               {"leak_share", shadowed ? double(leaks) / shadowed : 0.0}});
            }
    }
    return out;
}

// --------------------------------------------------------------------------------------------
// Whole renders: the stadium scaled by 1e5, float against double

ordered_json measureStadium(int width, int height, const std::string& imageDir) {
    const Scene base = loadBuiltinScene("stadium");
    struct Config {
        std::string key;
        double scale;
        D3 shift;
        Precision precision;
        RayOffsetMethod offset;
    };
    const D3 far(1e5, 0.0, 1e5);
    const std::vector<Config> configs = {
        {"double-x1", 1.0, D3(0.0), Precision::Double, RayOffsetMethod::Robust},
        {"float-x1", 1.0, D3(0.0), Precision::Float, RayOffsetMethod::Robust},
        {"double-x1e5", 1e5, D3(0.0), Precision::Double, RayOffsetMethod::Robust},
        {"float-x1e5", 1e5, D3(0.0), Precision::Float, RayOffsetMethod::Robust},
        {"float-x1e5-epsilon", 1e5, D3(0.0), Precision::Float, RayOffsetMethod::Epsilon},
        {"double-moved1e5", 1.0, far, Precision::Double, RayOffsetMethod::Robust},
        {"float-moved1e5", 1.0, far, Precision::Float, RayOffsetMethod::Robust},
    };
    std::map<std::string, std::vector<std::uint8_t>> images;
    for (const Config& c : configs) {
        progress("stadium " + c.key);
        const Scene s = transformScene(base, c.scale, c.shift);
        const Accelerator accel =
            buildAccelerator(s, AccelKind::BruteForce,
                             {c.precision, SphereMethod::Stable, TriangleMethod::Watertight});
        RenderOptions opt;
        opt.width = width;
        opt.height = height;
        opt.trace.bounces = s.settings.bounces;
        opt.trace.rayOffset = c.offset;
        images[c.key] = toSrgb8(render(s, accel, opt).image);
        if (!imageDir.empty())
            writePng(imageDir + "/accuracy-stadium-" + c.key + ".png", images[c.key], width,
                     height);
    }
    const auto compare = [&](const std::string& a, const std::string& b) {
        long differ = 0, differMuch = 0;
        const auto& A = images[a];
        const auto& B = images[b];
        for (std::size_t i = 0; i < A.size(); i += 3) {
            int m = 0;
            for (int k = 0; k < 3; ++k) m = std::max(m, std::abs(int(A[i + k]) - int(B[i + k])));
            differ += m > 0;
            differMuch += m > 16;
        }
        return ordered_json{{"a", a},
                            {"b", b},
                            {"pixels", A.size() / 3},
                            {"differ", differ},
                            {"differ_by_more_than_16", differMuch}};
    };
    ordered_json out = ordered_json::array();
    out.push_back(compare("double-x1", "float-x1"));
    out.push_back(compare("double-x1", "double-x1e5"));
    out.push_back(compare("double-x1e5", "float-x1e5"));
    out.push_back(compare("double-x1e5", "float-x1e5-epsilon"));
    out.push_back(compare("double-x1", "double-moved1e5"));
    out.push_back(compare("double-moved1e5", "float-moved1e5"));
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    int rays = 1000000;
    std::string outPath, imageDir;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--rays" && i + 1 < argc)
            rays = std::max(1000, std::atoi(argv[++i]));
        else if (arg == "--out" && i + 1 < argc)
            outPath = argv[++i];
        else if (arg == "--images" && i + 1 < argc)
            imageDir = argv[++i];
        else {
            std::fprintf(stderr,
                         "usage: raystep_accuracy [--rays N] [--out FILE.json] [--images DIR]\n");
            return 2;
        }
    }
    ordered_json j;
    progress("crack rate, " + std::to_string(rays) + " rays through edges and vertices");
    j["cracks"] = measureCracks(rays);
    progress("t error of triangles");
    j["triangle_t_error"] = measureTriangleT(std::max(1000, rays / 20));
    progress("t error of spheres");
    j["sphere_t_error"] = measureSphereT(std::max(1000, rays / 50));
    progress("shadow acne and leaks, scales 1e-3 to 1e6");
    j["acne"] = measureAcne(256);
    j["stadium"] = measureStadium(160, 120, imageDir);
    const std::string text = j.dump(2) + "\n";
    if (outPath.empty())
        std::cout << text;
    else
        writeFileAtomic(outPath, text);
    return 0;
}
