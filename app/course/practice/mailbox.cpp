// Practice on mailboxing (lecture: "Quanti test di intersezione?", "Mailboxing"): a 2D ray walks
// a small uniform grid whose segments and circles are listed in every cell their bounding boxes
// overlap; how many primitive tests the walk makes without a mailbox, with one, and how many it
// saves. easy: one primitive over two cells of the walk; medium: several; hard: the ray hits a
// segment first tested in a cell the hit lies beyond, and the walk stops early, in the cell of
// the hit, before cells that list other primitives. The grid and ray are dda.cpp's draw.
#include "course/practice/grid_draw.h"

#include "raystep/accel/dda.h"
#include "raystep/scene/scene2d.h"

#include <optional>
#include <tuple>

namespace raystep::practice {

namespace {

/// A primitive in tenths of a cell from the grid's min: a segment a-b, or a circle of centre a
/// and radius r. Tenths keep every bounding box off the grid lines, so its cells are plain.
struct Prim {
    bool circle = false;
    std::array<long, 2> a{}, b{};
    long r = 0;
    std::array<int, 2> lo{}, hi{};  // the cells its bounding box overlaps, per axis
    bool hasCell(const std::array<int, 2>& c) const {
        return c[0] >= lo[0] && c[0] <= hi[0] && c[1] >= lo[1] && c[1] <= hi[1];
    }
};

/// The walk through the whole grid as raystep's DDA takes it, with each cell's far side.
struct Walk {
    std::vector<std::array<int, 2>> cells;
    std::vector<double> exits;
    bool readable = true;  // no two crossings within 0.05: the cells after a stop count too
};

Walk fullWalk(const DdaData<2>& g) {
    GridSpec<2, double> spec;
    for (int a = 0; a < 2; ++a) {
        spec.lo[a] = g.lo[a];
        spec.hi[a] = g.hi[a];
        spec.res[a] = g.res[a];
    }
    Walk w;
    Dda<2, double> dda(spec, VecN<2, double>(g.o[0], g.o[1]), VecN<2, double>(g.d[0], g.d[1]));
    for (bool more = dda.valid(); more; more = dda.next()) {
        w.cells.push_back({dda.cell()[0], dda.cell()[1]});
        w.exits.push_back(dda.tCellExit());
        const auto tMax = dda.tMax();
        w.readable = w.readable && !(std::abs(tMax[0] - tMax[1]) < 0.05);
    }
    return w;
}

/// Where a primitive is, in the scene's units.
struct Placed {
    const DdaData<2>& g;
    // In whole hundredths, divided once: the decimals a student reads (as dda.cpp draws them).
    long tenth() const { return std::lround(g.cell * 100) / 10; }
    double at(int axis, long tenths) const {
        return hundredths(std::lround(g.lo[axis] * 100) + tenths * tenth());
    }
    double length(long tenths) const { return hundredths(tenths * tenth()); }
    Vec2 point(const std::array<long, 2>& p) const { return {at(0, p[0]), at(1, p[1])}; }
    Ray2 ray() const { return Ray2{{g.o[0], g.o[1]}, {g.d[0], g.d[1]}}; }
};

bool boundsFit(Prim& p, const DdaData<2>& g) {
    for (int k = 0; k < 2; ++k) {
        const long lo = p.circle ? p.a[k] - p.r : std::min(p.a[k], p.b[k]);
        const long hi = p.circle ? p.a[k] + p.r : std::max(p.a[k], p.b[k]);
        // Off every grid line and inside the grid (its extent is the markers').
        if (lo <= 0 || hi >= 10L * g.res[k] || lo % 10 == 0 || hi % 10 == 0) return false;
        p.lo[k] = static_cast<int>(lo / 10);
        p.hi[k] = static_cast<int>(hi / 10);
    }
    return true;
}

/// A primitive whose bounding box covers exactly the cells lo..hi; a circle only over at most
/// two cells per axis.
std::optional<Prim> realise(Random& r, const DdaData<2>& g, std::array<int, 2> lo,
                            std::array<int, 2> hi, bool circle) {
    Prim p;
    p.circle = circle;
    if (circle) {
        p.r = r.between(2, 6);
        for (int k = 0; k < 2; ++k) {
            const int span = hi[k] - lo[k] + 1;
            if (span > 2) return std::nullopt;
            if (span == 1) {
                if (p.r > 4) return std::nullopt;
                p.a[k] =
                    10L * lo[k] + r.between(static_cast<int>(p.r) + 1, 9 - static_cast<int>(p.r));
            } else {
                // Across the line between the two cells, inside both.
                const int most = static_cast<int>(std::min(p.r - 1, 9 - p.r));
                p.a[k] = 10L * (lo[k] + 1) + r.between(-most, most);
            }
        }
    } else {
        for (int k = 0; k < 2; ++k) {
            p.a[k] = 10L * lo[k] + r.between(1, 9);
            p.b[k] = 10L * hi[k] + r.between(1, 9);
        }
        if (r.chance(50)) std::swap(p.a[1], p.b[1]);
        if (std::abs(p.a[0] - p.b[0]) + std::abs(p.a[1] - p.b[1]) < 4) return std::nullopt;
    }
    if (!boundsFit(p, g) || p.lo != lo || p.hi != hi) return std::nullopt;
    return p;
}

/// How the ray meets a primitive, with a margin a drawing by hand decides: a clear miss, a
/// clear hit (its t), or neither (too close to call).
struct Meeting {
    bool clear = false;
    std::optional<double> t;
};

Meeting meet(const Prim& p, const Placed& at) {
    const Ray2 ray = at.ray();
    const double margin = 0.1 * at.g.cell;
    Meeting m;
    if (p.circle) {
        const Circle2 c{at.point(p.a), at.length(p.r)};
        // Distance from the centre to the ray's line, against the radius.
        const Vec2 f = c.center - ray.origin;
        const double along = glm::dot(f, ray.dir) / glm::dot(ray.dir, ray.dir);
        const double dist = glm::length(f - along * ray.dir);
        m.clear = dist >= c.radius + margin;  // circles are only ever missed
        return m;
    }
    const Segment2 s{at.point(p.a), at.point(p.b)};
    const auto t = intersectSegment(ray, s);
    const Vec2 e = s.b - s.a;
    const double den = ray.dir.x * e.y - ray.dir.y * e.x;  // as intersectSegment: cross(d, e)
    // Parallel in the decimals (0.4 against 0.8 and 1, say), whatever the doubles' rounding.
    if (std::abs(den) <= 1e-9 * glm::length(ray.dir) * glm::length(e)) {
        const Vec2 f = s.a - ray.origin;
        const double along = glm::dot(f, ray.dir) / glm::dot(ray.dir, ray.dir);
        m.clear = glm::length(f - along * ray.dir) >= margin;
        return m;
    }
    // Where the lines cross: u along the segment (0 at a, 1 at b), tl along the ray.
    const Vec2 ao = s.a - ray.origin;
    const double u = (ao.x * ray.dir.y - ao.y * ray.dir.x) / den;
    const double tl = (ao.x * e.y - ao.y * e.x) / den;
    const double len = glm::length(e);
    const double speed = glm::length(ray.dir);
    if (t) {
        m.t = t;
        m.clear = u * len >= margin && (1 - u) * len >= margin && tl * speed >= margin;
    } else {
        const bool off = u * len <= -margin || (u - 1) * len >= margin;
        m.clear = off || tl * speed <= -margin;
    }
    return m;
}

std::string cellText(const std::array<int, 2>& c) {
    std::string out = "(";
    out += std::to_string(c[0]);
    out += ", ";
    out += std::to_string(c[1]);
    return out + ")";
}

std::string cellsText(const Prim& p, bool it) {
    std::vector<std::string> list;
    for (int y = p.lo[1]; y <= p.hi[1]; ++y)
        for (int x = p.lo[0]; x <= p.hi[0]; ++x) list.push_back(cellText({x, y}));
    std::string out;
    for (std::size_t i = 0; i < list.size(); ++i)
        out += (i == 0 ? "" : i + 1 == list.size() ? (it ? " e " : " and ") : ", ") + list[i];
    return out;
}

struct MailboxData {
    DdaData<2> g;
    std::vector<Prim> prims;  // circles first, then segments: raystep's ids from 2 on
    int target = -1;          // hard: the segment hit (its index in prims)
};

/// A block of walk cells i..j (j = i + 1 or i + 2): its cell range.
std::pair<std::array<int, 2>, std::array<int, 2>> block(const Walk& w, std::size_t i,
                                                        std::size_t j) {
    std::array<int, 2> lo = w.cells[i], hi = w.cells[i];
    for (std::size_t k = i; k <= j; ++k)
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], w.cells[k][a]);
            hi[a] = std::max(hi[a], w.cells[k][a]);
        }
    return {lo, hi};
}

