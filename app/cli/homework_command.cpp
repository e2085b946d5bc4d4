#include "homework_command.h"

#include "common.h"

#include "course/grading.h"
#include "course/lesson.h"
#include "course/lesson_trace.h"
#include "course/practice/figure.h"
#include "course/practice/practice.h"

#include "raystep/base/file_error.h"
#include "raystep/base/i18n.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace raystep::cli {

namespace {

struct BadInput {
    std::string line;
};

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw BadInput{path + ": cannot be read"};
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// RFC 4180 records with the line each starts on; a UTF-8 BOM and CRLF are accepted.
std::vector<std::pair<int, std::vector<std::string>>> parseCsv(std::string text,
                                                               const std::string& file) {
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    std::vector<std::pair<int, std::vector<std::string>>> rows;
    std::vector<std::string> row;
    std::string field;
    bool quoted = false, any = false;
    int line = 1, start = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
                field += '"', ++i;
            else if (c == '"')
                quoted = false;
            else {
                if (c == '\n') ++line;
                field += c;
            }
        } else if (c == '"')
            quoted = any = true;
        else if (c == ',')
            row.push_back(field), field.clear(), any = true;
        else if (c == '\r' || c == '\n') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            row.push_back(field), field.clear();
            if (any || row.size() > 1 || !row[0].empty()) rows.emplace_back(start, row);
            row.clear(), any = false, start = ++line;
        } else
            field += c, any = true;
    }
    if (quoted)
        throw BadInput{file + ":" + std::to_string(start) + ": a quoted field is not closed"};
    if (any || !field.empty()) row.push_back(field), rows.emplace_back(start, row);
    return rows;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

struct Student {
    std::string id, name;
};
struct Roster {
    std::string column;
    std::vector<Student> students;
};

Roster loadRoster(const std::string& path) {
    const auto rows = parseCsv(readFile(path), path);
    if (rows.empty()) throw BadInput{path + ": the roster is empty (expected a header line)"};
    const auto& head = rows[0].second;
    int idCol = -1, nameCol = -1, firstCol = -1, lastCol = -1;
    for (int i = 0; i < static_cast<int>(head.size()); ++i) {
        const std::string h = lower(head[i]);
        if (idCol < 0 && (h == "id" || h == "username" || h == "idnumber" || h == "email"))
            idCol = i;
        if (h == "name" && nameCol < 0) nameCol = i;
        if (h == "firstname" && firstCol < 0) firstCol = i;
        if (h == "lastname" && lastCol < 0) lastCol = i;
    }
    if (idCol < 0)
        throw BadInput{path + ":1: no id column (expected id, username, idnumber or email)"};
    Roster r{lower(head[idCol]), {}};
    std::set<std::string> seen;
    for (std::size_t k = 1; k < rows.size(); ++k) {
        // Named locals, not a structured binding: clang 14 refuses one captured by a lambda.
        const auto& line = rows[k].first;
        const auto& f = rows[k].second;
        const std::string where = path + ":" + std::to_string(line) + ": " + head[idCol];
        auto at = [&](int c) { return c >= 0 && c < static_cast<int>(f.size()) ? f[c] : ""; };
        const std::string id = at(idCol);
        if (id.empty()) throw BadInput{where + ": the line has no id"};
        // The id names the student's folder: nothing that could leave it or hide in it.
        if (id == "." || id.find("..") != std::string::npos || id.find('/') != std::string::npos ||
            id.find('\\') != std::string::npos || std::any_of(id.begin(), id.end(), [](char c) {
                return static_cast<unsigned char>(c) < 32 || c == 127;
            }))
            throw BadInput{where + ": \"" + printable(id) + "\" cannot be a folder name"};
        if (!seen.insert(id).second)
            throw BadInput{where + ": \"" + printable(id) + "\" is a duplicate id"};
        std::string name = at(nameCol);
        if (name.empty()) name = at(firstCol) + (at(lastCol).empty() ? "" : " " + at(lastCol));
        if (name == " ") name.clear();
        r.students.push_back({id, name});
    }
    return r;
}

/// The student's seed: FNV-1a 64 of "S/topic/id" (docs/practice.md, "Homework").
std::uint64_t studentSeed(std::uint64_t seed, const std::string& topic, const std::string& id) {
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : std::to_string(seed) + "/" + topic + "/" + id) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    return h;
}

