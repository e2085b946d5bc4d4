#include "raystep/scene/model_process.h"

#include "raystep/base/json_reader.h"
#include "raystep/scene/model_checks.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <new>
#include <optional>
#include <thread>

extern char** environ;

namespace raystep {

// AddressSanitizer reserves terabytes of address space: no RLIMIT_AS under it (its own
// hard_rss_limit_mb, in ASAN_OPTIONS, bounds such a build's importer instead).
#if defined(__SANITIZE_ADDRESS__)
#define RAYSTEP_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYSTEP_ASAN 1
#endif
#endif

ImportLimits ImportLimits::defaults() {
    ImportLimits l;
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    const std::uint64_t ram =
        pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : std::uint64_t(8) << 30;
    l.memoryBytes =
        std::clamp<std::uint64_t>(ram / 2, std::uint64_t(1) << 30, std::uint64_t(4) << 30);
    l.cpuSeconds = 120;
    l.wallSeconds = 180;
    l.stackBytes = std::uint64_t(8) << 20;
    return l;
}

namespace detail {

namespace {

// The importer's answer, frame by frame: a type byte, a 4-byte length, the payload.
constexpr char kProgress = 'P', kBound = 'B', kTriangles = 'T', kError = 'E', kOutOfMemory = 'K',
               kDone = 'D';
constexpr std::uint32_t kTrianglesAFrame = 16384;
// The answer's descriptor in the importer: not its standard output, which a library it runs
// may print on (a line there would break the frames).
constexpr int kAnswerFd = 3;
constexpr std::uint32_t kMaxFrame = kTrianglesAFrame * 9 * sizeof(double);

std::string megabytes(std::uint64_t bytes) {
    return std::to_string(bytes >> 20) + " MB";
}

std::string seconds(double s) {
    return std::to_string(static_cast<long long>(std::llround(s))) + " s";
}

class FrameWriter {
  public:
    explicit FrameWriter(int fd) : fd_(fd) {}
    void frame(char type, const void* data, std::uint32_t length) {
        char head[5];
        head[0] = type;
        std::memcpy(head + 1, &length, 4);
        put(head, 5);
        put(data, length);
    }

  private:
    void put(const void* data, std::size_t n) {
        const char* p = static_cast<const char*>(data);
        while (n > 0) {
            const ssize_t w = ::write(fd_, p, n);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) ::_exit(4);  // the parent is gone: nobody to answer
            p += w;
            n -= static_cast<std::size_t>(w);
        }
    }
    int fd_;
};

void setLimit(int resource, std::uint64_t soft, std::uint64_t hard) {
    rlimit l{};
    if (::getrlimit(resource, &l) != 0) return;
    // Never above what is allowed already (an unprivileged process cannot raise a hard limit).
    if (l.rlim_max != RLIM_INFINITY) {
        hard = std::min<std::uint64_t>(hard, l.rlim_max);
        soft = std::min(soft, hard);
    }
    l.rlim_cur = soft;
    l.rlim_max = hard;
    ::setrlimit(resource, &l);
}

std::string signalName(int sig) {
    switch (sig) {
        case SIGSEGV:
            return "a segmentation fault";
        case SIGBUS:
            return "a bus error";
        case SIGABRT:
            return "an abort";
        case SIGFPE:
            return "an arithmetic exception";
        case SIGILL:
            return "an illegal instruction";
        default:
            return "signal " + std::to_string(sig);
    }
}

}  // namespace

std::string importerBesideThisProgram() {
    // Another importer, for tests of what the parent does when it misbehaves.
    if (const char* other = std::getenv("RAYSTEP_IMPORTER"); other && *other) return other;
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const std::string importer = (self.parent_path() / kImporterName).string();
    return ::access(importer.c_str(), X_OK) == 0 ? importer : std::string();
}

int runImporter(int argc, char** argv) {
    std::uint64_t memory = 0, stack = 0;
    double cpu = 0;
    long parent = 0;
    std::string path;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const char* next = i + 1 < argc ? argv[i + 1] : "";
        if (a == "--memory")
            memory = std::strtoull(next, nullptr, 10), ++i;
        else if (a == "--stack")
            stack = std::strtoull(next, nullptr, 10), ++i;
        else if (a == "--cpu")
            cpu = std::strtod(next, nullptr), ++i;
        else if (a == "--parent")
            parent = std::strtol(next, nullptr, 10), ++i;
        else if (a == "--" && i + 1 < argc)
            path = argv[++i];
    }
    if (path.empty() || parent <= 0) {
        std::fprintf(stderr,
                     "%s: reads one model for raystep-cli and raystep (not to be run by hand)\n",
                     kImporterName);
        return 64;
    }
    // Ended with the parent (a killed raystep-cli leaves no importer running); no core file.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) return 3;
    ::prctl(PR_SET_DUMPABLE, 0);
    setLimit(RLIMIT_CORE, 0, 0);
#ifndef RAYSTEP_ASAN
    if (memory > 0) setLimit(RLIMIT_AS, memory, memory);
#else
    (void)memory;
#endif
    // Soft: SIGXCPU ends it; the hard limit a few seconds later kills it should it be caught.
    if (cpu > 0) setLimit(RLIMIT_CPU, std::uint64_t(std::ceil(cpu)), std::uint64_t(cpu) + 5);
    if (stack > 0) setLimit(RLIMIT_STACK, stack, stack);