std::optional<MailboxData> drawMailbox(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    MailboxData m;
    // dda.cpp's draw, without hard's ties: the point here is the tests, not the walk.
    const PracticeLevel gridLevel = easy ? PracticeLevel::Easy : PracticeLevel::Medium;
    m.g = drawDda<2>(r, gridLevel);
    while (oneSpeed(m.g) || !startFits(m.g, gridLevel)) m.g = drawDda<2>(r, gridLevel);
    const DdaData<2>& g = m.g;
    const Walk all = fullWalk(g);
    const Placed at{g};
    const auto corner = [&](const std::array<int, 2>& c) {
        return (c[0] == 0 && c[1] == 0) || (c[0] == g.res[0] - 1 && c[1] == g.res[1] - 1);
    };
    if (all.cells.size() < 3 || !all.readable) return std::nullopt;
    // hard: the walk stops at the cell of the target's hit, `stop`; the rest must list others.
    std::size_t stop = all.cells.size() - 1;
    if (hard) {
        if (all.cells.size() < 5) return std::nullopt;
        stop = static_cast<std::size_t>(r.between(2, static_cast<int>(all.cells.size()) - 2));
    }
    for (std::size_t k = 0; k <= stop; ++k)
        if (corner(all.cells[k])) return std::nullopt;  // a marker would be tested
    const int want = easy ? 1 : r.between(3, 4);
    std::vector<Prim> circles, segments;
    std::optional<Prim> target;
    for (int n = 0; n < want; ++n) {
        // The role: the target (hard, first), one listed after the stop (hard, second), one off
        // the walk (medium's last, now and then), or one over two or three cells of the walk.
        const bool isTarget = hard && n == 0, isAfter = hard && n == 1;
        const bool offWalk = !easy && !hard && n == want - 1 && r.chance(40);
        std::optional<Prim> p;
        for (int tries = 0; tries < 60 && !p; ++tries) {
            std::array<int, 2> lo{}, hi{};
            if (isTarget) {
                // First listed a cell or two before the stop, and through it.
                const int back = std::min<int>(static_cast<int>(stop), r.between(1, 2));
                std::tie(lo, hi) = block(all, stop - back, stop);
            } else if (isAfter) {
                const std::size_t i = static_cast<std::size_t>(
                    r.between(static_cast<int>(stop) + 1, static_cast<int>(all.cells.size()) - 1));
                lo = hi = all.cells[i];
                if (r.chance(60)) {
                    const int a = r.between(0, 1);
                    hi[a] = std::min(hi[a] + 1, g.res[a] - 1);
                    lo[a] = hi[a] == lo[a] ? std::max(lo[a] - 1, 0) : lo[a];
                }
            } else if (offWalk) {
                for (int a = 0; a < 2; ++a) {
                    lo[a] = r.between(0, g.res[a] - 1);
                    hi[a] = std::min(lo[a] + r.between(0, 1), g.res[a] - 1);
                }
                if (lo == hi) continue;
            } else {
                const int last = static_cast<int>(stop) - 1;
                const std::size_t i = static_cast<std::size_t>(r.between(0, last));
                const std::size_t j = std::min<std::size_t>(i + (easy ? 1 : r.between(1, 2)), stop);
                std::tie(lo, hi) = block(all, i, j);
            }
            const bool circle = !isTarget && r.chance(40);
            std::optional<Prim> q = realise(r, g, lo, hi, circle);
            if (!q) continue;
            const Meeting mt = meet(*q, at);
            if (!mt.clear) continue;
            if (isTarget != mt.t.has_value()) continue;
            if (isTarget) {
                // The hit lies in the stop cell, off its sides, and the target is listed in a
                // cell before it: the test there finds a hit beyond that cell.
                const double lo_t = stop == 0 ? 0.0 : all.exits[stop - 1];
                if (!(*mt.t > lo_t + 0.05 && *mt.t < all.exits[stop] - 0.05)) continue;
                if (!q->hasCell(all.cells[stop - 1])) continue;
            }
            std::size_t walked = 0, later = 0;
            for (std::size_t k = 0; k < all.cells.size(); ++k)
                if (q->hasCell(all.cells[k])) ++(k <= stop ? walked : later);
            if (isAfter && (walked != 0 || later == 0)) continue;
            if (offWalk && walked != 0) continue;
            // Each over cells of its own: two primitives with the same cells teach nothing more.
            const auto sameCells = [&](const Prim& o) { return o.lo == q->lo && o.hi == q->hi; };
            if (std::any_of(circles.begin(), circles.end(), sameCells) ||
                std::any_of(segments.begin(), segments.end(), sameCells) ||
                (target && sameCells(*target)))
                continue;
            if (!offWalk && !isAfter && walked < 2) continue;
            if (easy && (walked != 2 || (q->hi[0] - q->lo[0] + 1) * (q->hi[1] - q->lo[1] + 1) != 2))
                continue;
            p = q;
        }
        if (!p) return std::nullopt;
        if (isTarget)
            target = p;
        else
            (p->circle ? circles : segments).push_back(*p);
    }
    m.prims = circles;
    m.prims.insert(m.prims.end(), segments.begin(), segments.end());
    if (target) {
        m.target = static_cast<int>(m.prims.size());
        m.prims.push_back(*target);
    }
    return m;
}

}  // namespace

