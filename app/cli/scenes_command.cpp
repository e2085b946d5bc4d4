// `raystep-cli scenes`: one line a built-in scene, its name, primitive count and description.
#include "scenes_command.h"

#include "raystep/scene/scene_loader.h"

#include <cstdio>
#include <string>
#include <vector>

namespace raystep::cli {

void addScenesCommand(CLI::App& app) {
    app.add_subcommand("scenes", "List the built-in scenes");
}

int listScenes() {
    std::vector<std::string> names = builtinSceneNames();
    for (const std::string& n : builtinScene2DNames()) names.push_back(n);
    for (const std::string& name : names) {
        std::visit(
            [&](const auto& s) {
                std::printf("%-15s %7u primitives  %s\n", name.c_str(), s.primitiveCount(),
                            s.description.c_str());
            },
            loadAnyScene(name));
    }
    return 0;
}

}  // namespace raystep::cli
