#pragma once
// Where each key of a JSON text stands: nlohmann::json keeps no positions, and every error
// in a scene or course file must name its line. Paths look like "objects[2].radius".
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raystep {

/// Levels of [ ] and { } a file read by raystep may nest (the root counts as one). The deepest
/// file format (progress) needs 5; the cap keeps nlohmann's recursive copies, comparisons and
/// dumps far from the end of the stack.
constexpr int kMaxJsonDepth = 64;

class JsonLineMap {
  public:
    /// Scans `text` without recursion, in time and memory linear in its size. Meant for JSON that
    /// parses (comments allowed), it stays safe on any bytes. It first checks the nesting against
    /// `maxDepth` as nlohmann's lexer sees brackets (outside strings and comments); when deeper,
    /// it records nothing but tooDeepLine().
    explicit JsonLineMap(std::string_view text, int maxDepth = kMaxJsonDepth);

    /// Line (1-based) of the key or element at `path`, else of its nearest ancestor; 1 for "".
    /// Keys are matched decoded (as nlohmann gives them), "\u0061" and "a" alike.
    int lineOf(std::string_view path) const;

    /// The first key written twice in one object (JSON keeps the last silently), with the second
    /// one's line; keys are compared decoded.
    const std::vector<std::pair<std::string, int>>& duplicates() const { return duplicates_; }

    /// Line of the first bracket past the depth cap, 0 when the text nests within it.
    int tooDeepLine() const { return tooDeepLine_; }
    /// The same check alone, without building the map.
    static int tooDeepLine(std::string_view text, int maxDepth = kMaxJsonDepth);

    static std::string child(const std::string& path, const std::string& key) {
        return path.empty() ? key : path + "." + key;
    }
    static std::string element(const std::string& path, std::size_t index) {
        return path + "[" + std::to_string(index) + "]";
    }

  private:
    static constexpr std::uint32_t kElement = 0xffffffffu;  // Node::keyLength of an element
    enum class Kind : std::uint8_t { Scalar, Object, Array };
    struct Node {
        std::uint32_t parent;
        std::uint32_t name;       // a key: its offset in keys_; an element: its index
        std::uint32_t keyLength;  // kElement for an element
        std::uint32_t hash;
        int line;
        Kind kind;
    };

    void scan(std::string_view text);
    std::uint32_t addNode(std::uint32_t parent, std::uint32_t name, std::uint32_t keyLength,
                          int line);
    std::uint32_t findKey(std::uint32_t parent, std::uint32_t hash, std::string_view key) const;
    std::uint32_t findElement(std::uint32_t parent, std::uint64_t index) const;
    void grow();
    std::string pathOf(std::uint32_t node) const;

    std::vector<Node> nodes_;           // nodes_[0] is the root
    std::string keys_;                  // every key, decoded, one after the other
    std::vector<std::uint32_t> slots_;  // open addressing: node + 1, 0 = empty
    std::vector<std::pair<std::string, int>> duplicates_;
    int tooDeepLine_ = 0;
};

}  // namespace raystep
