#include "raystep/json_lines.h"

namespace raystep {

JsonLineMap::JsonLineMap(std::string_view text) : s_(text) {
    skipSpace();
    if (i_ < s_.size()) value("");
}

int JsonLineMap::lineOf(const std::string& path) const {
    std::string p = path;
    while (!p.empty()) {
        if (auto it = lines_.find(p); it != lines_.end()) return it->second;
        const auto cut = p.find_last_of(".[");
        p = (cut == std::string::npos) ? std::string() : p.substr(0, cut);
    }
    return 1;
}

void JsonLineMap::skipSpace() {
    while (i_ < s_.size()) {
        const char c = s_[i_];
        if (c == '\n') {
            ++line_;
            ++i_;
        } else if (c == ' ' || c == '\t' || c == '\r') {
            ++i_;
        } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
            while (i_ < s_.size() && s_[i_] != '\n') ++i_;
        } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
            i_ += 2;
            while (i_ + 1 < s_.size() && !(s_[i_] == '*' && s_[i_ + 1] == '/')) {
                if (s_[i_] == '\n') ++line_;
                ++i_;
            }
            i_ += 2;
        } else {
            break;
        }
    }
}

std::string JsonLineMap::string() {
    std::string out;
    ++i_;  // opening quote
    while (i_ < s_.size() && s_[i_] != '"') {
        if (s_[i_] == '\\' && i_ + 1 < s_.size()) out += s_[i_++];
        out += s_[i_++];
    }
    ++i_;  // closing quote
    return out;
}

void JsonLineMap::value(const std::string& path) {
    skipSpace();
    if (i_ >= s_.size()) return;
    lines_.emplace(path, line_);  // a key's own line was recorded first and is kept
    const char c = s_[i_];
    if (c == '{') {
        ++i_;
        std::unordered_map<std::string, bool> seen;
        for (;;) {
            skipSpace();
            if (i_ >= s_.size() || s_[i_] == '}') break;
            if (s_[i_] == ',') {
                ++i_;
                continue;
            }
            const int keyLine = line_;
            const std::string key = string();
            const std::string childPath = child(path, key);
            if (!seen.emplace(key, true).second) duplicates_.emplace_back(childPath, keyLine);
            lines_.emplace(childPath, keyLine);
            skipSpace();
            ++i_;  // ':'
            value(childPath);
        }
        ++i_;
    } else if (c == '[') {
        ++i_;
        std::size_t index = 0;
        for (;;) {
            skipSpace();
            if (i_ >= s_.size() || s_[i_] == ']') break;
            if (s_[i_] == ',') {
                ++i_;
                continue;
            }
            value(element(path, index++));
        }
        ++i_;
    } else if (c == '"') {
        string();
    } else {
        // Number or literal: runs to the next delimiter.
        while (i_ < s_.size() && s_[i_] != ',' && s_[i_] != ']' && s_[i_] != '}' && s_[i_] != ' ' &&
               s_[i_] != '\n' && s_[i_] != '\t' && s_[i_] != '\r' && s_[i_] != '/')
            ++i_;
    }
}

}  // namespace raystep
