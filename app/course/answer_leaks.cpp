// Finding an exercise's answer in a text: the text is read as a student reads it (numbers with
// either decimal mark, cells in brackets or not, sentences), not searched for one spelling.
#include "course/answer_leaks.h"

#include "course/exercises/kind_unit.h"
#include "course/lesson_trace.h"

#include "raystep/base/i18n.h"
#include "raystep/trace/event_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace raystep {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isLetter(char c) {
    // Bytes of a UTF-8 letter (à, ì) count as letters: "2à" is no number.
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '`' || c == '*';
}

/// A number as written: its value, how many significant digits it shows, whether it is whole.
struct Token {
    double value = 0.0;
    int significant = 0;
    int decimals = 0;
    bool whole = true;
    std::size_t begin = 0, end = 0;
};

/// The numbers of `s`; `commaDecimal`: "3,25" is three and a quarter (Italian), else two numbers.
std::vector<Token> numberTokens(std::string_view s, bool commaDecimal) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        if (!isDigit(s[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        // Glued to a name before it ("t0", "x2", "tMax2") it is part of the name.
        const bool glued = start > 0 && isLetter(s[start - 1]);
        std::string digits;
        while (i < s.size() && isDigit(s[i])) digits += s[i++];
        std::string frac;
        if (i + 1 < s.size() && (s[i] == '.' || (commaDecimal && s[i] == ',')) &&
            isDigit(s[i + 1])) {
            ++i;
            while (i < s.size() && isDigit(s[i])) frac += s[i++];
        }
        std::string exponent;
        if (i + 1 < s.size() && (s[i] == 'e' || s[i] == 'E') &&
            (isDigit(s[i + 1]) ||
             ((s[i + 1] == '-' || s[i + 1] == '+') && i + 2 < s.size() && isDigit(s[i + 2])))) {
            exponent += s[i++];
            if (s[i] == '-' || s[i] == '+') exponent += s[i++];
            while (i < s.size() && isDigit(s[i])) exponent += s[i++];
        }
        // Glued to a word after it ("2D", "1st", "3x3") it is no number of its own.
        if (glued || (i < s.size() && isLetter(s[i]))) {
            while (i < s.size() && (isLetter(s[i]) || isDigit(s[i]))) ++i;
            continue;
        }
        Token t;
        t.begin = start;
        t.end = i;
        t.value =
            std::strtod((digits + (frac.empty() ? "" : "." + frac) + exponent).c_str(), nullptr);
        t.whole = frac.empty() && exponent.empty();
        t.decimals = static_cast<int>(frac.size());
        std::string all = digits + frac;
        const std::size_t first = all.find_first_not_of('0');
        t.significant = first == std::string::npos ? 1 : static_cast<int>(all.size() - first);
        // A minus sign: '-' or U+2212, unless it subtracts ("1 - 0.4" has a space, "1-0.4" a
        // digit before it).
        const auto signAt = [&](std::size_t len) {
            if (start < len) return false;
            const std::size_t at = start - len;
            const bool minus = len == 1 ? s[at] == '-' : s.substr(at, 3) == "\xe2\x88\x92";
            return minus &&
                   !(at > 0 && (isDigit(s[at - 1]) || isLetter(s[at - 1]) || s[at - 1] == ')'));
        };
        if (signAt(1)) {
            t.value = -t.value;
            t.begin = start - 1;
        } else if (signAt(3)) {
            t.value = -t.value;
            t.begin = start - 3;
        }
        out.push_back(t);
    }
    return out;
}

/// Both readings of a text: the decimal point only, then the comma too.
std::array<std::vector<Token>, 2> bothReadings(std::string_view s) {
    return {numberTokens(s, false), numberTokens(s, true)};
}

bool sameNumber(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
}

/// Whether a number written as `t` gives `answer`: it is the answer, or a rounding of it to three
/// or more significant digits, or (two or more) one the grader would take for it.
bool gives(const Token& t, double answer, double tolerance) {
    if (sameNumber(t.value, answer)) return true;
    if (t.significant >= 3 &&
        std::abs(t.value - answer) <= 0.5 * std::pow(10.0, -t.decimals) * (1.0 + 1e-9))
        return true;
    return t.significant >= 2 && !t.whole &&
           std::abs(t.value - answer) <= tolerance * std::max(1.0, std::abs(answer));
}

/// Whether `between` is only a separator: blanks and at most one of `seps` (or a word of `words`).
bool separatorOnly(std::string_view between, std::string_view seps,
                   std::initializer_list<std::string_view> words = {}) {
    std::string rest;
    for (const char c : between)
        if (!isSpace(c)) rest += c;
    if (rest.empty()) return true;
    if (rest.size() == 1 && seps.find(rest[0]) != std::string_view::npos) return true;
    for (const std::string_view w : words)
        if (rest == w) return true;
    return false;
}

std::string excerpt(std::string_view s, std::size_t begin, std::size_t end) {
    return std::string(s.substr(begin, std::min(end, s.size()) - begin));
}

/// A cell found in a text, where it starts and ends.
struct FoundCell {
    std::array<int, 3> cell{0, 0, 0};
    std::size_t begin = 0, end = 0;
};

std::size_t skipBlanksBack(std::string_view s, std::size_t at) {
    while (at > 0 && (s[at - 1] == ' ' || s[at - 1] == '\t')) --at;
    return at;
}
std::size_t skipBlanks(std::string_view s, std::size_t at) {
    while (at < s.size() && (s[at] == ' ' || s[at] == '\t')) ++at;
    return at;
}

/// Whether the bracket at `open` starts a vector a formula names: the direction in "o + t (1, 1)"
/// or "d = (1, 1)", a lower-case variable (cells are X, Y, or "cell (1, 1)").
bool namedVector(std::string_view s, std::size_t open) {
    std::size_t at = skipBlanksBack(s, open);
    if (at > 0 && s[at - 1] == '=') at = skipBlanksBack(s, at - 1);
    if (at == 0 || !(s[at - 1] >= 'a' && s[at - 1] <= 'z')) return false;
    return at == 1 || !isLetter(s[at - 2]);
}

/// Cells of `dims` indices as a text writes them: "(3, 1)", "(3,1)", "(3; 1)", "3, 1", "3,1",
/// "X = 3, Y = 1", in the order they appear.
std::vector<FoundCell> cellsIn(std::string_view s, int dims) {
    std::vector<FoundCell> found;
    for (const std::vector<Token>& tokens : bothReadings(s)) {
        for (std::size_t k = 0; k < tokens.size();) {
            const std::size_t open = skipBlanksBack(s, tokens[k].begin);
            const bool bracketed = open > 0 && s[open - 1] == '(';
            std::size_t last = k;
            // Inside brackets an Italian tuple may use ';'; outside, ';' separates two cells.
            while (
                last + 1 < tokens.size() &&
                separatorOnly(s.substr(tokens[last].end, tokens[last + 1].begin - tokens[last].end),
                              bracketed ? ",;" : ",") &&
                s.substr(tokens[last].end, tokens[last + 1].begin - tokens[last].end)
                        .find_first_of(",;") != std::string_view::npos)
                ++last;
            const std::size_t count = last - k + 1;
            bool ok = static_cast<int>(count) == dims;
            for (std::size_t j = k; ok && j <= last; ++j) ok = tokens[j].whole;
            std::size_t begin = tokens[k].begin, end = tokens[last].end;
            if (ok && bracketed && namedVector(s, open - 1)) ok = false;
            if (ok && bracketed) {
                const std::size_t close = skipBlanks(s, end);
                ok = close < s.size() && s[close] == ')';
                begin = open - 1;
                end = close + 1;
            }
            if (ok) {
                FoundCell c;
                for (int j = 0; j < dims; ++j) c.cell[j] = static_cast<int>(tokens[k + j].value);
                c.begin = begin;
                c.end = end;
                found.push_back(c);
            }
            k = last + 1;
        }
    }
    // "X = 3, Y = 1 (, Z = 2)": the slides' cell variables, upper case.
    for (std::size_t at = 0; at < s.size(); ++at) {
        if (s[at] != 'X' || (at > 0 && isLetter(s[at - 1])) ||
            (at + 1 < s.size() && isLetter(s[at + 1])))
            continue;
        FoundCell c;
        c.begin = at;
        std::size_t i = at;
        bool ok = true;
        for (int axis = 0; axis < dims && ok; ++axis) {
            if (axis > 0) {
                const std::size_t next = s.find("XYZ"[axis], i);
                ok = next != std::string_view::npos &&
                     separatorOnly(s.substr(i, next - i), ",;", {"and", "e", ",and", ",e"});
                i = next;
            }
            if (!ok) break;
            i = skipBlanks(s, i + 1);
            ok = i < s.size() && s[i] == '=';
            if (!ok) break;
            i = skipBlanks(s, i + 1);
            const auto tokens = numberTokens(s.substr(i), false);
            ok = !tokens.empty() && tokens[0].begin == 0 && tokens[0].whole;
            if (!ok) break;
            c.cell[axis] = static_cast<int>(tokens[0].value);
            i += tokens[0].end;
        }
        if (!ok) continue;
        c.end = i;
        found.push_back(c);
    }
    std::sort(found.begin(), found.end(),
              [](const FoundCell& a, const FoundCell& b) { return a.begin < b.begin; });
    return found;
}

std::string lowerAscii(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

/// The sentences of a text, each with whether it asks (ends in '?').
struct Sentence {
    std::string_view text;
    bool question = false;
};
std::vector<Sentence> sentences(std::string_view s) {
    std::vector<Sentence> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= s.size(); ++i) {
        const bool end = i == s.size();
        const char c = end ? '\n' : s[i];
        // A full stop ends a sentence only before a blank ("d.n" and "7.88" do not).
        const bool stop = c == '?' || c == '!' || c == ';' || c == '\n' ||
                          (c == '.' && (i + 1 >= s.size() || isSpace(s[i + 1]) || s[i + 1] == '"' ||
                                        s[i + 1] == ')'));
        if (!stop) continue;
        if (i > start) out.push_back({s.substr(start, i - start), c == '?'});
        start = i + 1;
    }
    return out;
}

std::vector<std::pair<std::string, std::size_t>> words(std::string_view s) {
    std::vector<std::pair<std::string, std::size_t>> out;
    std::size_t i = 0;
    while (i < s.size()) {
        if (!isLetter(s[i]) && !isDigit(s[i])) {
            ++i;
            continue;
        }
        const std::size_t b = i;
        while (i < s.size() && (isLetter(s[i]) || isDigit(s[i]))) ++i;
        out.emplace_back(lowerAscii(s.substr(b, i - b)), b);
    }
    return out;
}

/// Whether `w` is one of the words `role` is said with in any language (language.json).
bool oneOf(const std::string& w, std::string_view role) {
    const std::vector<std::string> list = wordsInAnyLanguage(role);
    return std::find(list.begin(), list.end(), w) != list.end();
}

/// A yes-or-no question ("Does the ray hit triangle 2?", "Il raggio incontra la sfera?") asks
/// what it names; a question of another kind takes it as known ("How many shadow rays leave the
/// hit point on the mirror?"): its words are a language's "question" words (Italian's leave out
/// "che", "come" and "quando", which also join clauses).
bool polar(std::string_view sentence) {
    for (const auto& [w, at] : words(sentence))
        if (oneOf(w, "question")) return false;
    return true;
}

/// A word that says how a test came out, in any language.
bool outcomeWord(const std::string& w) {
    return oneOf(w, "outcome");
}

/// Whether a sentence names the outcome's primitive: "primitive 2", "triangle 2", or its kind
/// alone ("the circle", "il cerchietto"), not another numbered one ("circle 3").
std::optional<std::size_t> namesPrimitive(const std::vector<std::pair<std::string, std::size_t>>& w,
                                          const AnswerForms::Outcome& o, TextRole role) {
    for (std::size_t k = 0; k < w.size(); ++k) {
        const std::string& word = w[k].first;
        if (role != TextRole::GivenData &&
            std::find(o.names.begin(), o.names.end(), word) != o.names.end())
            return w[k].second;
        const bool generic = oneOf(word, "primitive");
        const bool kind =
            (o.circle && oneOf(word, "circle")) || (o.segment && oneOf(word, "segment")) ||
            (o.sphere && oneOf(word, "sphere")) || (o.triangle && oneOf(word, "triangle"));
        if (!generic && !kind) continue;
        const bool numbered = k + 1 < w.size() && isDigit(w[k + 1].first[0]);
        if (numbered) {
            if (std::atoi(w[k + 1].first.c_str()) == static_cast<int>(o.prim)) return w[k].second;
        } else if (kind &&
                   (role == TextRole::Exercise || (role == TextRole::Prose && o.onlyOfItsKind))) {
            return w[k].second;
        }
    }
    return std::nullopt;
}

}  // namespace

