#include "course/moodle.h"

#include "course/exercise.h"
#include "course/grading.h"
#include "course/lesson_trace.h"
#include "course/practice/figure.h"

#include "raystep/base/format.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

namespace raystep {

namespace {

/// A question as both formats need it, from the engine.
struct Question {
    enum class Type { Numerical, ShortAnswer, MultiChoice };
    Type type = Type::Numerical;
    std::string name, category, text, explanation;
    std::optional<std::string> figurePng;
    struct Option {
        std::string text;
        double fraction = 0;  // 100 right, 0 wrong
        double tolerance = 0;
        std::string feedback;
    };
    std::vector<Option> options;
};

/// A number as the question shows it: six significant digits (1.4999999999999998 is 1.5),
/// well inside every tolerance.
std::string shortest(double v) {
    return formatNumber(v, kReadableDigits);
}

/// The grader's tolerance as Moodle's absolute one: relative, absolute below 1.
double absoluteTolerance(const Exercise& ex, double answer) {
    return ex.tolerance * std::max(1.0, std::abs(answer));
}

/// A wrong option's feedback: the slip it betrays, else the explanation of the right one.
std::string whyWrong(const Verdict& v) {
    return v.slip.empty() ? v.feedback : v.slip;
}

bool numeric(const Exercise& ex) {
    return ex.kind == ExerciseKind::Value || ex.kind == ExerciseKind::Compute ||
           ex.kind == ExerciseKind::Count;
}

/// The ways a student may write `a` that raystep reads back as `a`: only those it accepts.
std::vector<std::string> spellings(const Exercise& ex, const Answer& right, const EventLog& log,
                                   const std::string& file, Language lang) {
    std::vector<std::vector<int>> items;
    const auto per = static_cast<std::size_t>(
        ex.kind == ExerciseKind::NextCell ? right.numbers.size() : std::max(1, right.perItem));
    for (std::size_t i = 0; i + per <= right.numbers.size(); i += per) {
        std::vector<int> c;
        for (std::size_t k = 0; k < per; ++k) c.push_back(static_cast<int>(right.numbers[i + k]));
        items.push_back(c);
    }
    const auto join = [&](const std::string& inner, const std::string& open,
                          const std::string& close, const std::string& between) {
        std::string out;
        for (std::size_t i = 0; i < items.size(); ++i) {
            out += (i ? between : "") + open;
            for (std::size_t k = 0; k < items[i].size(); ++k)
                out += (k ? inner : "") + std::to_string(items[i][k]);
            out += close;
        }
        return out;
    };
    std::vector<std::string> candidates = {formatAnswer(ex, right, lang)};
    if (ex.kind == ExerciseKind::NextCell || (ex.kind == ExerciseKind::Sequence && !ex.ofNodes)) {
        for (const char* between : {"; ", ";", " "})
            for (const auto& [inner, open, close] : std::vector<std::array<std::string, 3>>{
                     {",", "", ""}, {", ", "(", ")"}, {",", "(", ")"}, {" ", "", ""}}) {
                if (std::string(between) == " " && open.empty()) continue;
                candidates.push_back(join(inner, open, close, between));
            }
    } else if (ex.kind == ExerciseKind::Sequence) {
        for (const char* between : {" ", ", ", ","})
            candidates.push_back(join("", "", "", between));
    }
    std::vector<std::string> out;
    for (const std::string& c : candidates) {
        if (std::find(out.begin(), out.end(), c) != out.end()) continue;
        const auto parsed = parseAnswer(ex, c, nullptr, lang);
        if (parsed && checkAnswer(ex, log, *parsed, lang, file).correct) out.push_back(c);
    }
    return out;
}

/// Wrong answers a slip names, with the slip as their feedback: the usual transformations of
/// the right number (sign, twice, half, the reciprocal, one off) or the cells next to the right
/// one, each kept only when raystep's own slip check names it.
std::vector<Question::Option> slipOptions(const Exercise& ex, const Answer& right,
                                          const EventLog& log, const std::string& file,
                                          const LessonScene* scene, Language lang) {
    std::vector<Answer> wrong;
    if (numeric(ex) && !right.numbers.empty()) {
        const double a = right.numbers[0];
        for (double v : {-a, 2 * a, a / 2, a != 0 ? 1 / a : 0.0, a - 1, a + 1})
            if (std::isfinite(v)) wrong.push_back(Answer{{v}, std::nullopt, 1});
    } else if (ex.kind == ExerciseKind::NextCell) {
        for (std::size_t k = 0; k < right.numbers.size(); ++k)
            for (int step : {-1, 1}) {
                Answer w = right;
                w.numbers[k] += step;
                wrong.push_back(w);
            }
    }
    std::vector<Question::Option> out;
    std::set<std::string> seen;
    for (const Answer& w : wrong) {
        const Verdict v = checkAnswer(ex, log, w, lang, file, nullptr, scene);
        if (v.correct || v.slip.empty()) continue;
        const std::string t = numeric(ex) ? shortest(w.numbers[0]) : formatAnswer(ex, w, lang);
        if (!seen.insert(t).second) continue;
        out.push_back({t, 0, numeric(ex) ? absoluteTolerance(ex, w.numbers[0]) / 100 : 0, v.slip});
    }
    return out;
}

std::vector<Question> questionsOf(const MoodleSource& src, Language lang,
                                  std::vector<std::string>& skipped) {
    const Lesson& l = src.lesson;
    const LessonRun run = runLesson(l);
    const LessonLogs logs = run.logs();
    const std::vector<GridSweepRow> sweep = sweepRowsIfNeeded(l, run);
    const std::optional<std::string> figure = practiceFigurePng(l);
    std::vector<Question> out;
    for (const Exercise& ex : l.exercises) {
        const EventLog& log = logs.of(ex.setup);
        const Answer right = referenceAnswer(ex, log, l.file, &sweep);
        Question q;
        q.name = l.id + " " + ex.id;
        q.category = src.category + "/" + ex.id;
        // A compute prompt states its data itself (checkComputePrompts); the others need the
        // lesson's text for theirs.
        q.text = ex.kind == ExerciseKind::Compute ? ex.prompt.in(lang)
                                                  : l.text.in(lang) + "\n\n" + ex.prompt.in(lang);
        q.figurePng = figure;
        q.explanation = checkAnswer(ex, log, right, lang, l.file, &sweep, run.scene.get()).feedback;
        if (ex.kind == ExerciseKind::Choice) {
            q.type = Question::Type::MultiChoice;
            for (std::size_t k = 0; k < ex.choices.size(); ++k)
                q.options.push_back({ex.choices[k].text.in(lang),
                                     static_cast<int>(k) == ex.answer ? 100.0 : 0.0, 0,
                                     ex.choices[k].why.in(lang)});
        } else if (ex.kind == ExerciseKind::HitOrMiss && !ex.withT) {
            q.type = Question::Type::MultiChoice;
            for (bool option : {true, false}) {
                const Answer a{{}, option, 1};
                const Verdict v = checkAnswer(ex, log, a, lang, l.file, nullptr, run.scene.get());
                q.options.push_back({formatAnswer(ex, a, lang), v.correct ? 100.0 : 0.0, 0,
                                     v.correct ? "" : whyWrong(v)});
            }
        } else if (ex.kind == ExerciseKind::PickSplit) {
            q.type = Question::Type::MultiChoice;
            for (const SplitCandidate& c : splitCandidates(ex, log)) {
                const Answer a{{double(c.axis), c.position}, std::nullopt, 1};
                const Verdict v = checkAnswer(ex, log, a, lang, l.file);
                q.options.push_back({formatAnswer(ex, a, lang), v.correct ? 100.0 : 0.0, 0,
                                     v.correct ? "" : whyWrong(v)});
            }
        } else if (numeric(ex) && right.numbers.size() == 1) {
            q.type = Question::Type::Numerical;
            const double a = right.numbers[0];
            q.options.push_back({shortest(a), 100,
                                 ex.kind == ExerciseKind::Count ? 0 : absoluteTolerance(ex, a),
                                 ""});
            for (auto& o : slipOptions(ex, right, log, l.file, run.scene.get(), lang))
                q.options.push_back(o);
        } else if (ex.kind == ExerciseKind::NextCell || ex.kind == ExerciseKind::Sequence) {
            q.type = Question::Type::ShortAnswer;
            for (const std::string& s : spellings(ex, right, log, l.file, lang))
                q.options.push_back({s, 100, 0, ""});
            for (auto& o : slipOptions(ex, right, log, l.file, run.scene.get(), lang))
                q.options.push_back(o);
        } else {
            skipped.push_back(l.id + "/" + ex.id + ": an exercise of type " +
                              std::string(exerciseKindName(ex.kind)) +
                              (ex.kind == ExerciseKind::HitOrMiss ? " with its t" : "") +
                              " has no Moodle question type");
            continue;
        }
        out.push_back(std::move(q));
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (unsigned(static_cast<unsigned char>(bytes[i])) << 16) |
                           (unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8) |
                           unsigned(static_cast<unsigned char>(bytes[i + 2]));
        for (int s = 18; s >= 0; s -= 6) out += kDigits[(v >> s) & 63];
    }
    if (const std::size_t rest = bytes.size() - i; rest > 0) {
        unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16;
        if (rest == 2) v |= unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8;
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += rest == 2 ? kDigits[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string xmlEscape(std::string_view s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

/// A lesson's Markdown-ish text as HTML: paragraphs, code spans; escaped first.
std::string toHtml(const std::string& text) {
    std::string escaped = xmlEscape(text), out = "<p>";
    bool code = false;
    for (std::size_t i = 0; i < escaped.size(); ++i) {
        if (escaped[i] == '`') {
            out += code ? "</code>" : "<code>";
            code = !code;
        } else if (escaped.compare(i, 2, "\n\n") == 0) {
            out += "</p><p>";
            ++i;
        } else if (escaped[i] == '\n') {
            out += "<br>";
        } else {
            out += escaped[i];
        }
    }
    if (code) out += "</code>";
    return out + "</p>";
}

std::string typeName(Question::Type t) {
    switch (t) {
        case Question::Type::Numerical:
            return "numerical";
        case Question::Type::ShortAnswer:
            return "shortanswer";
        case Question::Type::MultiChoice:
            return "multichoice";
    }
    return "numerical";
}

/// A source's questions by category: one category per exercise, every variant of it in it.
std::vector<Question> sortedQuestions(const MoodleSource& src, Language lang,
                                      std::vector<std::string>& skipped) {
    std::vector<Question> qs = questionsOf(src, lang, skipped);
    std::stable_sort(qs.begin(), qs.end(),
                     [](const Question& a, const Question& b) { return a.category < b.category; });
    return qs;
}

}  // namespace

MoodleExport moodleXml(const std::vector<MoodleSource>& sources, Language lang) {
    MoodleExport out;
    std::string& x = out.text;
    x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n";
    std::string lastCategory;
    for (const MoodleSource& src : sources) {
        const std::vector<Question> qs = sortedQuestions(src, lang, out.skipped);
        for (const Question& q : qs) {
            if (q.category != lastCategory) {
                x += "  <question type=\"category\">\n    <category><text>$course$/top/" +
                     xmlEscape(q.category) + "</text></category>\n  </question>\n";
                lastCategory = q.category;
            }
            x += "  <question type=\"" + typeName(q.type) + "\">\n";
            x += "    <name><text>" + xmlEscape(q.name) + "</text></name>\n";
            std::string html = toHtml(q.text);
            std::string file;
            if (q.figurePng) {
                html += "<p><img src=\"@@PLUGINFILE@@/figure.png\" alt=\"figure\"></p>";
                file = "      <file name=\"figure.png\" path=\"/\" encoding=\"base64\">" +
                       base64(*q.figurePng) + "</file>\n";
            }
            x += "    <questiontext format=\"html\">\n      <text><![CDATA[" + html +
                 "]]></text>\n" + file + "    </questiontext>\n";
            x += "    <generalfeedback format=\"html\"><text><![CDATA[" + toHtml(q.explanation) +
                 "]]></text></generalfeedback>\n";
            x += "    <defaultgrade>1</defaultgrade>\n    <penalty>0.3333333</penalty>\n"
                 "    <hidden>0</hidden>\n";
            if (q.type == Question::Type::MultiChoice)
                x += "    <single>true</single>\n    <shuffleanswers>true</shuffleanswers>\n"
                     "    <answernumbering>abc</answernumbering>\n";
            if (q.type == Question::Type::ShortAnswer) x += "    <usecase>0</usecase>\n";
            for (const Question::Option& o : q.options) {
                x += "    <answer fraction=\"" + shortest(o.fraction) + "\" format=\"" +
                     std::string(q.type == Question::Type::MultiChoice ? "html"
                                                                       : "moodle_auto_format") +
                     "\">\n";
                x += "      <text>" + xmlEscape(o.text) + "</text>\n";
                if (q.type == Question::Type::Numerical)
                    x += "      <tolerance>" + shortest(o.tolerance) + "</tolerance>\n";
                x += "      <feedback format=\"html\"><text><![CDATA[" +
                     (o.feedback.empty() ? std::string() : toHtml(o.feedback)) +
                     "]]></text></feedback>\n    </answer>\n";
            }
            x += "  </question>\n";
            ++out.questions;
        }
    }
    x += "</quiz>\n";
    return out;
}

namespace {
/// GIFT's special characters ~ = # { } : and the backslash, escaped.
std::string giftEscape(std::string_view s) {
    std::string out;
    for (const char c : s) {
        if (std::string_view("~=#{}:\\").find(c) != std::string_view::npos) out += '\\';
        out += c == '\n' ? ' ' : c;
    }
    return out;
}
}  // namespace

MoodleExport moodleGift(const std::vector<MoodleSource>& sources, Language lang) {
    MoodleExport out;
    std::string& g = out.text;
    std::string lastCategory;
    for (const MoodleSource& src : sources) {
        const std::vector<Question> qs = sortedQuestions(src, lang, out.skipped);
        for (const Question& q : qs) {
            if (q.category != lastCategory) {
                g += "$CATEGORY: $course$/top/" + q.category + "\n\n";
                lastCategory = q.category;
            }
            g += "::" + giftEscape(q.name) + "::" + giftEscape(q.text) + " {";
            if (q.type == Question::Type::Numerical) g += "#";
            for (std::size_t i = 0; i < q.options.size(); ++i) {
                const Question::Option& o = q.options[i];
                const std::string fb = o.feedback.empty() ? "" : " #" + giftEscape(o.feedback);
                if (q.type == Question::Type::Numerical)
                    g += (o.fraction == 100 ? "=" : "=%0%") + giftEscape(o.text) + ":" +
                         shortest(o.tolerance) + fb + " ";
                else if (q.type == Question::Type::ShortAnswer)
                    g += (o.fraction == 100 ? "=" : "=%0%") + giftEscape(o.text) + fb + " ";
                else
                    g += (o.fraction == 100 ? "=" : "~") + giftEscape(o.text) + fb + " ";
            }
            g += "####" + giftEscape(q.explanation) + "}\n\n";
            ++out.questions;
        }
    }
    return out;
}

}  // namespace raystep