std::string html(const std::string& s) {
    std::string o;
    for (const char c : s) {
        if (c == '&')
            o += "&amp;";
        else if (c == '<')
            o += "&lt;";
        else if (c == '>')
            o += "&gt;";
        else if (c == '"')
            o += "&quot;";
        else if (c == '\'')
            o += "&#39;";
        else
            o += c;
    }
    return o;
}

/// A lesson's text as HTML: escaped, its `code spans` as <code>.
std::string prose(const std::string& s) {
    std::string o;
    bool code = false;
    for (const char c : html(s)) {
        if (c == '`') {
            o += code ? "</code>" : "<code>";
            code = !code;
        } else {
            o += c;
        }
    }
    return code ? o + "</code>" : o;
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string o = "\"";
    for (const char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
}

int make(const HomeworkArgs& a, Language lang) {
    const Roster roster = loadRoster(a.roster);
    std::vector<std::string> topics = splitList(a.topics);
    for (const std::string& t : topics)
        if (!findPracticeTopic(t))
            throw BadInput{"--topics " + printable(t) + ": unknown topic (expected one of " +
                           practiceTopicList() + ")"};
    const PracticeLevel level = *parsePracticeLevel(a.level);
    std::vector<std::string> store;                        // the bytes writeOutputs points at
    std::vector<std::pair<std::string, std::string>> out;  // path, bytes
    nlohmann::ordered_json meta = {{"format", "raystep-homework"},
                                   {"version", 1},
                                   {"roster", a.roster},
                                   {"roster_column", roster.column},
                                   {"seed", a.seed},
                                   {"topics", topics},
                                   {"level", a.level},
                                   {"students", nlohmann::ordered_json::array()}};
    std::string key = "student,topic,lesson,exercise,answer\r\n";
    const std::filesystem::path dir(a.output);
    for (const Student& s : roster.students) {
        std::string md = "# " + (s.name.empty() ? s.id : s.name) + " (" + s.id + ")\n\n";
        std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" +
                        html(s.id) + "</title></head><body>\n<h1>" +
                        html(s.name.empty() ? s.id : s.name) + " (" + html(s.id) + ")</h1>\n";
        nlohmann::ordered_json lessons = nlohmann::ordered_json::object();
        for (const std::string& t : topics) {
            const std::uint64_t seed = studentSeed(a.seed, t, s.id);
            const PracticeInstance p = makePractice(t, seed, level);
            const Lesson& l = p.lesson;
            lessons[t] = l.id;
            md += "## " + l.title.in(lang) + "\n\n" +
                  trf(lang, "Lesson id: %1", {"`" + l.id + "`"}) + "\n\n" + l.text.in(lang) +
                  "\n\n";
            h += "<h2>" + html(l.title.in(lang)) + "</h2>\n<p>" +
                 trf(lang, "Lesson id: %1", {"<code>" + html(l.id) + "</code>"}) + "</p>\n<p>" +
                 prose(l.text.in(lang)) + "</p>\n";
            if (auto png = practiceFigurePng(l)) {
                const std::string fig = "figure-" + t + ".png";
                out.emplace_back((dir / s.id / fig).string(), *png);
                md += "![" + t + "](" + fig + ")\n\n";
                h += "<p><img src=\"" + html(fig) + "\" alt=\"" + html(t) + "\"></p>\n";
            }
            h += "<ol>\n";
            for (const Exercise& ex : l.exercises) {
                md += "- **" + ex.id + "**: " + ex.prompt.in(lang) + "\n\n";
                h += "<li><b>" + html(ex.id) + "</b>: " + prose(ex.prompt.in(lang));
                // A choice is answered by its letter (key.csv's): the sheet lists the options.
                if (!ex.choices.empty()) h += "<ol type=\"a\">";
                for (std::size_t k = 0; k < ex.choices.size(); ++k) {
                    const std::string letter(1, static_cast<char>('a' + k));
                    md += "  " + letter + ") " + ex.choices[k].text.in(lang) + "\n";
                    h += "<li>" + prose(ex.choices[k].text.in(lang)) + "</li>";
                }
                if (!ex.choices.empty()) {
                    md += "\n";
                    h += "</ol>";
                }
                md += "  " + tr(lang, "Answer") + ": ____________________\n\n";
                h += "<br>" + html(tr(lang, "Answer")) + ": ______________________________</li>\n";
            }
            h += "</ol>\n";
            const nlohmann::ordered_json sheet = {
                {"lesson", l.id}, {"student", s.id}, {"answers", nlohmann::ordered_json::object()}};
            out.emplace_back((dir / s.id / ("answers-" + t + ".json")).string(),
                             sheet.dump(2) + "\n");
            // Kept alive: a range-for over a temporary's member would dangle.
            const nlohmann::ordered_json pj = p.toJson();
            for (const auto& ex : pj["exercises"])
                key += csvField(s.id) + "," + t + "," + l.id + "," +
                       csvField(ex["id"].get<std::string>()) + "," +
                       csvField(ex["answer"].get<std::string>()) + "\r\n";
        }
        h += "</body></html>\n";
        out.emplace_back((dir / s.id / "sheet.md").string(), md);
        out.emplace_back((dir / s.id / "sheet.html").string(), h);
        meta["students"].push_back({{"id", s.id}, {"name", s.name}, {"lessons", lessons}});
    }
    out.emplace_back((dir / "key.csv").string(), key);
    out.emplace_back((dir / "homework.json").string(), meta.dump(2) + "\n");
    std::error_code ec;
    for (const Student& s : roster.students) std::filesystem::create_directories(dir / s.id, ec);
    if (ec) throw BadInput{"-o " + a.output + ": cannot be written (" + ec.message() + ")"};
    std::vector<FileToWrite> files;
    for (const auto& [p, b] : out) files.push_back({p, b});
    if (auto problem = writeOutputs(files)) throw BadInput{*problem};
    std::printf("%s: %zu students, topics %s, id column \"%s\"\n", a.output.c_str(),
                roster.students.size(), a.topics.c_str(), roster.column.c_str());
    return 0;
}

std::string twoDecimals(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f", v);
    return b;
}

int grade(const HomeworkArgs& a, Language lang) {
    const std::filesystem::path dir(a.dir);
    const std::string metaPath = (dir / "homework.json").string();
    nlohmann::ordered_json meta;
    try {
        meta = nlohmann::ordered_json::parse(readFile(metaPath));
    } catch (const nlohmann::json::exception& e) {
        throw BadInput{metaPath + ": not JSON (" + std::string(e.what()) + ")"};
    }
    if (!meta.contains("students") || !meta.contains("topics"))
        throw BadInput{metaPath + ": not a homework.json (students, topics)"};
    std::string grades = "id,grade,feedback\r\n";
    // Per topic: the lesson of each student and their sheets, for the class table.
    std::map<std::string, std::vector<std::pair<std::string, AnswerSheet>>> byTopic;
    std::map<std::string, Lesson> firstLesson;
    for (const auto& st : meta["students"]) {
        const std::string id = st["id"].get<std::string>();
        int score = 0, outOf = 0;
        bool any = false;
        std::string feedback;
        for (const auto& tj : meta["topics"]) {
            const std::string t = tj.get<std::string>();
            const std::string lessonId = st["lessons"][t].get<std::string>();
            const Lesson l = loadLesson(lessonId);
            const std::filesystem::path sub =
                std::filesystem::path(a.answers) / id / ("answers-" + t + ".json");
            std::error_code ec;
            if (!std::filesystem::exists(sub, ec)) {
                outOf += static_cast<int>(l.exercises.size());
                feedback += (feedback.empty() ? "" : "; ") + t + ": no submission";
                continue;
            }
            const AnswerSheet sheet = loadAnswerSheetFile(sub.string());
            if (sheet.lesson != lessonId)
                throw BadInput{sub.string() + ":" + std::to_string(sheet.lessonLine) +
                               ": lesson: " + printable(sheet.lesson) + " is not " + lessonId};
            any = true;
            const LessonRun run = runLesson(l);
            const auto sweep = sweepRowsIfNeeded(l, run);
            const Grade g =
                gradeAnswers(l, run.logs(), sheet, lang, sub.string(), &sweep, run.scene.get());
            score += g.score;
            outOf += static_cast<int>(g.items.size());
            std::string slip;
            for (const auto& i : g.items)
                if (!i.correct) {
                    slip = i.exercise + (i.answered ? " wrong" : " not answered");
                    break;
                }
            feedback += (feedback.empty() ? "" : "; ") + t + ": " + std::to_string(g.score) + "/" +
                        std::to_string(g.items.size()) +
                        (slip.empty() ? "" : " (first slip: " + slip + ")");
            byTopic[t].emplace_back(sub.string(), sheet);
            firstLesson.emplace(t, l);
        }
        if (!any) feedback = "no submission";
        const double pct = outOf ? 100.0 * score / outOf : 0.0;
        grades += csvField(id) + "," + twoDecimals(pct) + "," + csvField(feedback) + "\r\n";
    }
    // The class table per topic; each student's own instance is graded against its own lesson.
    std::string cls = "# Homework: the class\n\n";
    for (const auto& tj : meta["topics"]) {
        const std::string t = tj.get<std::string>();
        cls += "## " + t + "\n\n";
        std::map<std::string, ClassTable::Row> rows;
        std::map<std::string, std::map<std::string, int>> slips;
        std::vector<std::string> order;
        for (const auto& st : meta["students"]) {
            const Lesson l = loadLesson(st["lessons"][t].get<std::string>());
            const std::filesystem::path sub = std::filesystem::path(a.answers) /
                                              st["id"].get<std::string>() /
                                              ("answers-" + t + ".json");
            std::error_code ec;
            for (const Exercise& ex : l.exercises)
                if (!rows.count(ex.id)) rows[ex.id].exercise = ex.id, order.push_back(ex.id);
            if (!std::filesystem::exists(sub, ec)) {
                for (const Exercise& ex : l.exercises) ++rows[ex.id].notAnswered;
                continue;
            }
            const LessonRun run = runLesson(l);
            const auto sweep = sweepRowsIfNeeded(l, run);
            const Grade g = gradeAnswers(l, run.logs(), loadAnswerSheetFile(sub.string()), lang,
                                         sub.string(), &sweep, run.scene.get());
            for (const auto& i : g.items) {
                auto& r = rows[i.exercise];
                if (!i.answered)
                    ++r.notAnswered;
                else if (i.correct)
                    ++r.right;
                else
                    ++r.wrong, ++slips[i.exercise][i.feedback];
            }
        }
        cls +=
            "| exercise | right | wrong | not answered | most common slip "
            "|\n|---|---|---|---|---|\n";
        for (const std::string& e : order) {
            const auto& r = rows[e];
            std::string slip;
            int n = 0;
            for (const auto& [f, c] : slips[e])
                if (c > n) slip = f, n = c;
            std::string cell =
                slip.empty() ? "" : printable(slip, 200) + " (" + std::to_string(n) + ")";
            for (std::size_t p = 0; (p = cell.find('|', p)) != std::string::npos; p += 2)
                cell.replace(p, 1, "\\|");
            cls += "| " + e + " | " + std::to_string(r.right) + " | " + std::to_string(r.wrong) +
                   " | " + std::to_string(r.notAnswered) + " | " + cell + " |\n";
        }
        cls += "\n";
    }
    const std::string gp = (dir / "grades.csv").string(), cp = (dir / "class.md").string();
    if (auto problem = writeOutputs({{gp, grades}, {cp, cls}})) throw BadInput{*problem};
    std::printf("%s, %s: %zu students\n", gp.c_str(), cp.c_str(), meta["students"].size());
    return 0;
}

}  // namespace

