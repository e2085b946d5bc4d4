// The practice topics, in the lecture's order: a new topic is one generator file and one entry.
#include "course/practice/generator.h"

namespace raystep::practice {

const std::vector<Generator>& generators() {
    static const std::vector<Generator> list = {
        {{"dda-2d",
          {"The 2D DDA: tDelta, tMax, the first cell and the walk",
           {{"it", "Il DDA in 2D: tDelta, tMax, la prima cella e il cammino"}}},
          {"easy: a ray from inside, towards +x and +y; medium: any direction, from outside too; "
           "hard: ties through a grid vertex",
           {{"it",
             "facile: un raggio dall'interno, verso +x e +y; medio: ogni direzione, anche "
             "da fuori; difficile: casi di parità (tMax uguali) in un vertice della griglia"}}}},
         makeDda2D},
        {{"dda-3d",
          {"The 3D DDA: tDelta, tMax, the first cell and the walk",
           {{"it", "Il DDA in 3D: tDelta, tMax, la prima cella e il cammino"}}},
          {"easy: from inside, positive directions; medium: any direction, from outside too; "
           "hard: ties",
           {{"it",
             "facile: dall'interno, direzioni positive; medio: ogni direzione, anche da "
             "fuori; difficile: casi di parità"}}}},
         makeDda3D},
        {{"mailbox",
          {"Mailboxing: the primitive tests a grid walk makes without and with a mailbox",
           {{"it",
             "Mailboxing: i test con le primitive di un attraversamento della griglia senza e "
             "con il mailboxing"}}},
          {"easy: one primitive over two cells; medium: several primitives; hard: the ray hits "
           "a primitive beyond the cell that first tests it, and the walk stops early",
           {{"it",
             "facile: una primitiva su due celle; medio: più primitive; difficile: il raggio "
             "colpisce una primitiva oltre la cella che la testa per prima, e l'attraversamento "
             "si ferma prima"}}}},
         makeMailbox},
        {{"kdtree",
          {"Building a kd-tree: P(L|C), P(R|C), the SAH cost, the cheapest plane, TestTree",
           {{"it",
             "Costruire un kd-tree: P(L|C), P(R|C), il costo SAH, il piano migliore, TestTree"}}},
          {"easy: one plane of the root, both sides full; medium: also the cheapest of three "
           "planes and the nodes TestTree enters; hard: the plane in a child of the root, "
           "cutting off empty space (the empty bonus)",
           {{"it",
             "facile: un piano della radice, con primitive da entrambe le parti; medio: anche il "
             "meno costoso di tre piani e i nodi in cui entra TestTree; difficile: il piano in un "
             "figlio della radice, che taglia via spazio vuoto (il bonus per lo spazio vuoto)"}}}},
         makeKdTree},
        {{"bvh",
          {"A ray through a BVH: the boxes it enters, in order, and the primitives it tests",
           {{"it",
             "Un raggio attraverso una BVH: le scatole in cui entra, in ordine, e le primitive "
             "che testa"}}},
          {"easy: a few boxes, no two siblings overlap; medium: overlapping boxes, a leaf "
           "entered whose primitives the ray misses; hard: more primitives, the ray enters both "
           "of two overlapping boxes",
           {{"it",
             "facile: poche scatole, nessuna coppia di fratelli si interseca; medio: scatole che "
             "si intersecano, una foglia in cui il raggio entra mancandone le primitive; "
             "difficile: più primitive, il raggio entra in entrambe le scatole di una coppia che "
             "si interseca"}}}},
         makeBvh},
        {{"ray-sphere",
          {"Ray-sphere intersection: B, C, the discriminant, hit or miss and t",
           {{"it", "Intersezione raggio-sfera: B, C, il discriminante, colpisce o manca e t"}}},
          {"easy: from outside, a perfect square discriminant; medium: any discriminant, misses "
           "too; hard: from inside the sphere, and a sphere behind the ray",
           {{"it",
             "facile: da fuori, un discriminante quadrato perfetto; medio: ogni discriminante, "
             "anche raggi che mancano la sfera; difficile: dall'interno della sfera, e una sfera "
             "dietro il raggio"}}}},
         makeRaySphere},
        {{"ray-triangle",
          {"Ray-triangle intersection: t, the barycentric u and v, hit or miss",
           {{"it",
             "Intersezione raggio-triangolo: t, le coordinate baricentriche u e v, colpisce o "
             "manca"}}},
          {"easy: a triangle in a plane z = k, short decimals; medium: any plane, points outside "
           "the triangle too; hard: the plane behind the origin, u + v just above 1",
           {{"it",
             "facile: un triangolo in un piano z = k, decimali brevi; medio: ogni piano, anche "
             "punti esterni al triangolo; difficile: il piano dietro l'origine, u + v appena "
             "sopra 1"}}}},
         makeRayTriangle},
        {{"phong",
          {"Phong shading at a hit point: n.l, the diffuse term, r.v and the specular term",
           {{"it",
             "Lo shading di Phong in un punto colpito: n.l, il termine diffuso, r.v e il termine "
             "speculare"}}},
          {"easy: the diffuse term, the light in front; medium: the specular term too; hard: the "
           "light behind the surface, or the mirrored light turned away from the eye",
           {{"it",
             "facile: il termine diffuso, la luce davanti; medio: anche il termine speculare; "
             "difficile: la luce dietro la superficie, o la luce riflessa che si allontana "
             "dall'occhio"}}}},
         makePhong},
        {{"ray-tree",
          {"The ray tree: how many shadow, reflection and refraction rays one pixel traces",
           {{"it",
             "L'albero dei raggi: quanti raggi d'ombra, riflessi e rifratti traccia un pixel"}}},
          {"easy: one or two spheres, one light, bounces 1 or 2; medium: glass in front, "
           "bounces 2 or 3; hard: glass in front and a mirror, two lights, bounces 3 or 4",
           {{"it",
             "facile: una o due sfere, una luce, `bounces` = 1 o 2; medio: il vetro davanti, "
             "`bounces` = 2 o 3; difficile: il vetro davanti e uno specchio, due luci, "
             "`bounces` = 3 o 4"}}}},
         makeRayTree},
    };
    return list;
}

}  // namespace raystep::practice
