// raystep-import: reads one model with assimp for raystep-cli and raystep, in a process of its
// own under limits (raystep/scene/model_process.h), so that a crash or a blow-up inside assimp
// ends this process only, and its parent says so in one line.
#include "raystep/scene/model_process.h"

int main(int argc, char** argv) {
    return raystep::detail::runImporter(argc, argv);
}
