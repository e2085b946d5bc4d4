#pragma once
// `raystep-cli intersect`: one ray against one triangle or sphere, with the intermediate
// quantities a student computes by hand, so homework can be checked.
#include <CLI/CLI.hpp>

#include <string>

namespace raystep::cli {

struct IntersectArgs {
    std::string ray;
    std::string triangle;
    std::string sphere;
    std::string method;
    std::string precision = "double";
    bool json = false;
};

void addIntersectCommand(CLI::App& app, IntersectArgs& args);
int runIntersect(const IntersectArgs& args);

}  // namespace raystep::cli
