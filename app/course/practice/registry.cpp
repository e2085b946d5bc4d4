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
             "da fuori; difficile: pareggi in un vertice della griglia"}}}},
         makeDda2D},
        {{"dda-3d",
          {"The 3D DDA: tDelta, tMax, the first cell and the walk",
           {{"it", "Il DDA in 3D: tDelta, tMax, la prima cella e il cammino"}}},
          {"easy: from inside, positive directions; medium: any direction, from outside too; "
           "hard: ties",
           {{"it",
             "facile: dall'interno, direzioni positive; medio: ogni direzione, anche da "
             "fuori; difficile: pareggi"}}}},
         makeDda3D},
    };
    return list;
}

}  // namespace raystep::practice
