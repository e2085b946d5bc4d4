#pragma once
// What every raystep-cli command shares: the one-line error, strict number parsing and option
// checks, and the output files (checked before the work, written all or none after it).
#include "raystep/render/image.h"
#include "raystep/scene/scene.h"
#include "raystep/scene/scene2d.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace raystep::cli {

constexpr int kExitBadInput = 2;

/// Prints "raystep-cli: error: <message>" on one line; returns the exit code for bad input.
int fail(const std::string& message);

/// Splits "1,2,3" into finite numbers; nullopt if any part is not one (nan, inf, 1e999, "x", "").
std::optional<std::vector<double>> parseNumbers(const std::string& text, char separator = ',');
/// "a,b,c" as its parts, empty ones kept ("a,," is "a", "", ""; "" is one empty part).
std::vector<std::string> splitList(const std::string& text, char separator = ',');

/// True if `path` ends in `ext` (".png"), in any case.
bool hasExtension(const std::string& path, const std::string& ext);

/// Checks, before any long work, that every output (option, path) can be written, that no two
/// options name the same file and that no output is one of the command's input files (a scene,
/// an answers file: writing over it would lose it); skips empty paths. The one-line problem if not.
std::optional<std::string> checkOutputs(
    const std::vector<std::pair<std::string, std::string>>& optionsAndPaths,
    const std::vector<std::string>& inputs = {});

/// The files a command reads from its scene or model argument: itself and what it refers to (a
/// scene's meshes, a glTF's buffers, an OBJ's .mtl files and textures), for checkOutputs.
std::vector<std::string> inputsOf(const std::string& sceneOrModel);

/// A built-in scene, a scene file or a model (.obj .ply .stl .gltf .glb), with a progress bar
/// while a model is imported; throws SceneError. Remembers it for an out-of-memory message.
std::variant<Scene, Scene2D> loadInput(const std::string& nameOrPath);

/// The scene or model the command works on ("" before it has one): main names it when memory
/// runs out.
const std::string& currentInput();
void setCurrentInput(const std::string& nameOrPath);

/// `asked` threads (0: all cores) clamped to what TBB will give (TBB warns, and ignores, past it).
int threadCount(int asked);

/// CLI11 check for a file name option: not empty (`--events ""` would otherwise mean "none").
CLI::Validator fileName();

/// Writes a command's output files all or none (writeFilesAtomic); the one-line problem if not.
std::optional<std::string> writeOutputs(const std::vector<FileToWrite>& files);

/// CLI11 check for a whole-number option: decimal digits only (no hex, octal, exponent or blank),
/// range-checked in 64 bits before CLI11 converts it, so no value wraps or saturates.
CLI::Validator wholeNumber(std::uint64_t lo, std::uint64_t hi);

/// CLI11 check for a real-number option: finite (no nan, inf or overflow to inf).
CLI::Validator finiteNumber();

/// Adds --max-events to a command that records events: past `cap` the trace file is cut short.
void addMaxEventsOption(CLI::App* cmd, std::size_t& cap);

/// --seed (a whole number up to `maxSeed`), --level (easy, medium or hard) and --lang of a
/// command that makes practice instances: practice make, export moodle, homework make. The
/// seed's option is returned (a command may require it).
CLI::Option* addPracticeOptions(CLI::App* cmd, std::uint64_t& seed, std::uint64_t maxSeed,
                                const std::string& seedHelp, std::string& level,
                                const std::string& levelHelp, std::string& lang,
                                const std::string& langHelp);

/// Whole number from text, within [lo, hi]; nullopt otherwise.
std::optional<int> parseInt(const std::string& text, int lo, int hi);

}  // namespace raystep::cli
