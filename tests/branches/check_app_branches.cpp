// Fails, naming file:line, when code under the given folder (app/) branches on a structure's kind
// or type (branch_check.h).
#include "branch_check.h"

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
        std::cerr << "usage: check_app_branches ROOT FOLDER...\n";
        return 2;
    }
    const fs::path root = argv[1];
    const std::vector<std::string> folders(argv + 2, argv + argc);
    std::vector<fs::path> files;
    for (const std::string& folder : folders)
        for (const auto& e : fs::recursive_directory_iterator(root / folder))
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
        for (const auto& b : raystep::checks::findBranches(text.str())) {
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