void addHomeworkCommand(CLI::App& app, HomeworkArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "homework", "A practice sheet per student of a roster, and its grades for Moodle");
    cmd->require_subcommand(1);
    a.make = cmd->add_subcommand("make", "Sheets, answers templates, key.csv and homework.json");
    a.make->add_option("--roster", a.roster, "Moodle-style CSV with an id column")->required();
    a.make->add_option("--topics", a.topics, "Topics of `practice list`, comma-separated")
        ->required();
    addPracticeOptions(a.make, a.seed, UINT64_MAX, "The homework's seed", a.level,
                       "easy, medium or hard", a.lang, "Language of the texts")
        ->required();
    a.make->add_option("-o,--output", a.output, "The homework folder")
        ->check(fileName())
        ->required();
    a.grade = cmd->add_subcommand("grade", "grades.csv (Moodle import) and class.md");
    a.grade->add_option("DIR", a.dir, "The folder `homework make` wrote")->required();
    a.grade->add_option("--answers", a.answers, "Submissions: ID/answers-TOPIC.json")->required();
    a.grade->add_option("--lang", a.lang, "Language of the feedback: " + languageChoices())
        ->capture_default_str();
}

int runHomework(const HomeworkArgs& a) {
    const auto lang = parseLanguage(a.lang);
    if (!lang) return fail("--lang " + a.lang + ": expected " + languageChoices());
    try {
        return a.make->parsed() ? make(a, *lang) : grade(a, *lang);
    } catch (const BadInput& e) {
        return fail(e.line);
    } catch (const FileError& e) {
        return fail(e.what());
    }
}

}  // namespace raystep::cli
