// Fails, naming file:line, when code under the given folder (app/) branches on a structure's kind
// or type (branch_check.h). The places in files named after --pending (another branch cleans
// them, not yet merged) are listed without failing.
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
    if (argc < 2) {
        std::cerr << "usage: check_app_branches ROOT FOLDER [--pending FILE...]\n";
        return 2;
    }
    const fs::path root = argv[1];
    std::vector<std::string> folders, pending;
    bool inPending = false;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--pending")
            inPending = true;
        else
            (inPending ? pending : folders).push_back(a);
    }
    std::vector<fs::path> files;
    for (const std::string& folder : folders)
        for (const auto& e : fs::recursive_directory_iterator(root / folder))
            if (e.is_regular_file() &&
                (e.path().extension() == ".h" || e.path().extension() == ".cpp"))
                files.push_back(e.path());
    std::sort(files.begin(), files.end());
    int failures = 0, waiting = 0;
    for (const fs::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        const std::string name = fs::relative(file, root).generic_string();
        const bool isPending = std::find(pending.begin(), pending.end(), name) != pending.end();
        for (const auto& b : raystep::checks::findBranches(text.str())) {
            (isPending ? std::cout : std::cerr)
                << name << ":" << b.line << ": " << (isPending ? "pending: " : "") << b.what << ": "
                << b.text << "\n";
            (isPending ? waiting : failures) += 1;
        }
    }
    if (waiting) std::cout << waiting << " place(s) in files another branch cleans (--pending)\n";
    if (failures) {
        std::cerr << failures
                  << " place(s) branch on a structure's kind or type: read its row in the "
                     "table (structure_info.h) or its outline (outline.h) instead\n";
        return 1;
    }
    std::cout << files.size() << " files checked: none branches on a structure's kind or type\n";
    return 0;
}
