// raystep-cli: the renderer from the command line, for lecturers' scripts and for tests.
#include "assess_command.h"
#include "build_command.h"
#include "common.h"
#include "compare_command.h"
#include "dda_command.h"
#include "export_command.h"
#include "homework_command.h"
#include "intersect_command.h"
#include "lesson_command.h"
#include "practice_command.h"
#include "render_command.h"
#include "scenes_command.h"
#include "trace_command.h"

#include "raystep/base/i18n.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>

using namespace raystep::cli;

int main(int argc, char** argv) {
    CLI::App app{"raystep-cli: the raystep ray tracer from the command line"};
    app.require_subcommand(1);

    // CLI11 would only say "A subcommand is required": name the word it did not know.
    const std::string first = argc > 1 ? argv[1] : "";
    const std::array<std::string, 12> commands = {"scenes",   "render", "intersect", "dda",
                                                  "build",    "trace",  "compare",   "lesson",
                                                  "practice", "export", "homework",  "assess"};
    if (!first.empty() && first[0] != '-' &&
        std::find(commands.begin(), commands.end(), first) == commands.end())
        return fail(std::string("unknown command '") + argv[1] +
                    "' (expected: scenes, render, intersect, dda, build, trace, compare, lesson, "
                    "practice, export, homework, assess)");

    // The languages (base/i18n.h), with those of a RAYSTEP_LANGUAGES folder: a bad one is bad
    // input.
    try {
        (void)raystep::languages();
    } catch (const std::exception& e) {
        return fail(e.what());
    }

    // Each command lives in its <name>_command file; `--help` lists them in this order.
    addScenesCommand(app);
    RenderArgs renderArgs;
    addRenderCommand(app, renderArgs);
    IntersectArgs intersectArgs;
    addIntersectCommand(app, intersectArgs);
    DdaArgs ddaArgs;
    addDdaCommand(app, ddaArgs);
    BuildArgs buildArgs;
    addBuildCommand(app, buildArgs);
    TraceArgs traceArgs;
    addTraceCommand(app, traceArgs);
    CompareArgs compareArgs;
    addCompareCommand(app, compareArgs);
    LessonArgs lessonArgs;
    addLessonCommand(app, lessonArgs);
    PracticeArgs practiceArgs;
    addPracticeCommand(app, practiceArgs);
    ExportArgs exportArgs;
    addExportCommand(app, exportArgs);
    HomeworkArgs homeworkArgs;
    addHomeworkCommand(app, homeworkArgs);
    AssessArgs assessArgs;
    addAssessCommand(app, assessArgs);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(e.what());
    }

    int code = 0;
    // Whatever a command did not catch (a path the file system refuses, memory) is still bad
    // input: one line and exit 2, never an abort.
    try {
        if (app.got_subcommand("scenes"))
            code = listScenes();
        else if (app.got_subcommand("intersect"))
            code = runIntersect(intersectArgs);
        else if (app.got_subcommand("dda"))
            code = runDda(ddaArgs);
        else if (app.got_subcommand("build"))
            code = runBuild(buildArgs);
        else if (app.got_subcommand("trace"))
            code = runTrace(traceArgs);
        else if (app.got_subcommand("compare"))
            code = runCompare(compareArgs);
        else if (app.got_subcommand("lesson"))
            code = runLesson(app.get_subcommand("lesson"), lessonArgs);
        else if (app.got_subcommand("practice"))
            code = runPractice(practiceArgs);
        else if (app.got_subcommand("export"))
            code = runExport(exportArgs);
        else if (app.got_subcommand("homework"))
            code = runHomework(homeworkArgs);
        else if (app.got_subcommand("assess"))
            code = runAssess(assessArgs);
        else
            code = runRender(renderArgs);
    } catch (const std::filesystem::filesystem_error& e) {
        return fail(e.path1().string() + ": " + e.code().message());
    } catch (const std::bad_alloc&) {
        // A scene or model at the caps can need more memory than the computer has.
        const std::string& input = currentInput();
        return fail((input.empty() ? std::string() : input + ": ") +
                    "out of memory: the scene and the options ask for more than this computer "
                    "can give (fewer triangles, a smaller image or fewer samples?)");
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    // Output redirected to a full disk or a closed file is a failed write too.
    errno = 0;
    if ((std::fflush(stdout) != 0 || std::ferror(stdout)) && code == 0)
        return fail(std::string("standard output: cannot write: ") +
                    (errno ? std::strerror(errno) : "write error"));
    return code;
}
