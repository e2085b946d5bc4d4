#pragma once
// Where each key of a JSON text stands: nlohmann::json keeps no positions, and every error
// in a scene or lesson file must name its line. Paths look like "objects[2].radius".
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace raystep {

class JsonLineMap {
  public:
    /// `text` must already have parsed as JSON (comments allowed); the map only scans it.
    explicit JsonLineMap(std::string_view text);

    /// Line (1-based) of the key or element at `path`, else of its nearest ancestor; 1 for "".
    int lineOf(const std::string& path) const;

    /// Keys written twice in one object (JSON keeps the last silently), with the second line.
    const std::vector<std::pair<std::string, int>>& duplicates() const { return duplicates_; }

    static std::string child(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }
    static std::string element(const std::string& path, std::size_t index) {
        return path + "[" + std::to_string(index) + "]";
    }

  private:
    void value(const std::string& path);
    void skipSpace();
    std::string string();

    std::string_view s_;
    std::size_t i_ = 0;
    int line_ = 1;
    std::unordered_map<std::string, int> lines_;
    std::vector<std::pair<std::string, int>> duplicates_;
};

}  // namespace raystep
