#pragma once
// A test's own folder and raystep-cli run in it: the fixture the model and robustness tests
// share (cli_test.cpp's Cli keeps its stdout inside the folder, for its own checks).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace raystep::testing {

struct CliResult {
    int code;
    std::string out, err;
    double seconds;  ///< wall time of the command
};

class CliFolder : public ::testing::Test {
  protected:
    // The suite's name too: two suites' tests of one name may run at once under ctest -j.
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("raystep-" +
         std::string(::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()) +
         "-" + std::to_string(::getpid()) + "-" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::string env;  ///< "NAME=value " before the command
    void SetUp() override { std::filesystem::create_directories(dir); }
    void TearDown() override { std::filesystem::remove_all(dir); }

    static std::string slurp(const std::filesystem::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    void write(const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
    }
    /// raystep-cli in the test's folder, its outputs outside it; ended after 120 s (a hang on a
    /// FIFO fails the test with 124 rather than blocking the suite).
    CliResult run(const std::string& args) {
        const std::filesystem::path out = dir.string() + ".out", err = dir.string() + ".err";
        const std::string cmd = "cd '" + dir.string() + "' && " + env +
                                "timeout 120 '" RAYSTEP_CLI "' " + args + " > '" + out.string() +
                                "' 2> '" + err.string() + "' < /dev/null";
        const auto start = std::chrono::steady_clock::now();
        const int status = std::system(cmd.c_str());
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        CliResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err), s};
        std::filesystem::remove(out);
        std::filesystem::remove(err);
        return r;
    }
    /// Bad input's answer: exit code 2 and one line, raystep-cli's, naming `file`, saying `why`.
    static void expectOneLine(const CliResult& r, const std::string& file, const std::string& why) {
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.rfind("raystep-cli: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    }
};

}  // namespace raystep::testing
