// choice: a conceptual question whose right option is in the lesson file (the one exception to
// answers read from the trace); a wrong option is answered with its own why.
#include "course/exercises/kind_unit.h"

#include "raystep/base/i18n.h"

#include <algorithm>

namespace raystep::exercises {

namespace {

/// An option's text before its why: without its own full stop ("... the nearest one.: The").
std::string optionText(std::string text) {
    while (!text.empty() && (text.back() == '.' || text.back() == ' ')) text.pop_back();
    return text;
}

class Choice final : public ExerciseKindUnit {
  public:
    ExerciseKind kind() const override { return ExerciseKind::Choice; }
    std::string_view name() const override { return "choice"; }
    std::vector<const char*> keys() const override { return {"choices", "answer"}; }

    void read(const LessonReader& r, const detail::json& j, const std::string& path,
              Exercise& ex) const override {
        for (const char* key : {"choices", "answer"})
            if (!j.contains(key))
                r.fail(path, std::string("a choice exercise needs \"") + key + "\"");
        const std::string cp = JsonLineMap::child(path, "choices");
        const detail::json& cs = j["choices"];
        if (!cs.is_array() || cs.size() < 2 || cs.size() > 6)
            r.fail(cp, "expected 2 to 6 options [{\"text\": TEXT, \"why\": TEXT}, ...]");
        for (std::size_t i = 0; i < cs.size(); ++i) {
            const std::string op = JsonLineMap::element(cp, i);
            r.requireObject(cs[i], op);
            r.checkKeys(cs[i], op, {"text", "why"});
            if (!cs[i].contains("text") || !cs[i].contains("why"))
                r.fail(op, "an option needs its \"text\" and \"why\"");
            ex.choices.push_back(
                {lesson_reading::readText(r, cs[i]["text"], JsonLineMap::child(op, "text")),
                 lesson_reading::readText(r, cs[i]["why"], JsonLineMap::child(op, "why"))});
        }
        ex.answer = r.integer(j["answer"], JsonLineMap::child(path, "answer"), 0,
                              static_cast<int>(cs.size()) - 1);
    }

    Reference reference(const Context& c, Language lang) const override {
        Reference ref;
        Answer& a = ref.answer;
        std::string& why = ref.why;
        a.numbers.push_back(c.ex.answer);
        const ChoiceOption& right = c.ex.choices.at(static_cast<std::size_t>(c.ex.answer));
        why = trf(lang, "The right answer is %1) %2: %3",
                  {letter(c.ex.answer), optionText(right.text.in(lang)), right.why.in(lang)});
        return ref;
    }

    std::optional<Answer> parse(const Exercise& ex, std::string_view text, std::string* why,
                                Language lang) const override {
        const auto bad = [&](const std::string& message) { return rejected(why, message); };
        Answer a;
        std::string s = lower(trim(text));
        while (!s.empty() && (s.front() == '(' || s.back() == ')' || s.back() == '.')) {
            if (s.front() == '(') s.erase(0, 1);
            if (!s.empty() && (s.back() == ')' || s.back() == '.')) s.pop_back();
        }
        const int options = static_cast<int>(ex.choices.size());
        int index = -1;
        if (s.size() == 1 && s[0] >= 'a' && s[0] < 'a' + options) index = s[0] - 'a';
        if (const auto v = parseWhole(s); v && *v >= 1 && *v <= options)
            index = static_cast<int>(*v) - 1;
        if (index < 0)
            return bad(trf(lang, "expected a letter (a to %1) or a number (1 to %2)",
                           {letter(std::max(options, 1) - 1), std::to_string(options)}));
        a.numbers.push_back(index);
        return a;
    }

    std::string format(const Exercise&, const Answer& a, Language) const override {
        return a.numbers.empty() ? "" : letter(static_cast<int>(a.numbers[0]));
    }

    bool grade(const Context&, const Answer& given, const Reference& ref) const override {
        return given.numbers == ref.answer.numbers;
    }

    std::string slip(const Context& c, const Answer& answer, const Reference&, const std::string&,
                     Language lang) const override {
        const double given = answer.numbers[0];
        if (given < 0 || given >= static_cast<double>(c.ex.choices.size())) return "";
        const auto& chosen = c.ex.choices[static_cast<std::size_t>(given)];
        return trf(lang, "%1) %2: %3",
                   {letter(static_cast<int>(given)), optionText(chosen.text.in(lang)),
                    chosen.why.in(lang)});
    }

    std::string retryAdvice(const Exercise&, bool, Language lang) const override {
        return tr(lang,
                  "Read each option again and ask what the lecture's algorithm does in "
                  "that case.");
    }
    bool answerInTrace() const override { return false; }
    AnswerInputSpec input(const Exercise&) const override {
        return {AnswerInputSpec::Widget::Options};
    }
    // No answer forms: a choice's options are on screen by design.
};

}  // namespace

const ExerciseKindUnit& choiceUnit() {
    static const Choice unit;
    return unit;
}

}  // namespace raystep::exercises
