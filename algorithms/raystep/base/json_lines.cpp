#include "raystep/base/json_lines.h"

#include <limits>
#include <unordered_set>

namespace raystep {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

std::uint64_t fnvStep(std::uint64_t h, char c) {
    return (h ^ static_cast<unsigned char>(c)) * kFnvPrime;
}
// splitmix64's finaliser: spreads the FNV sum and the parent over the low bits the table uses.
std::uint32_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return static_cast<std::uint32_t>(x);
}
std::uint32_t keyHash(std::uint32_t parent, std::uint64_t fnv) {
    return mix(fnv ^ (parent * 0x9e3779b97f4a7c15ull));
}
std::uint32_t elementHash(std::uint32_t parent, std::uint64_t index) {
    return mix((index * 0xff51afd7ed558ccdull) ^ (parent * 0x9e3779b97f4a7c15ull) ^ 0x5bd1e995ull);
}

/// The cursor over the text: whitespace and comments as nlohmann's lexer skips them (a line
/// comment ends at LF, CR or NUL), lines counted at LF.
struct Cursor {
    std::string_view s;
    std::size_t i = 0;
    int line = 1;

    bool atEnd() const { return i >= s.size(); }
    char peek(std::size_t ahead = 0) const { return i + ahead < s.size() ? s[i + ahead] : '\0'; }
    void advance() {
        if (s[i] == '\n') ++line;
        ++i;
    }
    void skipSpace() {
        while (!atEnd()) {
            const char c = s[i];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (!atEnd() && s[i] != '\n' && s[i] != '\r' && s[i] != '\0') ++i;
            } else if (c == '/' && peek(1) == '*') {
                i += 2;
                while (!atEnd() && !(s[i] == '*' && peek(1) == '/')) advance();
                i = std::min(i + 2, s.size());
            } else {
                break;
            }
        }
    }
    /// A string from its opening quote to past its closing one (or the end); decoded into `out`
    /// when given, \uXXXX (and surrogate pairs) as UTF-8, as nlohmann decodes it.
    void string(std::string* out) {
        ++i;  // opening quote
        while (!atEnd() && s[i] != '"') {
            if (s[i] != '\\') {
                if (out) *out += s[i];
                advance();
                continue;
            }
            ++i;
            if (atEnd()) break;
            const char e = s[i];
            if (e == 'u' && out) {
                const auto hex4 = [&](std::size_t at) -> long {
                    long v = 0;
                    for (std::size_t k = at; k < at + 4; ++k) {
                        const char h = k < s.size() ? s[k] : '\0';
                        const int d = h >= '0' && h <= '9'   ? h - '0'
                                      : h >= 'a' && h <= 'f' ? h - 'a' + 10
                                      : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                                             : -1;
                        if (d < 0) return -1;
                        v = v * 16 + d;
                    }
                    return v;
                };
                long cp = hex4(i + 1);
                if (cp < 0) {  // not an escape nlohmann accepts: kept as written
                    *out += "\\u";
                    ++i;
                    continue;
                }
                i += 5;
                if (cp >= 0xd800 && cp <= 0xdbff && peek() == '\\' && peek(1) == 'u') {
                    const long low = hex4(i + 2);
                    if (low >= 0xdc00 && low <= 0xdfff) {
                        cp = 0x10000 + ((cp - 0xd800) << 10) + (low - 0xdc00);
                        i += 6;
                    }
                }
                appendUtf8(*out, cp);
                continue;
            }
            if (out) {
                switch (e) {
                    case 'b':
                        *out += '\b';
                        break;
                    case 'f':
                        *out += '\f';
                        break;
                    case 'n':
                        *out += '\n';
                        break;
                    case 'r':
                        *out += '\r';
                        break;
                    case 't':
                        *out += '\t';
                        break;
                    default:
                        *out += e;  // \" \\ \/
                }
            }
            advance();
        }
        if (!atEnd()) ++i;  // closing quote
    }
    static void appendUtf8(std::string& out, long cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xc0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3f));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xe0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (cp & 0x3f));
        } else {
            out += static_cast<char>(0xf0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (cp & 0x3f));
        }
    }
    /// A number, literal or any stray token up to the next delimiter; at least one character
    /// unless it stands at a ',', ']' or '}' (which the caller consumes), so the scan always ends.
    void literal() {
        const std::size_t start = i;
        while (!atEnd()) {
            const char c = s[i];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == ']' ||
                c == '}' || c == '[' || c == '{' || c == '"' || c == ':' || c == '/')
                break;
            ++i;
        }
        if (i == start && !atEnd() && s[i] != ',' && s[i] != ']' && s[i] != '}') advance();
    }
};

