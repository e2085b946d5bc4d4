// Raystep's own run of a student's ray: the exact DDA walk, or a structure's recorded events, as
// the units (cells, nodes) the comparison goes through.
#include "raystep/accel/outline.h"
#include "raystep/assess/assess.h"
#include "raystep/assess/divergence.h"

#include <algorithm>

namespace raystep {

namespace {

using Kind = ReferenceUnit::Kind;

template <int N>
ReferenceRay ddaReference(const GridSpec<3, double>& grid3, const StudentRay& ray) {
    const auto [grid, o, d] = assess_detail::onGrid<N>(grid3, ray);
    ReferenceRay ref;
    ref.dims = N;
    ref.cells = true;
    Dda<N, double> dda(grid, o, d);
    for (int a = 0; a < N; ++a) {
        ref.step[a] = dda.step()[a];
        ref.tDelta[a] = dda.tDelta()[a];
    }
    ref.entersGrid = dda.valid();
    ref.tEnter = dda.tEnter();
    ref.tGridExit = dda.tGridExit();
    for (bool more = dda.valid(); more; more = dda.next()) {
        ReferenceUnit u;
        u.kind = Kind::Cell;
        for (int a = 0; a < N; ++a) {
            u.cell[a] = dda.cell()[a];
            u.tMax[a] = dda.tMax()[a];
        }
        u.axes = dda.axesTaken();
        u.tNear = dda.tEnter();
        u.tFar = dda.tCellExit();
        ref.units.push_back(u);
    }
    return ref;
}

ReferenceRay fromLog(const EventLog& log, int dims) {
    ReferenceRay ref;
    ref.dims = dims;
    ref.cells = false;
    const auto unit = [&]() -> ReferenceUnit& {
        if (ref.units.empty()) ref.units.push_back({});
        return ref.units.back();
    };
    for (const Event& e : log.events()) {
        if (const auto* s = std::get_if<DdaSetup>(&e)) {
            ref.cells = true;
            ref.entersGrid = true;
            for (int a = 0; a < dims; ++a) {
                ref.step[a] = s->step[a];
                ref.tDelta[a] = s->tDelta[a];
            }
            ref.tEnter = s->tEnter;
            ref.tGridExit = s->tGridExit;
        } else if (const auto* c = std::get_if<DdaCell>(&e)) {
            ref.cells = true;
            ReferenceUnit u;
            u.kind = Kind::Cell;
            for (int a = 0; a < dims; ++a) {
                u.cell[a] = c->cell[a];
                u.tMax[a] = c->tMax[a];
            }
            u.axes = c->axes;
            u.tNear = ref.units.empty() || ref.units.back().kind != Kind::Cell
                          ? ref.tEnter
                          : ref.units.back().tFar;
            u.tFar = ref.tGridExit;
            for (int a = 0; a < dims; ++a) u.tFar = std::min(u.tFar, u.tMax[a]);
            ref.units.push_back(u);
        } else if (const auto* n = std::get_if<NodeEnter>(&e)) {
            ReferenceUnit u;
            u.kind = Kind::Node;
            u.node = n->node;
            u.tNear = n->tNear;
            u.tFar = n->tFar;
            ref.units.push_back(u);
        } else if (const auto* k = std::get_if<NodeSkip>(&e)) {
            ref.skips.push_back(*k);
        } else if (const auto* t = std::get_if<PrimitiveTest>(&e)) {
            unit().tests.push_back(t->prim);
            if (t->hit) unit().hits.push_back({t->prim, t->t});
        } else if (const auto* m = std::get_if<MailboxSkip>(&e)) {
            unit().skipped.push_back(m->prim);
        } else if (const auto* h = std::get_if<RayHit>(&e)) {
            ref.hit = true;
            ref.prim = h->prim;
            ref.t = h->t;
        }
    }
    return ref;
}

template <int N>
std::vector<ReferenceNode> treeNodes(const StructureOutline<N>& o) {
    std::vector<ReferenceNode> nodes(o.nodes.size());
    for (std::size_t i = 0; i < o.nodes.size(); ++i) {
        const auto& n = o.nodes[i];
        nodes[i].parent = n.parent;
        nodes[i].children = n.children;
        nodes[i].axis = n.axis;
        nodes[i].leaf = n.leaf;
        if (n.plane) nodes[i].split = o.planes[*n.plane].position;
    }
    return nodes;
}

template <int N>
GridSpec<3, double> widen(const GridSpec<N, double>& g) {
    GridSpec<3, double> w;
    for (int a = 0; a < N; ++a) {
        w.lo[a] = g.lo[a];
        w.hi[a] = g.hi[a];
        w.res[a] = g.res[a];
    }
    return w;
}

}  // namespace

int ReferenceRay::walkCount() const {
    int n = 0;
    for (const auto& u : units) n += u.kind != ReferenceUnit::Kind::None;
    return n;
}

Reference Reference::dda(const GridSpec<3, double>& grid, int dims) {
    Reference r;
    r.dims_ = dims;
    r.kind_ = AccelKind::Grid;
    r.grid_ = grid;
    return r;
}

Reference Reference::structure(const AnyStructure& structure, AccelKind kind) {
    Reference r;
    r.structure_ = &structure;
    r.kind_ = kind;
    if (structure.in2D) {
        r.dims_ = 2;
        const auto o = outline(*structure.in2D);
        r.nodes_ = treeNodes(o);
        if (o.grid) r.grid_ = widen(o.grid->spec);
    } else {
        r.dims_ = 3;
        const auto o = outline(*structure.in3D);
        r.nodes_ = treeNodes(o);
        if (o.grid) r.grid_ = widen(o.grid->spec);
    }
    return r;
}

EventLog Reference::record(const StudentRay& ray) const {
    EventLog log;
    if (!structure_) return log;
    if (structure_->in2D) {
        Ray2 r;
        r.origin = {ray.origin[0], ray.origin[1]};
        r.dir = {ray.dir[0], ray.dir[1]};
        traceRay2D(*structure_->in2D, r, log);
    } else {
        Ray r;
        r.origin = {ray.origin[0], ray.origin[1], ray.origin[2]};
        r.dir = {ray.dir[0], ray.dir[1], ray.dir[2]};
        traceRay3D(*structure_->in3D, r, log);
    }
    return log;
}

ReferenceRay Reference::run(const StudentRay& ray) const {
    if (!structure_)
        return dims_ == 2 ? ddaReference<2>(*grid_, ray) : ddaReference<3>(*grid_, ray);
    return fromLog(record(ray), dims_);
}

}  // namespace raystep
