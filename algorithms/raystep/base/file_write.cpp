#include "raystep/base/file_write.h"

#include <fcntl.h>
#include <unistd.h>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace raystep {

namespace {

namespace fs = std::filesystem;

/// Whether a new file can be created in `folder`.
std::string folderProblem(const fs::path& folder) {
    std::error_code ec;
    const fs::file_status st = fs::status(folder, ec);
    const std::string name = folder.string();
    if (st.type() == fs::file_type::not_found) return "folder '" + name + "' does not exist";
    if (ec) return "folder '" + name + "': " + ec.message();
    if (!fs::is_directory(st)) return "'" + name + "' is not a folder";
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return "folder '" + name + "' is not writable: " + std::strerror(errno);
    return "";
}

fs::path folderOf(const fs::path& p) {
    return p.parent_path().empty() ? fs::path(".") : p.parent_path();
}

/// The file a write to `path` replaces: `path`, or the file its symlink names, existing or not
/// (the link stays, as with a shell's redirection).
fs::path targetOf(const fs::path& path) {
    std::error_code ec;
    fs::path p = path;
    for (int hops = 0; hops < 40 && fs::is_symlink(p, ec); ++hops) {
        const fs::path next = fs::read_symlink(p, ec);
        if (ec) break;
        p = next.is_absolute() ? next : folderOf(p) / next;
    }
    return p;
}

/// A new name beside `target` made by `create` (which returns false and sets errno on failure);
/// O_EXCL-style, so an existing file of that name is never touched. Empty if none could be made.
template <typename Create>
fs::path uniqueSibling(const fs::path& target, const std::string& tag, Create create) {
    const std::string name = target.filename().string();
    const std::string pid = std::to_string(::getpid());
    for (int n = 0; n < 100; ++n) {
        std::string suffix = "." + tag + "." + pid;
        if (n) suffix.append(".").append(std::to_string(n));
        // A name near the 255-byte limit gets a short hidden one instead of failing.
        const std::string sibling =
            name.size() + suffix.size() <= NAME_MAX ? name + suffix : ".raystep" + suffix;
        const fs::path p = folderOf(target) / sibling;
        if (create(p)) return p;
        if (errno != EEXIST) return {};
    }
    return {};
}

bool writeAll(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    // On disk before the rename, so a crash leaves the old file or the new one, never an empty one.
    return ::fsync(fd) == 0 || errno == EINVAL;
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    if (fs::equivalent(a, b, ec)) return true;  // both exist (hard links too)
    // Absolute first: weakly_canonical leaves "a.png" relative when nothing of it exists yet.
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
    if (ec) return false;
    const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return !ec && ca == cb;
}

std::string writeProblem(const std::string& path) {
    if (path.empty()) return "no file name given";
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (st.type() == fs::file_type::not_found) return folderProblem(folderOf(targetOf(path)));
    if (ec) return ec.message();  // a symlink loop, a name over 255 bytes, an unsearchable folder
    if (fs::is_directory(st)) return "is a folder";
    if (!fs::is_regular_file(st))
        return "is not a regular file (a device, pipe or socket): outputs are written as files";
    return folderProblem(folderOf(targetOf(path)));
}

void writeFilesAtomic(const std::vector<FileToWrite>& files) {
    struct Staged {
        fs::path target, tmp, backup;
        bool existed = false;
    };
    std::vector<Staged> staged(files.size());
    const auto fail = [&staged](const std::string& path, const std::string& why) {
        std::error_code ec;
        for (const Staged& s : staged) {
            if (!s.tmp.empty()) fs::remove(s.tmp, ec);
            if (!s.backup.empty()) fs::remove(s.backup, ec);
        }
        throw std::runtime_error(path + ": cannot write: " + why);
    };
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (const std::string why = writeProblem(files[i].path); !why.empty())
            fail(files[i].path, why);
        staged[i].target = targetOf(files[i].path);
        std::error_code ec;
        staged[i].existed = fs::exists(staged[i].target, ec);
        for (std::size_t j = 0; j < i; ++j)
            if (sameFile(staged[j].target.string(), staged[i].target.string()))
                fail(files[i].path, "the same file as " + files[j].path);
    }
    // Every temporary written in full before any destination is touched.
    for (std::size_t i = 0; i < files.size(); ++i) {
        int fd = -1;
        staged[i].tmp = uniqueSibling(staged[i].target, "tmp", [&fd](const fs::path& p) {
            fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            return fd >= 0;
        });
        if (fd < 0) fail(files[i].path, std::strerror(errno));
        const bool ok = writeAll(fd, files[i].bytes);
        const int err = errno;
        if (::close(fd) != 0 && ok) fail(files[i].path, std::strerror(errno));
        if (!ok) fail(files[i].path, std::strerror(err));
    }
    // A hard link to each old file but the last, so that if a later rename fails the earlier
    // files can be put back (best effort: a file system without hard links gets no rollback).
    for (std::size_t i = 0; i + 1 < files.size(); ++i)
        if (staged[i].existed)
            staged[i].backup = uniqueSibling(staged[i].target, "old", [&](const fs::path& p) {
                return ::link(staged[i].target.c_str(), p.c_str()) == 0;
            });
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::error_code ec;
        fs::rename(staged[i].tmp, staged[i].target, ec);
        if (!ec) {
            staged[i].tmp.clear();
            continue;
        }
        for (std::size_t j = 0; j < i; ++j) {
            std::error_code undo;
            if (!staged[j].backup.empty()) {
                // Restored, or if not, the old file is left beside the new one, not deleted.
                fs::rename(staged[j].backup, staged[j].target, undo);
                staged[j].backup.clear();
            } else if (!staged[j].existed) {
                fs::remove(staged[j].target, undo);
            }
        }
        fail(files[i].path, ec.message());
    }
    for (const Staged& s : staged) {
        std::error_code ec;
        if (!s.backup.empty()) fs::remove(s.backup, ec);
    }
}

void writeFileAtomic(const std::string& path, const std::string& bytes) {
    writeFilesAtomic({{path, bytes}});
}

}  // namespace raystep