/// Line of the first '[' or '{' past `maxDepth` levels, counted as nlohmann's lexer sees them
/// (outside strings and comments); 0 if none. Until nlohmann's first syntax error its nesting
/// equals this count, so it never nests deeper than a text this passes.
int firstTooDeep(std::string_view s, int maxDepth) {
    Cursor c{s};
    int depth = 0;
    while (!c.atEnd()) {
        c.skipSpace();
        if (c.atEnd()) break;
        const char ch = c.s[c.i];
        if (ch == '"') {
            c.string(nullptr);
        } else if (ch == '[' || ch == '{') {
            if (++depth > maxDepth) return c.line;
            ++c.i;
        } else if (ch == ']' || ch == '}') {
            if (depth > 0) --depth;
            ++c.i;
        } else {
            c.advance();
        }
    }
    return 0;
}

}  // namespace

int JsonLineMap::tooDeepLine(std::string_view text, int maxDepth) {
    return firstTooDeep(text, maxDepth);
}

JsonLineMap::JsonLineMap(std::string_view text, int maxDepth) {
    tooDeepLine_ = firstTooDeep(text, maxDepth);
    // Ids are 32-bit: a text of 4 GB or more gets no map (every line falls back to 1).
    if (tooDeepLine_ == 0 && text.size() < kNone) scan(text);
}

void JsonLineMap::scan(std::string_view text) {
    Cursor c{text};
    if (text.starts_with("\xEF\xBB\xBF")) c.i = 3;  // nlohmann skips a UTF-8 byte order mark
    slots_.assign(64, 0);
    nodes_.push_back({kNone, 0, kElement, 0, 1, Kind::Scalar});

    struct Frame {
        std::uint32_t node;
        std::uint32_t nextIndex;
        bool object;
    };
    std::vector<Frame> stack;  // at most the depth cap: each frame is a bracket counted above
    std::uint32_t current = 0;
    bool expectValue = true;
    std::string key;
    for (;;) {
        c.skipSpace();
        if (c.atEnd()) break;
        const char ch = c.s[c.i];
        if (expectValue) {
            expectValue = false;
            if (ch == '{' || ch == '[') {
                nodes_[current].kind = ch == '{' ? Kind::Object : Kind::Array;
                stack.push_back({current, 0, ch == '{'});
                ++c.i;
            } else if (ch == '"') {
                c.string(nullptr);
            } else {
                c.literal();
            }
            continue;
        }
        if (stack.empty()) break;  // the root value is complete
        Frame& f = stack.back();
        if (ch == ',') {
            ++c.i;
        } else if (ch == ']' || ch == '}') {
            ++c.i;
            stack.pop_back();
        } else if (!f.object) {
            current = addNode(f.node, f.nextIndex++, kElement, c.line);
            expectValue = true;
        } else if (ch != '"') {
            c.literal();  // not a key: skipped (the text did not parse anyway)
        } else {
            const int keyLine = c.line;
            key.clear();
            c.string(&key);
            const auto offset = static_cast<std::uint32_t>(keys_.size());
            keys_ += key;
            current = addNode(f.node, offset, static_cast<std::uint32_t>(key.size()), keyLine);
            c.skipSpace();
            if (c.peek() == ':') ++c.i;
            expectValue = true;
        }
    }
}

std::uint32_t JsonLineMap::addNode(std::uint32_t parent, std::uint32_t name,
                                   std::uint32_t keyLength, int line) {
    const bool isKey = keyLength != kElement;
    std::uint32_t hash;
    bool duplicate = false;
    if (isKey) {
        std::uint64_t fnv = kFnvOffset;
        const std::string_view key(keys_.data() + name, keyLength);
        for (const char ch : key) fnv = fnvStep(fnv, ch);
        hash = keyHash(parent, fnv);
        if (findKey(parent, hash, key) != kNone) {
            duplicate = true;
            if (duplicates_.empty())
                duplicates_.emplace_back(child(pathOf(parent), std::string(key)), line);
        }
    } else {
        hash = elementHash(parent, name);
    }
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({parent, name, keyLength, hash, line, Kind::Scalar});
    // A duplicate stays out of the table: its path finds the first (kept) key's line.
    if (!duplicate) {
        if ((nodes_.size() + 1) * 2 > slots_.size()) grow();
        std::size_t p = hash & (slots_.size() - 1);
        while (slots_[p] != 0) p = (p + 1) & (slots_.size() - 1);
        slots_[p] = id + 1;
    }
    return id;
}

