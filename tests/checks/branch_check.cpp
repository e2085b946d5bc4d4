#include "branch_check.h"

#include <algorithm>
#include <cctype>
#include <regex>

namespace raystep::checks {

std::string codeOnly(std::string_view src) {
    std::string out(src);
    const auto blank = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to && k < out.size(); ++k)
            if (out[k] != '\n') out[k] = ' ';
    };
    const auto identChar = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    std::size_t i = 0;
    while (i < src.size()) {
        if (src.compare(i, 2, "//") == 0) {
            const std::size_t end = std::min(src.find('\n', i), src.size());
            blank(i, end);
            i = end;
        } else if (src.compare(i, 2, "/*") == 0) {
            const std::size_t close = src.find("*/", i + 2);
            const std::size_t end = close == std::string_view::npos ? src.size() : close + 2;
            blank(i, end);
            i = end;
        } else if (src[i] == 'R' && i + 1 < src.size() && src[i + 1] == '"' &&
                   (i == 0 || !identChar(src[i - 1]) || src[i - 1] == 'u' || src[i - 1] == 'L' ||
                    src[i - 1] == '8')) {
            // A raw string: R"delim( ... )delim".
            const std::size_t open = src.find('(', i + 2);
            if (open == std::string_view::npos) break;
            // Built by append: GCC 12 warns (-Wrestrict, falsely) on ")" + std::string(...).
            const std::string close =
                std::string(")").append(src.substr(i + 2, open - i - 2)).append("\"");
            const std::size_t at = src.find(close, open + 1);
            const std::size_t end = at == std::string_view::npos ? src.size() : at + close.size();
            blank(i + 2, end - 1);
            i = end;
        } else if (src[i] == '"' ||
                   (src[i] == '\'' &&
                    !(i > 0 && std::isxdigit(static_cast<unsigned char>(src[i - 1]))))) {
            // A string or character literal (a digit separator, 1'000, is neither).
            const char quote = src[i];
            std::size_t k = i + 1;
            while (k < src.size() && src[k] != quote && src[k] != '\n') k += src[k] == '\\' ? 2 : 1;
            blank(i + 1, std::min(k, src.size()));
            i = k + 1;
        } else {
            ++i;
        }
    }
    return out;
}

std::vector<Branch> findBranches(std::string_view source) {
    static const std::string types = "(UniformGridT?|KdTree3?|Bvh3?|BruteForceT?)";
    static const std::string ns = "(?:(?:raystep)?::)?";
    static const std::vector<std::pair<std::regex, std::string>> rules = {
        {std::regex("[=!]=\\s*" + ns + "AccelKind\\s*::"), "compares a kind"},
        {std::regex("\\bAccelKind\\s*::\\s*\\w+\\s*[=!]="), "compares a kind"},
        {std::regex("\\bcase\\s+" + ns + "AccelKind\\s*::"), "switches on a kind"},
        {std::regex("\\b(get_if|get|holds_alternative)\\s*<\\s*" + ns + types + "\\b"),
         "asks a structure's type"},
        {std::regex("\\b(UniformGridT|KdTree|Bvh|BruteForceT)\\s*<"), "names a structure's type"},
        {std::regex("(^|[^:\\w])(UniformGrid|KdTree3|Bvh3)\\b"), "names a structure's type"},
    };
    const std::string code = codeOnly(source);
    // Where each line starts, to turn an offset into a line number and its text.
    std::vector<std::size_t> starts{0};
    for (std::size_t k = 0; k < source.size(); ++k)
        if (source[k] == '\n') starts.push_back(k + 1);
    std::vector<std::pair<std::size_t, std::string>> found;  // (offset, what)
    for (const auto& [rule, what] : rules)
        for (auto it = std::sregex_iterator(code.begin(), code.end(), rule);
             it != std::sregex_iterator(); ++it)
            found.emplace_back(static_cast<std::size_t>(it->position()), what);
    std::sort(found.begin(), found.end());
    std::vector<Branch> out;
    for (const auto& [offset, what] : found) {
        // The line of the match's first non-space character (a match may start with a newline).
        std::size_t at = offset;
        while (at < code.size() && std::isspace(static_cast<unsigned char>(code[at]))) ++at;
        const std::size_t line = static_cast<std::size_t>(
            std::upper_bound(starts.begin(), starts.end(), at) - starts.begin());
        if (!out.empty() && out.back().line == line) continue;  // one report per line
        const std::size_t from = starts[line - 1];
        const std::size_t to = std::min(source.find('\n', from), source.size());
        std::string text(source.substr(from, to - from));
        text.erase(0, text.find_first_not_of(" \t"));
        out.push_back({line, what, text});
    }
    return out;
}

}  // namespace raystep::checks
