// Fails, naming file:line, when a source file under the given folders breaks the layering
// (layer_check.h).
#include "layer_check.h"
#include "source_tree.h"

#include <filesystem>
#include <iostream>
#include <string>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: check_layers ROOT FOLDER...\n";
        return 2;
    }
    const fs::path root = argv[1];
    const auto files = raystep::checks::sourceFiles(root, {argv + 2, argv + argc});
    int failures = 0;
    for (const fs::path& file : files) {
        const std::string name = fs::relative(file, root).generic_string();
        for (const auto& v :
             raystep::checks::findLayerViolations(name, raystep::checks::readWhole(file))) {
            std::cerr << name << ":" << v.line << ": #include \"" << v.header << "\": " << v.rule
                      << "\n";
            ++failures;
        }
    }
    if (failures) {
        std::cerr << failures << " include(s) break the layering (docs/architecture.md, Layers)\n";
        return 1;
    }
    std::cout << files.size() << " files checked: the layering holds\n";
    return 0;
}
