#pragma once
// The check that no code in app/ branches on a structure's kind or type again: what is specific
// to a structure is its row in the table (structure_info.h) and its outline (outline.h), read by
// every client, so a new structure is added in the core without touching the views.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace raystep::checks {

/// One place that branches on a structure: its line (from 1), what it does, the line's text.
struct Branch {
    std::size_t line = 0;
    std::string what;
    std::string text;
};

/// The branches in one source file's text: a comparison with a kind (`== AccelKind::`,
/// `!= AccelKind::`, either side), a `case AccelKind::`, a question of a structure's type
/// (`get_if`, `get` or `holds_alternative` of UniformGrid, KdTree, Bvh or BruteForce) or any
/// use of a structure's class template or alias (`UniformGridT<`, `KdTree<`, `Bvh<`,
/// `BruteForceT<`, `UniformGrid`, `KdTree3`, `Bvh3`). Comments and string literals are not code.
std::vector<Branch> findBranches(std::string_view source);

/// The text with comments and the insides of string and character literals blanked (newlines
/// kept, so offsets keep their line).
std::string codeOnly(std::string_view source);

}  // namespace raystep::checks