    FrameWriter out(kAnswerFd);
    std::vector<double> chunk;
    chunk.reserve(std::size_t(kTrianglesAFrame) * 9);
    const auto flush = [&] {
        if (chunk.empty()) return;
        out.frame(kTriangles, chunk.data(), std::uint32_t(chunk.size() * sizeof(double)));
        chunk.clear();
    };
    double reported = -1;
    const ProgressFn progress = [&](double f) {
        if (f - reported >= 0.005 || f >= 1.0) {
            reported = f;
            out.frame(kProgress, &f, sizeof f);
        }
        return true;
    };
    try {
        std::uint64_t dropped = 0;
        importModelTriangles(
            path, diskFiles(),
            [&](const Triangle& t) {
                for (const Vec3& p : {t.a, t.b, t.c})
                    for (int k = 0; k < 3; ++k) chunk.push_back(p[k]);
                if (chunk.size() >= std::size_t(kTrianglesAFrame) * 9) flush();
            },
            dropped, progress,
            [&](std::uint64_t bound) { out.frame(kBound, &bound, sizeof bound); });
        flush();
        out.frame(kDone, &dropped, sizeof dropped);
        return 0;
    } catch (const std::bad_alloc&) {
        // The limit it ran into, which may be lower than asked (inherited from a ulimit -v).
        rlimit l{};
        std::uint64_t limit = ::getrlimit(RLIMIT_AS, &l) == 0 && l.rlim_cur != RLIM_INFINITY
                                  ? std::uint64_t(l.rlim_cur)
                                  : 0;
        out.frame(kOutOfMemory, &limit, sizeof limit);
    } catch (const SceneError& e) {
        const std::int32_t line = e.line();
        std::string payload(reinterpret_cast<const char*>(&line), 4);
        payload += e.file() + '\0' + e.key() + '\0' + e.what();
        out.frame(kError, payload.data(), std::uint32_t(payload.size()));
    } catch (const std::exception& e) {
        const std::int32_t line = 0;
        std::string payload(reinterpret_cast<const char*>(&line), 4);
        payload +=
            path + '\0' + '\0' +
            SceneError(path, 0, "", std::string("cannot import the model: ") + e.what()).what();
        out.frame(kError, payload.data(), std::uint32_t(payload.size()));
    }
    return 2;
}

}  // namespace detail