Draft makeMailbox(Random& r, PracticeLevel level) {
    std::optional<MailboxData> drawn;
    while (!(drawn = drawMailbox(r, level))) {
    }
    const MailboxData& m = *drawn;
    const DdaData<2>& g = m.g;
    const Placed at{g};
    const bool hard = level == PracticeLevel::Hard;

    std::string listEn, listIt;
    ojson scene = markers(g);
    ojson prims = ojson::array();
    for (std::size_t i = 0; i < m.prims.size(); ++i) {
        const Prim& p = m.prims[i];
        const int id = static_cast<int>(i) + 2;  // the two markers are circles 0 and 1
        const Vec2 a = at.point(p.a), b = at.point(p.b);
        ojson item = {{"id", id}, {"type", p.circle ? "circle" : "segment"}};
        std::string en, it;
        if (p.circle) {
            const double rad = at.length(p.r);
            scene["circles"].push_back({{"center", jsonVec({a.x, a.y})}, {"radius", rad}});
            item["center"] = jsonVec({a.x, a.y});
            item["radius"] = rad;
            en = "a circle of centre `" + vec({a.x, a.y}) + "` and radius `" + num(rad) + "`";
            it = "un cerchio di centro `" + vec({a.x, a.y}) + "` e raggio `" + num(rad) + "`";
        } else {
            if (!scene.contains("segments")) scene["segments"] = ojson::array();
            scene["segments"].push_back(
                {{"from", jsonVec({a.x, a.y})}, {"to", jsonVec({b.x, b.y})}});
            item["from"] = jsonVec({a.x, a.y});
            item["to"] = jsonVec({b.x, b.y});
            en = "a segment from `" + vec({a.x, a.y}) + "` to `" + vec({b.x, b.y}) + "`";
            it = "un segmento da `" + vec({a.x, a.y}) + "` a `" + vec({b.x, b.y}) + "`";
        }
        ojson cells = ojson::array();
        for (int y = p.lo[1]; y <= p.hi[1]; ++y)
            for (int x = p.lo[0]; x <= p.hi[0]; ++x) cells.push_back({x, y});
        item["cells"] = cells;
        prims.push_back(item);
        listEn += "\n- primitive " + std::to_string(id) + ", " + en +
                  ": its bounding box overlaps cells " + cellsText(p, false) + ";";
        listIt += "\n- primitiva " + std::to_string(id) + ", " + it +
                  ": il suo bounding box tocca le celle " + cellsText(p, true) + ";";
    }
    listEn.back() = '.';
    listIt.back() = '.';
    scene["description"] = "practice: a uniform grid, two corner circles and the primitives";

    const std::string en = gridWords(g, false), it = gridWords(g, true);
    Draft d;
    ojson& l = d.lesson;
    l["title"] = text("Practice: mailboxing", "Esercitazione: il mailboxing");
    const std::string stopEn =
        hard ? " The ray hits one of the primitives. As in lesson 6, every primitive a cell "
               "lists is tested, and the walk stops only after a cell whose far side lies "
               "beyond the nearest hit found so far (the hit lies inside the current cell): a "
               "hit found in a cell but lying beyond it does not stop the walk."
             : " The ray misses every primitive, so the walk goes on until it leaves the grid.";
    const std::string stopIt =
        hard ? " Il raggio colpisce una delle primitive. Come nella lezione 6, si testano tutte "
               "le primitive elencate in una cella, e l'attraversamento si ferma solo dopo una "
               "cella il cui lato lontano sta oltre l'intersezione più vicina trovata finora "
               "(l'intersezione cade dentro la cella corrente): un'intersezione trovata in una "
               "cella ma che cade oltre essa non ferma l'attraversamento."
             : " Il raggio manca tutte le primitive, quindi l'attraversamento continua finché "
               "esce dalla griglia.";
    l["text"] = text(
        en +
            " Each cell lists every primitive whose bounding box overlaps it (cells X,Y counted "
            "from 0 at min):" +
            listEn +
            "\n\nThe two small circles at the corners only mark the grid; the walk does not "
            "pass through their cells." +
            stopEn +
            " With a **mailbox** every primitive keeps the id of the last ray tested against it, "
            "and a test this ray already made is skipped. Work each count by hand: walk the "
            "DDA, then go through the cells' lists.",
        it +
            " Ogni cella elenca ogni primitiva il cui bounding box la tocca (celle X,Y contate "
            "da 0 a partire da min):" +
            listIt +
            "\n\nI due piccoli cerchi agli angoli segnano solo la griglia; l'attraversamento non "
            "passa per le loro celle." +
            stopIt +
            " Con il **mailboxing** ogni primitiva conserva l'ID dell'ultimo raggio con cui è "
            "stata testata, e un test già fatto da questo raggio viene saltato. Ricava ogni "
            "conteggio a mano: segui il DDA, poi scorri le liste delle celle.");
    l["scene"] = scene;
    l["setup"] = {{"accel", "grid"}, {"mailbox", true}, {"grid_res", {g.res[0], g.res[1]}}};
    l["trace"] = {{"ray", {g.o[0], g.o[1], g.d[0], g.d[1]}}};

    const ojson walkHint = text("First the walk: the cells the DDA visits" +
                                    std::string(hard ? ", up to the cell where it stops" : "") +
                                    ". Then, cell by cell, the primitives each one lists.",
                                "Prima l'attraversamento: le celle che il DDA visita" +
                                    std::string(hard ? ", fino alla cella in cui si ferma" : "") +
                                    ". Poi, cella per cella, le primitive che ognuna elenca.");
    ojson ex = ojson::array();
    ojson without = exercise(
        "tests-without", "count",
        text("Without a mailbox, how many ray-primitive intersection tests does the walk make?",
             "Senza mailboxing, quanti test di intersezione raggio-primitiva fa "
             "l'attraversamento?"));
    without["count"] = "primitive_test";
    without["setup"] = {{"mailbox", false}};
    without["hint"] = hints(
        {walkHint, text("Without a mailbox every cell of the walk tests every primitive it lists: "
                        "add up the lengths of the lists.",
                        "Senza mailboxing ogni cella dell'attraversamento testa ogni primitiva che "
                        "elenca: somma le lunghezze delle liste.")});
    ex.push_back(without);
    ojson with = exercise("tests-with", "count",
                          text("With the mailbox, how many tests are actually made?",
                               "Con il mailboxing, quanti test vengono effettivamente eseguiti?"));
    with["count"] = "primitive_test";
    with["hint"] = hints(
        {walkHint, text("Every primitive listed along the walk is tested exactly once, in the "
                        "first cell of the walk that lists it: count the different primitives.",
                        "Ogni primitiva elencata lungo l'attraversamento è testata esattamente "
                        "una volta, nella prima cella dell'attraversamento che la elenca: conta "
                        "le primitive distinte.")});
    ex.push_back(with);
    ojson saved = exercise("saved", "count",
                           text("How many tests does the mailbox save on this ray?",
                                "Quanti test fa risparmiare il mailboxing su questo raggio?"));
    saved["count"] = "mailbox_skip";
    saved["hint"] =
        hints({text("A primitive listed in k cells of the walk is tested once and skipped k - 1 "
                    "times.",
                    "Una primitiva elencata in k celle dell'attraversamento è testata una volta "
                    "e saltata k - 1 volte.")});
    ex.push_back(saved);
    l["exercises"] = ex;

    d.given = {{"grid", {g.res[0], g.res[1]}}, {"min", jsonVec(asVec(g.lo))},
               {"max", jsonVec(asVec(g.hi))},  {"origin", jsonVec(asVec(g.o))},
               {"dir", jsonVec(asVec(g.d))},   {"primitives", prims}};
    d.answers = [](const Reference& ref) {
        ojson walk = ojson::array();
        ojson hit = nullptr;
        for (const Event& e : ref.log().events()) {
            if (const auto* c = std::get_if<DdaCell>(&e)) walk.push_back({c->cell[0], c->cell[1]});
            if (const auto* h = std::get_if<RayHit>(&e)) hit = h->prim;
        }
        return ojson{{"testsWithout", static_cast<int>(ref.number("tests-without"))},
                     {"testsWith", static_cast<int>(ref.number("tests-with"))},
                     {"saved", static_cast<int>(ref.number("saved"))},
                     {"walk", walk},
                     {"hit", hit}};
    };
    const int target = m.target < 0 ? -1 : m.target + 2;
    d.accept = [level, target](const Reference& ref) {
        const WalkShape w = walkShape<2>(ref.log(), false);
        if (!w.readable || w.cells < 3 || w.cells > (level == PracticeLevel::Easy ? 6 : 8))
            return false;
        int hitPrim = -1;
        for (const Event& e : ref.log().events()) {
            if (const auto* t = std::get_if<PrimitiveTest>(&e); t && t->prim < 2) return false;
            if (const auto* h = std::get_if<RayHit>(&e)) hitPrim = static_cast<int>(h->prim);
        }
        if (hitPrim != target) return false;
        const int saved = static_cast<int>(ref.number("saved"));
        if (level == PracticeLevel::Easy) return saved == 1;
        return saved >= 2;
    };
    return d;
}

}  // namespace raystep::practice
