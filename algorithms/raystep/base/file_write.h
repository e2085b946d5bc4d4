#pragma once
// Files written whole or not at all (a temporary renamed into place), and why a path cannot be
// written: every file raystep writes (images, scenes, traces, reports) goes through here.
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Why no file can be written at `path` ("folder 'out' does not exist", "is a folder", "is not a
/// regular file ...", "Too many levels of symbolic links"), or "" if it can. Never throws.
std::string writeProblem(const std::string& path);

/// Whether two paths name one file (links and "./" resolved), existing or not. Never throws.
bool sameFile(const std::string& a, const std::string& b);

/// One file of a set written together; `bytes` must outlive the call.
struct FileToWrite {
    std::string path;
    std::string_view bytes;
};

/// Writes every file or none: each to a new temporary beside its destination, then all renamed
/// into place. On any failure the temporaries are removed and every destination keeps its old
/// content. A symlink is written through (the link stays); a folder, device, FIFO or socket is
/// refused, as are two paths naming one file. Throws std::runtime_error naming the path.
void writeFilesAtomic(const std::vector<FileToWrite>& files);

/// Writes a whole file atomically; throws std::runtime_error naming the path on failure.
void writeFileAtomic(const std::string& path, const std::string& bytes);

}  // namespace raystep
