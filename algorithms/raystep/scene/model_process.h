#pragma once
// A model read by assimp in a child process (docs/reliability.md, "Models"): the importer
// program (raystep-import, app/cli/import_main.cpp) runs importModelTriangles under memory, CPU
// and stack limits and streams what it found to its parent through a pipe; the parent
// (importModel, model_import.h) waits for it with a wall-clock limit, reports its progress,
// kills it on a cancel, and reads its triangles back with the caps. Whatever ends it (a crash
// inside assimp, a limit, a kill) becomes one SceneError naming the model.
#include "raystep/scene/model_import.h"

#include <string>

namespace raystep::detail {

/// The importer program's name, found beside the running program.
constexpr const char* kImporterName = "raystep-import";

/// The importer beside the running program (/proc/self/exe's folder), or "" when there is none;
/// the environment's RAYSTEP_IMPORTER instead when set (tests give a misbehaving one).
std::string importerBesideThisProgram();

/// The importer program's whole work: `argv` as importModel passes it (the limits, the parent's
/// process id, the model's path); writes its answer on descriptor 3 (its standard output is
/// /dev/null: what assimp may print there is not an answer); returns the exit code.
int runImporter(int argc, char** argv);

}  // namespace raystep::detail