namespace {

/// The importer process while it runs: killed and waited for if the parent stops waiting.
class Child {
  public:
    Child(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;
    ~Child() {
        if (pid_ > 0) {
            ::kill(pid_, SIGKILL);
            wait();
        }
        if (fd_ >= 0) ::close(fd_);
    }
    int fd() const { return fd_; }
    void kill() {
        if (pid_ > 0) ::kill(pid_, SIGKILL);
    }
    /// Waits for its end; its status (or nullopt when it was reaped elsewhere).
    std::optional<int> wait() {
        int status = 0;
        pid_t r;
        do r = ::waitpid(pid_, &status, 0);
        while (r < 0 && errno == EINTR);
        pid_ = -1;
        if (r < 0) return std::nullopt;
        return status;
    }

  private:
    pid_t pid_;
    int fd_;
};

}  // namespace

ImportedModel importModel(const std::string& path, const ImportOptions& options) {
    using namespace detail;
    const auto fail = [&](const std::string& message) -> void {
        throw SceneError(path, 0, "", message);
    };
    if (!isModelPath(path)) fail("not a model file (expected .obj, .ply, .stl, .gltf or .glb)");
    const std::string importer =
        options.importer.empty() ? detail::importerBesideThisProgram() : options.importer;
    if (importer.empty())
        fail(std::string("cannot import the model: ") + detail::kImporterName +
             ", the program that reads models, is not beside this one");
    const ImportLimits& limits = options.limits;

    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        fail(std::string("cannot start the model importer: ") + std::strerror(errno));
    if (fds[1] == kAnswerFd) {
        // dup2 onto itself would keep its close-on-exec flag: the child would get no answer fd.
        const int moved = ::fcntl(fds[1], F_DUPFD_CLOEXEC, kAnswerFd + 1);
        ::close(fds[1]);
        if (moved < 0) {
            ::close(fds[0]);
            fail(std::string("cannot start the model importer: ") + std::strerror(errno));
        }
        fds[1] = moved;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], kAnswerFd);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    // Its stderr is nobody's business (one line is the rule), unless asked for while debugging.
    if (!std::getenv("RAYSTEP_IMPORTER_STDERR"))
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXCPU})
        sigaddset(&defaults, sig);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    std::vector<std::string> args = {importer,
                                     "--memory",
                                     std::to_string(limits.memoryBytes),
                                     "--cpu",
                                     std::to_string(limits.cpuSeconds),
                                     "--stack",
                                     std::to_string(limits.stackBytes),
                                     "--parent",
                                     std::to_string(::getpid()),
                                     "--",
                                     path};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int spawned =
        ::posix_spawn(&pid, importer.c_str(), &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(fds[1]);
    if (spawned != 0) {
        ::close(fds[0]);
        fail("cannot start the model importer " + importer + ": " + std::strerror(spawned));
    }
    Child child(pid, fds[0]);

    // Its answer, read as it comes, within the caps; its progress passed on, a cancel obeyed.
    ImportedModel model;
    std::optional<SceneError> error;
    bool outOfMemory = false, done = false, malformed = false;
    std::uint64_t memoryLimit = 0;  // the importer's, as it found it
    double fraction = 0;
    std::string pending;
    std::size_t at = 0;
    const auto start = std::chrono::steady_clock::now();
    std::vector<char> buffer(1 << 20);
    const auto takeFrames = [&] {
        while (pending.size() - at >= 5) {
            const char type = pending[at];
            std::uint32_t length = 0;
            std::memcpy(&length, pending.data() + at + 1, 4);
            if (length > kMaxFrame) {
                malformed = true;
                return;
            }
            if (pending.size() - at - 5 < length) break;
            const char* p = pending.data() + at + 5;
            if (type == kProgress && length == 8) {
                std::memcpy(&fraction, p, 8);
                fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
            } else if (type == kBound && length == 8) {
                std::uint64_t bound = 0;
                std::memcpy(&bound, p, 8);
                model.triangles.reserve(std::min(bound, detail::kMaxModelTriangles));
            } else if (type == kTriangles && length % (9 * sizeof(double)) == 0) {
                for (std::uint32_t k = 0; k < length / (9 * sizeof(double)); ++k) {
                    std::array<double, 9> v;
                    std::memcpy(v.data(), p + k * sizeof v, sizeof v);
                    if (!std::all_of(v.begin(), v.end(),
                                     [](double x) { return std::isfinite(x); }) ||
                        model.triangles.size() >= detail::kMaxModelTriangles) {
                        malformed = true;
                        return;
                    }
                    const Triangle t{Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]),
                                     Vec3(v[6], v[7], v[8]), 0};
                    model.triangles.push_back(t);
                    model.bounds.extend(t.a);
                    model.bounds.extend(t.b);
                    model.bounds.extend(t.c);
                }
            } else if (type == kDone && length == 8) {
                std::memcpy(&model.droppedDegenerateTriangles, p, 8);
                done = true;
            } else if (type == kOutOfMemory && length == 8) {
                outOfMemory = true;
                std::memcpy(&memoryLimit, p, 8);
            } else if (type == kError && length >= 6) {
                std::int32_t line = 0;
                std::memcpy(&line, p, 4);
                const std::string rest(p + 4, length - 4);
                const std::size_t z1 = rest.find('\0'),
                                  z2 = z1 == std::string::npos ? z1 : rest.find('\0', z1 + 1);
                if (z2 == std::string::npos) {
                    malformed = true;
                    return;
                }
                // The child's SceneError as it was: its file, line, key, and the whole text.
                const std::string file = rest.substr(0, z1), key = rest.substr(z1 + 1, z2 - z1 - 1);
                std::string what = rest.substr(z2 + 1);
                std::string prefix = SceneError(file, line, key, "").what();
                const std::string message =
                    what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
                error.emplace(file, line, key, message);
            } else {
                malformed = true;
                return;
            }
            at += 5 + length;
        }
        if (at > (1u << 22)) {  // keep the buffer small
            pending.erase(0, at);
            at = 0;
        }
    };
    for (;;) {
        if (options.progress && !options.progress(fraction)) {
            child.kill();
            throw BuildCancelled();
        }
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (limits.wallSeconds > 0 && elapsed > limits.wallSeconds) {
            child.kill();
            fail("the import took longer than " + detail::seconds(limits.wallSeconds) +
                 " (the importer's limit on the clock); the model is too big or malformed");
        }
        pollfd p{child.fd(), POLLIN, 0};
        const int ready = ::poll(&p, 1, 100);
        if (ready < 0 && errno != EINTR)
            fail(std::string("cannot read the model importer's answer: ") + std::strerror(errno));
        if (ready <= 0) continue;
        const ssize_t n = ::read(child.fd(), buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // its end (or a read error: treated as its end)
        pending.append(buffer.data(), static_cast<std::size_t>(n));
        takeFrames();
        if (malformed) {
            child.kill();
            fail("the model importer's answer is malformed");
        }
    }
    const std::optional<int> status = child.wait();
    const bool exited = status && WIFEXITED(*status);
    if (status && WIFSIGNALED(*status)) {
        const int sig = WTERMSIG(*status);
        if (sig == SIGXCPU || (sig == SIGKILL && limits.cpuSeconds > 0 &&
                               std::chrono::steady_clock::now() - start >=
                                   std::chrono::duration<double>(limits.cpuSeconds)))
            fail("the import took more than " + detail::seconds(limits.cpuSeconds) +
                 " of processor time (the importer's limit); the model is too big or malformed");
        if (sig == SIGKILL) fail("the model importer was killed (by the system: out of memory?)");
        fail("the model importer crashed inside assimp (" + signalName(sig) +
             "): the file is malformed in a way raystep's own checks do not catch");
    }
    if (error && exited && WEXITSTATUS(*status) == 2) throw *error;
    if (outOfMemory)
        fail(memoryLimit > 0 ? "reading the model needs more memory than the importer's limit "
                               "of " +
                                   megabytes(memoryLimit) + "; the model is too big or malformed"
                             : std::string("reading the model needs more memory than this "
                                           "computer can give"));
    if (!done || (status && !(exited && WEXITSTATUS(*status) == 0)))
        fail(
            "the model importer ended without an answer" +
            (exited ? " (exit code " + std::to_string(WEXITSTATUS(*status)) + ")" : std::string()));
    detail::checkImportedModel(path, model);
    return model;
}

}  // namespace raystep
