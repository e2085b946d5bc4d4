// The one table of exercise kinds: a new kind is one more unit here (docs/architecture.md, "Add
// an exercise kind").
#include "course/exercises/kind_unit.h"

#include <stdexcept>

namespace raystep::exercises {

// The units, one file each (app/course/exercises/<kind>.cpp).
const ExerciseKindUnit& nextCellUnit();
const ExerciseKindUnit& valueUnit();
const ExerciseKindUnit& pickSplitUnit();
const ExerciseKindUnit& countUnit();
const ExerciseKindUnit& hitOrMissUnit();
const ExerciseKindUnit& choiceUnit();
const ExerciseKindUnit& sequenceUnit();
const ExerciseKindUnit& sweepPickUnit();
const ExerciseKindUnit& computeUnit();
const ExerciseKindUnit& overlapUnit();
const ExerciseKindUnit& spotBugUnit();

const std::vector<const ExerciseKindUnit*>& kindUnits() {
    // In the order of ExerciseKind: a key two kinds take is named after the first.
    static const std::vector<const ExerciseKindUnit*> units{
        &nextCellUnit(),  &valueUnit(),   &pickSplitUnit(), &countUnit(),
        &hitOrMissUnit(), &choiceUnit(),  &sequenceUnit(),  &sweepPickUnit(),
        &computeUnit(),   &overlapUnit(), &spotBugUnit()};
    return units;
}

const ExerciseKindUnit& unitOf(ExerciseKind kind) {
    for (const ExerciseKindUnit* u : kindUnits())
        if (u->kind() == kind) return *u;
    throw std::logic_error("no unit for exercise kind " + std::to_string(static_cast<int>(kind)));
}

}  // namespace raystep::exercises