namespace exercises {

/// The name a 3D primitive goes by when its material is its own ("the mirror", "lo specchio"):
/// the material's name, and its words in the languages ("material:mirror" in language.json).
std::vector<std::string> uniqueNames(const Scene& scene, std::uint32_t prim) {
    if (prim >= scene.primitiveCount()) return {};
    const std::string& name = scene.materialOf(prim).name;
    for (std::uint32_t p = 0; p < scene.primitiveCount(); ++p)
        if (p != prim && scene.materialOf(p).name == name) return {};
    std::vector<std::string> names{lowerAscii(name)};
    for (std::string& w : wordsInAnyLanguage("material:" + names[0])) names.push_back(std::move(w));
    return names;
}

}  // namespace exercises

AnswerForms answerForms(const Exercise& ex, const EventLog& log, const std::string& lessonFile,
                        const LessonScene* scene, const std::vector<GridSweepRow>* sweep) {
    AnswerForms f;
    f.tolerance = ex.tolerance;
    f.dims = log.dims();
    exercises::unitOf(ex.kind).answerForms({ex, log, lessonFile, scene, sweep}, f);
    return f;
}

std::optional<std::string> findAnswer(const AnswerForms& f, std::string_view text, TextRole role) {
    // Numbers, with either decimal mark ("3,25" is a decimal, not two numbers, in any text).
    if (!f.numbers.empty())
        for (const Token& t : numberTokens(text, true))
            for (const double answer : f.numbers)
                if (gives(t, answer, f.tolerance)) return excerpt(text, t.begin, t.end);
    // A cell, or a walk's cells in order (others may stand between them).
    if (!f.cells.empty()) {
        const std::vector<FoundCell> cells = cellsIn(text, f.dims);
        std::size_t next = 0, first = 0;
        for (const FoundCell& c : cells) {
            if (next < f.cells.size() && c.cell == f.cells[next]) {
                if (next == 0) first = c.begin;
                if (++next == f.cells.size()) return excerpt(text, first, c.end);
            }
        }
    }
    // TestTree's order: the ids one after the other ("0 1 2 14", "0, 1, 2 and 14", "0 → 1");
    // an overlap's pair the same way ("3 and 4").
    std::vector<std::vector<int>> runs;
    if (!f.nodes.empty()) runs.push_back(f.nodes);
    for (const auto& p : f.nodePairs) runs.push_back({p[0], p[1]});
    if (!runs.empty()) {
        const std::vector<Token> tokens = numberTokens(text, false);
        for (const std::vector<int>& ids : runs)
            for (std::size_t k = 0; k + ids.size() <= tokens.size(); ++k) {
                bool run = true;
                for (std::size_t j = 0; run && j < ids.size(); ++j) {
                    const Token& t = tokens[k + j];
                    run = t.whole && static_cast<int>(t.value) == ids[j];
                    if (run && j > 0)
                        run = separatorOnly(
                            text.substr(tokens[k + j - 1].end, t.begin - tokens[k + j - 1].end),
                            ",;", {"and", "e", "then", "poi", "with", "con", "->", "\xe2\x86\x92"});
                }
                if (run) return excerpt(text, tokens[k].begin, tokens[k + ids.size() - 1].end);
            }
    }
    // A test's outcome: a sentence that names the primitive and says hit or miss.
    if (f.outcome)
        for (const Sentence& s : sentences(text)) {
            if (s.question && polar(s.text)) continue;
            const auto w = words(s.text);
            const bool says =
                std::any_of(w.begin(), w.end(), [](const auto& x) { return outcomeWord(x.first); });
            if (says && namesPrimitive(w, *f.outcome, role)) return std::string(s.text);
        }
    // A split plane: "y = 2.96", "y=2,96".
    if (f.plane)
        for (const Token& t : numberTokens(text, true)) {
            std::size_t at = skipBlanksBack(text, t.begin);
            if (at == 0 || text[at - 1] != '=') continue;
            at = skipBlanksBack(text, at - 1);
            if (at == 0 || text[at - 1] != "xyz"[f.plane->axis] ||
                (at > 1 && isLetter(text[at - 2])))
                continue;
            const bool same =
                sameNumber(t.value, f.plane->position) ||
                (t.significant >= 3 && std::abs(t.value - f.plane->position) <=
                                           0.5 * std::pow(10.0, -t.decimals) * (1.0 + 1e-9));
            if (same) return excerpt(text, at - 1, t.end);
        }
    // A sweep's resolution: "8 x 8 x 8", "8 cells per axis", "8 celle per asse".
    if (f.resolution) {
        const std::vector<Token> tokens = numberTokens(text, false);
        for (std::size_t k = 0; k < tokens.size(); ++k) {
            if (!tokens[k].whole || static_cast<int>(tokens[k].value) != *f.resolution) continue;
            const std::string after = lowerAscii(text.substr(tokens[k].end, 24));
            const std::string_view rest = std::string_view(after).substr(skipBlanks(after, 0));
            for (const std::string_view tail :
                 {"x", "\xc3\x97", "cells per axis", "per axis", "celle per asse", "per asse"})
                if (rest.substr(0, tail.size()) == tail &&
                    (tail.size() > 2 || (k + 1 < tokens.size() &&
                                         static_cast<int>(tokens[k + 1].value) == *f.resolution)))
                    return excerpt(text, tokens[k].begin, tokens[k].end + after.size());
        }
    }
    return std::nullopt;
}

}  // namespace raystep