void JsonLineMap::grow() {
    std::vector<std::uint32_t> old(slots_.size() * 2, 0);
    old.swap(slots_);
    for (const std::uint32_t slot : old) {
        if (slot == 0) continue;
        std::size_t p = nodes_[slot - 1].hash & (slots_.size() - 1);
        while (slots_[p] != 0) p = (p + 1) & (slots_.size() - 1);
        slots_[p] = slot;
    }
}

std::uint32_t JsonLineMap::findKey(std::uint32_t parent, std::uint32_t hash,
                                   std::string_view key) const {
    for (std::size_t p = hash & (slots_.size() - 1); slots_[p] != 0;
         p = (p + 1) & (slots_.size() - 1)) {
        const Node& n = nodes_[slots_[p] - 1];
        if (n.hash == hash && n.parent == parent && n.keyLength == key.size() &&
            keys_.compare(n.name, n.keyLength, key) == 0)
            return slots_[p] - 1;
    }
    return kNone;
}

std::uint32_t JsonLineMap::findElement(std::uint32_t parent, std::uint64_t index) const {
    const std::uint32_t hash = elementHash(parent, index);
    for (std::size_t p = hash & (slots_.size() - 1); slots_[p] != 0;
         p = (p + 1) & (slots_.size() - 1)) {
        const Node& n = nodes_[slots_[p] - 1];
        if (n.hash == hash && n.parent == parent && n.keyLength == kElement && n.name == index)
            return slots_[p] - 1;
    }
    return kNone;
}

std::string JsonLineMap::pathOf(std::uint32_t node) const {
    std::vector<std::uint32_t> chain;
    for (std::uint32_t n = node; n != 0; n = nodes_[n].parent) chain.push_back(n);
    std::string path;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const Node& n = nodes_[*it];
        path = n.keyLength == kElement ? element(path, n.name)
                                       : child(path, keys_.substr(n.name, n.keyLength));
    }
    return path;
}

int JsonLineMap::lineOf(std::string_view path) const {
    if (nodes_.empty() || path.empty()) return 1;
    // A key may hold '.' or '[' itself, so a path can split into keys and indices in more than
    // one way: depth first over the splits, each (node, position) once, the shortest key first.
    // A split that reaches the end wins; else the one that matched the longest prefix.
    struct State {
        std::uint32_t node;
        std::size_t pos;
    };
    std::vector<State> todo{{0, 0}};
    std::unordered_set<std::uint64_t> seen;
    std::size_t bestPos = 0;
    int bestLine = 1;
    std::vector<State> children;
    while (!todo.empty()) {
        const auto [node, pos] = todo.back();
        todo.pop_back();
        if (pos == path.size()) return nodes_[node].line;
        if (pos > bestPos) {
            bestPos = pos;
            bestLine = nodes_[node].line;
        }
        if (!seen.insert((std::uint64_t(node) << 32) ^ pos).second) continue;
        const Node& n = nodes_[node];
        children.clear();
        if (n.kind == Kind::Array && path[pos] == '[') {
            std::uint64_t index = 0;
            std::size_t k = pos + 1;
            for (; k < path.size() && path[k] >= '0' && path[k] <= '9' && index < kNone; ++k)
                index = index * 10 + static_cast<std::uint64_t>(path[k] - '0');
            if (k > pos + 1 && k < path.size() && path[k] == ']' && index < kNone)
                if (const auto child = findElement(node, index); child != kNone)
                    children.push_back({child, k + 1});
        } else if (n.kind == Kind::Object && (pos == 0 || path[pos] == '.')) {
            // Each candidate key's hash carried on from the last.
            const std::size_t start = pos == 0 ? 0 : pos + 1;
            std::uint64_t fnv = kFnvOffset;
            for (std::size_t j = start;; ++j) {
                if (j == path.size() || path[j] == '.' || path[j] == '[')
                    if (const auto child =
                            findKey(node, keyHash(node, fnv), path.substr(start, j - start));
                        child != kNone)
                        children.push_back({child, j});
                if (j == path.size()) break;
                fnv = fnvStep(fnv, path[j]);
            }
        }
        todo.insert(todo.end(), children.rbegin(), children.rend());
    }
    return bestLine;
}

}  // namespace raystep
