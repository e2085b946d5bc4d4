// Practice on the ray tree of Whitted's ray tracing (lecture: "Quanti rimbalzi?"): the centre
// pixel of a small scene whose spheres (mirror, glass, matte) all sit on the camera's axis, so
// every reflection and refraction ray runs along that axis (normal incidence: straight through
// glass, straight back off a mirror) and a student draws the tree on one line. How many shadow,
// reflection and refraction rays the pixel traces, and how many rays of one depth. easy: one or
// two spheres, one light, bounces 1 or 2; medium: glass in front, one or two lights, bounces 2
// or 3; hard: glass in front and a mirror, two lights, bounces 3 or 4.
#include "course/practice/generator.h"

#include <cmath>

namespace raystep::practice {

namespace {

enum class Mat { Mirror, Glass, Matte };

struct Ball {
    int z = 0;  // centre (0, 0, z), in whole units
    int r = 1;
    Mat mat = Mat::Matte;
};

struct TreeData {
    std::vector<Ball> balls;                 // front (nearest the eye) first
    std::vector<std::array<int, 3>> lights;  // point lights, off the axis
    int eye = 12;
    int bounces = 1;
};

const char* matName(Mat m) {
    return m == Mat::Mirror ? "mirror" : m == Mat::Glass ? "glass" : "matte";
}

TreeData drawTree(Random& r, PracticeLevel level) {
    const bool easy = level == PracticeLevel::Easy, hard = level == PracticeLevel::Hard;
    for (;;) {
        TreeData t;
        const int count = easy ? r.between(1, 2) : hard ? r.between(2, 3) : 2;
        // Spheres from the eye's side backwards, a gap of at least 1 between them.
        int front = r.between(3, 5);
        for (int i = 0; i < count; ++i) {
            Ball b;
            b.r = r.between(1, 2);
            b.z = front - b.r;
            front = b.z - b.r - r.between(1, 3);
            b.mat = r.pick(std::vector<Mat>{Mat::Mirror, Mat::Glass, Mat::Matte});
            t.balls.push_back(b);
        }
        const auto has = [&](Mat m) {
            for (const Ball& b : t.balls)
                if (b.mat == m) return true;
            return false;
        };
        if (!has(Mat::Glass) && !(easy && r.chance(40))) continue;
        if (hard && !has(Mat::Mirror)) continue;
        // From medium on the glass comes first: behind a mirror or a matte sphere it is hidden.
        if (!easy && t.balls.front().mat != Mat::Glass) continue;
        if (t.balls.front().mat == Mat::Matte) continue;  // a tree of one hit
        const int lights = easy ? 1 : hard ? 2 : r.between(1, 2);
        for (int i = 0; i < lights; ++i) {
            // Off the axis, its z at least 0.5 from every surface (whole numbers from surfaces
            // on whole numbers would tie: the light's z is a half).
            const int z2 = 2 * r.between(front - 1, t.balls.front().z + t.balls.front().r + 3) + 1;
            t.lights.push_back({r.between(3, 6) * r.sign(), r.between(2, 6), z2});
        }
        t.eye = t.balls.front().z + t.balls.front().r + r.between(5, 8);
        t.bounces = easy ? r.between(1, 2) : hard ? r.between(3, 4) : r.between(2, 3);
        return t;
    }
}

}  // namespace

Draft makeRayTree(Random& r, PracticeLevel level) {
    const TreeData t = drawTree(r, level);
    std::string ballsEn, ballsIt;
    ojson objects = ojson::array(), balls = ojson::array(), lights = ojson::array(),
          lightList = ojson::array();
    for (std::size_t i = 0; i < t.balls.size(); ++i) {
        const Ball& b = t.balls[i];
        const std::vector<double> c{0.0, 0.0, double(b.z)};
        objects.push_back({{"type", "sphere"},
                           {"center", jsonVec(c)},
                           {"radius", b.r},
                           {"material", matName(b.mat)}});
        balls.push_back({{"center", jsonVec(c)}, {"radius", b.r}, {"material", matName(b.mat)}});
        const std::string where = "`c = " + vec(c) + "`, `R = " + std::to_string(b.r) + "`";
        const char* en = b.mat == Mat::Mirror  ? "a mirror sphere"
                         : b.mat == Mat::Glass ? "a glass sphere"
                                               : "a matte sphere";
        const char* it = b.mat == Mat::Mirror  ? "una sfera a specchio"
                         : b.mat == Mat::Glass ? "una sfera di vetro"
                                               : "una sfera opaca";
        ballsEn += std::string("\n- ") + en + ", " + where + ";";
        ballsIt += std::string("\n- ") + it + ", " + where + ";";
    }
    ballsEn.back() = '.';
    ballsIt.back() = '.';
    std::string lightsEn, lightsIt;
    for (std::size_t i = 0; i < t.lights.size(); ++i) {
        const auto& L = t.lights[i];
        const std::vector<double> p{double(L[0]), double(L[1]), L[2] / 2.0};
        lights.push_back({{"position", jsonVec(p)}});
        lightList.push_back(jsonVec(p));
        const std::string s = "`" + vec(p) + "`";
        lightsEn += (i ? " and " : "") + s;
        lightsIt += (i ? " e " : "") + s;
    }
    const std::vector<double> eye{0.0, 0.0, double(t.eye)};
    ojson scene;
    scene["description"] = "practice: spheres on the camera's axis, a ray tree";
    scene["camera"] = {{"eye", jsonVec(eye)}, {"look_at", jsonVec({0.0, 0.0, 0.0})}};
    scene["render"] = {{"width", 33}, {"height", 25}, {"bounces", t.bounces}};
    scene["lights"] = lights;
    scene["materials"] = {
        {"mirror", {{"kd", 0.1}, {"reflect", 0.9}}},
        {"glass", {{"kd", 0.0}, {"reflect", 0.1}, {"transparency", 0.9}, {"ior", 1.5}}},
        {"matte", {{"kd", 0.8}}}};
    scene["objects"] = objects;

    const std::string en =
        "The camera at `eye = " + vec(eye) +
        "` looks at the origin; the pixel is the image's centre, so the primary ray runs down "
        "the z axis, towards -z. On that axis:" +
        ballsEn + "\n\nThe point light" + (t.lights.size() > 1 ? "s are at " : " is at ") +
        lightsEn + "; `bounces` is " + std::to_string(t.bounces) + ".";
    const std::string it =
        "La camera in `eye = " + vec(eye) +
        "` guarda l'origine; il pixel è il centro dell'immagine, quindi il raggio primario "
        "percorre l'asse z, verso -z. Su quell'asse:" +
        ballsIt + "\n\n" +
        (t.lights.size() > 1 ? "Le luci puntiformi sono in " : "La luce puntiforme è in ") +
        lightsIt + "; `bounces` vale " + std::to_string(t.bounces) + ".";
    const std::string rulesEn =
        " raystep's rules (lesson 3): at every hit, whatever its depth, a **shadow ray** to each "
        "light on the side the surface faces (the side the ray came from), blocked or not; then, "
        "if the hit's depth is below `bounces`, a **reflection ray** where the material "
        "reflects (the mirror; the glass too, with weight 0.1) and a **refraction ray** through "
        "glass. A ray's depth is its parent's plus one (the primary ray's is 0; a shadow ray's is "
        "its hit's plus one). Here every hit is head-on: a reflection goes straight back, a "
        "refraction straight on, and a ray that leaves the spheres behind meets nothing.";
    const std::string rulesIt =
        " Le regole di raystep (lezione 3): in ogni punto colpito, a qualunque profondità, un "
        "**raggio d'ombra** verso ogni luce dal lato verso cui è rivolta la superficie (il lato "
        "da cui arriva il raggio), bloccato o no; poi, se la profondità del punto è minore di "
        "`bounces`, un **raggio riflesso** se il materiale riflette (lo specchio; anche il vetro, "
        "con peso 0,1) e un **raggio rifratto** attraverso il vetro. La profondità di un raggio "
        "è quella del padre più uno (quella del raggio primario è 0; quella di un raggio d'ombra "
        "è quella del suo punto più uno). Qui ogni raggio colpisce le superfici "
        "perpendicolarmente: un raggio riflesso torna indietro lungo l'asse, uno rifratto "
        "prosegue dritto, e un raggio che si lascia alle spalle le sfere non incontra nulla.";

    Draft d;
    ojson& l = d.lesson;
    l["title"] = text("Practice: the ray tree", "Esercitazione: l'albero dei raggi");
    l["text"] = text(en + rulesEn + " Draw the tree by hand, then count.",
                     it + rulesIt + " Disegna l'albero a mano, poi conta.");
    l["scene"] = scene;
    l["setup"] = {{"accel", "bruteforce"}};
    l["trace"] = {{"pixel", {16, 12}}, {"image", {33, 25}}};
    l["views"] = {"3d"};

    bool glass = false;
    for (const Ball& b : t.balls) glass = glass || b.mat == Mat::Glass;
    const int depth = level == PracticeLevel::Easy ? 1 : r.between(1, 2);
    ojson ex = ojson::array();
    const auto count = [&](const std::string& id, const char* kind, const std::string& en2,
                           const std::string& it2) {
        ojson e = exercise(id, "count", text(en2, it2));
        e["count"] = "ray_begin";
        if (kind) e["ray_kind"] = kind;
        return e;
    };
    ojson shadow =
        count("shadow-rays", "shadow", "How many shadow rays does this pixel trace in all?",
              "Quanti raggi d'ombra vengono tracciati in tutto per questo pixel?");
    shadow["hint"] = hints(
        {text("List the hits of the tree first, with their depths; at each, which lights lie on "
              "the side the ray came from?",
              "Elenca prima i punti colpiti dell'albero, con la loro profondità; per ognuno, quali "
              "luci stanno dal lato da cui arriva il raggio?")});
    ex.push_back(shadow);
    ojson refl = count("reflection-rays", "reflection", "How many reflection rays does it trace?",
                       "Quanti raggi riflessi traccia?");
    refl["hint"] =
        hints({text("A hit on the mirror or on the glass below depth `bounces` sends one.",
                    "Un punto sullo specchio o sul vetro con profondità minore di "
                    "`bounces` ne lancia uno.")});
    ex.push_back(refl);
    if (glass) {
        ojson refr =
            count("refraction-rays", "refraction", "How many refraction rays does it trace?",
                  "Quanti raggi rifratti traccia?");
        refr["hint"] =
            hints({text("Every hit on the glass below depth `bounces` sends one, "
                        "from outside in and from inside out.",
                        "Ogni punto sul vetro con profondità minore di `bounces` ne "
                        "lancia uno, da fuori verso dentro e da dentro verso fuori.")});
        ex.push_back(refr);
    }
    ojson atDepth =
        count("depth-rays", nullptr,
              "How many rays of depth " + std::to_string(depth) +
                  " does it trace, of every kind (shadow rays too)?",
              "Quanti raggi di profondità " + std::to_string(depth) +
                  " vengono tracciati in tutto, di qualunque tipo (compresi quelli d'ombra)?");
    atDepth["ray_depth"] = depth;
    atDepth["hint"] =
        hints({text("Rays of depth " + std::to_string(depth) +
                        " leave the hits of the rays of depth " + std::to_string(depth - 1) + ".",
                    "I raggi di profondità " + std::to_string(depth) +
                        " partono dai punti colpiti dai raggi di profondità " +
                        std::to_string(depth - 1) + ".")});
    ex.push_back(atDepth);
    l["exercises"] = ex;

    d.given = {{"eye", jsonVec(eye)},  {"pixel", {16, 12}}, {"image", {33, 25}},
               {"bounces", t.bounces}, {"spheres", balls},  {"lights", lightList},
               {"depth", depth}};
    d.answers = [glass, depth](const Reference& ref) {
        ojson a = {{"shadowRays", static_cast<int>(ref.number("shadow-rays"))},
                   {"reflectionRays", static_cast<int>(ref.number("reflection-rays"))}};
        a["refractionRays"] =
            glass ? ojson(static_cast<int>(ref.number("refraction-rays"))) : ojson(0);
        a["raysAtDepth"] = {{"depth", depth},
                            {"count", static_cast<int>(ref.number("depth-rays"))}};
        return a;
    };
    // Trees a student draws by hand: every ray but the shadow rays on the axis, at most 24 rays.
    d.accept = [](const Reference& ref) {
        if (ref.number("depth-rays") == 0) return false;  // a depth the tree does not reach
        const auto& rays = ref.log().rays();
        for (const RayRecord& ray : rays)
            if (ray.kind != RayKind::Shadow &&
                (std::abs(ray.dir.x) > 1e-12 || std::abs(ray.dir.y) > 1e-12))
                return false;
        return rays.size() >= 3 && rays.size() <= 24;
    };
    return d;
}

}  // namespace raystep::practice
