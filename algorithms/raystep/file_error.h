#pragma once
// A file that cannot be read as what it should be (scene, lesson, answers): which file, which line,
// which key, and why, in the one-line form "file:line: key 'k': message".
#include <stdexcept>
#include <string>

namespace raystep {

class FileError : public std::runtime_error {
  public:
    FileError(std::string file, int line, std::string key, const std::string& message)
        : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                             (key.empty() ? std::string() : "key '" + key + "': ") + message),
          file_(std::move(file)),
          line_(line),
          key_(std::move(key)) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }  // 0 when the error is about the file as a whole
    const std::string& key() const { return key_; }

  private:
    std::string file_;
    int line_;
    std::string key_;
};

}  // namespace raystep
