#pragma once
// A file that cannot be read as what it should be (scene, trace, course file): which file,
// which line, which key, and why, in the one-line form "file:line: key 'k': message".
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raystep {

/// Text from a file (a value, a key, a file name) made safe to quote in a one-line message:
/// control characters, invalid UTF-8 and the Unicode line, paragraph and direction marks become
/// \n, \t, \xNN or \u{NNNN}; valid UTF-8 passes as it is. Past `maxBytes` bytes of output it is
/// cut and the original length given, "abc... (5000 bytes)". Applying it twice changes nothing.
inline std::string printable(std::string_view text, std::size_t maxBytes = 60) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    std::size_t i = 0;
    const auto byteAt = [&](std::size_t k) {
        return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
    };
    while (i < text.size() && out.size() < maxBytes) {
        const unsigned char c = byteAt(i);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        if (c < 0x80) {  // a control character
            if (c == '\n') {
                out += "\\n";
            } else if (c == '\r') {
                out += "\\r";
            } else if (c == '\t') {
                out += "\\t";
            } else {
                out += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
            }
            ++i;
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte, the second byte's range from RFC 3629
        // (no overlong forms, no surrogates, nothing past U+10FFFF).
        std::size_t length = 0;
        unsigned lo = 0x80, hi = 0xbf;
        if (c >= 0xc2 && c <= 0xdf) {
            length = 2;
        } else if (c >= 0xe0 && c <= 0xef) {
            length = 3;
            if (c == 0xe0) lo = 0xa0;
            if (c == 0xed) hi = 0x9f;
        } else if (c >= 0xf0 && c <= 0xf4) {
            length = 4;
            if (c == 0xf0) lo = 0x90;
            if (c == 0xf4) hi = 0x8f;
        }
        bool valid = length > 0 && byteAt(i + 1) >= lo && byteAt(i + 1) <= hi;
        for (std::size_t k = 2; valid && k < length; ++k)
            valid = byteAt(i + k) >= 0x80 && byteAt(i + k) <= 0xbf;
        if (!valid) {
            out += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
            ++i;
            continue;
        }
        unsigned code = c & (length == 2 ? 0x1f : length == 3 ? 0x0f : 0x07);
        for (std::size_t k = 1; k < length; ++k) code = (code << 6) | (byteAt(i + k) & 0x3f);
        // C1 controls (NEL among them), line and paragraph separators, bidirectional overrides.
        if ((code >= 0x80 && code <= 0x9f) || code == 0x2028 || code == 0x2029 ||
            (code >= 0x202a && code <= 0x202e) || (code >= 0x2066 && code <= 0x2069)) {
            out += "\\u{";
            for (int shift = 12; shift >= 0; shift -= 4) out += kHex[(code >> shift) & 15];
            out += '}';
        } else {
            out.append(text.substr(i, length));
        }
        i += length;
    }
    if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

class FileError : public std::runtime_error {
  public:
    /// The message is escaped as a whole (printable), so it stays one line whatever it quotes;
    /// file() and key() keep the text as given.
    FileError(std::string file, int line, std::string key, const std::string& message)
        : std::runtime_error(compose(file, line, key, message)),
          file_(std::move(file)),
          line_(line),
          key_(std::move(key)) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }  // 0 when the error is about the file as a whole
    const std::string& key() const { return key_; }

  private:
    std::string file_;
    int line_;
    std::string key_;

    // Appended piece by piece: GCC 12 sees a false overlap (-Wrestrict) in "x" + std::string&&.
    static std::string compose(const std::string& file, int line, const std::string& key,
                               const std::string& message) {
        std::string s = printable(file, 512);
        if (line > 0) s.append(":").append(std::to_string(line));
        s.append(": ");
        if (!key.empty()) s.append("key '").append(printable(key, 160)).append("': ");
        return s.append(printable(message, std::string::npos));
    }
};

}  // namespace raystep
