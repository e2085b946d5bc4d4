// Fails, naming file:line, when a source file under the given folders breaks the layering
// (layer_check.h).
#include "layer_check.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: check_layers ROOT FOLDER...\n";
        return 2;
    }
    const fs::path root = argv[1];
    std::vector<fs::path> files;
    for (int i = 2; i < argc; ++i)
        for (const auto& e : fs::recursive_directory_iterator(root / argv[i]))
            if (e.is_regular_file() &&
                (e.path().extension() == ".h" || e.path().extension() == ".cpp"))
                files.push_back(e.path());
    std::sort(files.begin(), files.end());
    int failures = 0;
    for (const fs::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        const std::string name = fs::relative(file, root).generic_string();
        for (const auto& v : raystep::checks::findLayerViolations(name, text.str())) {
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
