#pragma once
// A student's own run, as JSON Lines (docs/assignment-format.md): rays, and for each the cells,
// nodes and primitive tests it logged and the hit it found. Language-neutral: any program with a
// print statement writes it.
#include "raystep/base/file_error.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

enum class StudentRecordKind : std::uint8_t { Cell, Test, Node, Hit, Miss };

struct StudentRecord {
    StudentRecordKind kind = StudentRecordKind::Cell;
    int line = 0;                               // 1-based, in the file
    std::array<long long, 3> cell{};            // Cell: i, j(, k)
    std::optional<std::array<double, 3>> tMax;  // Cell, when logged; null (infinity) as inf
    std::uint32_t id = 0;                       // Test, Hit: the primitive; Node: the node
    double t = 0.0;                             // Hit
};

struct StudentRay {
    int line = 0;
    int dims = 2;  // 2 or 3: the length of origin and dir
    std::array<double, 3> origin{}, dir{};
    std::vector<StudentRecord> records;
};

struct StudentTrace {
    std::string file;
    std::vector<StudentRay> rays;
};

/// Reads a student's trace; throws FileError naming the file, the line and the key. `dims` is
/// the grid's or scene's (2 or 3): a ray or cell with another number of coordinates is refused.
StudentTrace readStudentTrace(std::string_view text, const std::string& file, int dims);
/// The same from a file (a regular file of at most 256 MB).
StudentTrace loadStudentTrace(const std::string& path, int dims);

}  // namespace raystep
