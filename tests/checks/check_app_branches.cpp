// Fails, naming file:line, when code under the given folder (app/) branches on a structure's kind
// or type (branch_check.h).
#include "branch_check.h"
#include "source_tree.h"

#include <filesystem>
#include <iostream>
#include <string>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: check_app_branches ROOT FOLDER...\n";
        return 2;
    }
    const fs::path root = argv[1];
    const auto files = raystep::checks::sourceFiles(root, {argv + 2, argv + argc});
    int failures = 0;
    for (const fs::path& file : files) {
        const std::string name = fs::relative(file, root).generic_string();
        for (const auto& b : raystep::checks::findBranches(raystep::checks::readWhole(file))) {
            std::cerr << name << ":" << b.line << ": " << b.what << ": " << b.text << "\n";
            ++failures;
        }
    }
    if (failures) {
        std::cerr << failures
                  << " place(s) branch on a structure's kind or type: read its row in the "
                     "table (structure_info.h) or its outline (outline.h) instead\n";
        return 1;
    }
    std::cout << files.size() << " files checked: none branches on a structure's kind or type\n";
    return 0;
}
