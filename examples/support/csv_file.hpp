// SPDX-License-Identifier: BSL-1.0
// The examples' CSV files. Each example writes its data into the directory named by its first
// command-line argument, or else into ODESTEP_EXAMPLE_DATA_DIR, which examples/CMakeLists.txt sets to
// the build tree's examples/data: never into the source tree.
#ifndef ODESTEP_EXAMPLES_CSV_FILE_HPP
#define ODESTEP_EXAMPLES_CSV_FILE_HPP

#include <odestep/host/csv_observer.hpp>

#include <array>
#include <cstdio>

#ifndef ODESTEP_EXAMPLE_DATA_DIR
#define ODESTEP_EXAMPLE_DATA_DIR "."
#endif

namespace example {

// One CSV file, opened for writing on construction and closed on destruction; `csv` writes to it.
class csv_file {
public:
    csv_file(int argc, char** argv, const char* name) : csv(open(argc, argv, name)) {}
    ~csv_file() {
        if (file_ != nullptr) std::fclose(file_);
    }
    csv_file(const csv_file&) = delete;
    csv_file& operator=(const csv_file&) = delete;

    // True while the file is open and every write has succeeded.
    bool good() const { return file_ != nullptr && csv.good(); }

    // Two blank lines: the next rows are a new data set (gnuplot's `index`).
    void next_block() {
        if (file_ != nullptr) std::fputs("\n\n", file_);
    }

    // One blank line: the next rows are a new curve of the same data set (gnuplot draws no line across).
    void next_curve() {
        if (file_ != nullptr) std::fputs("\n", file_);
    }

private:
    std::FILE* file_ = nullptr;

    std::FILE* open(int argc, char** argv, const char* name) {
        const char* dir = argc > 1 ? argv[1] : ODESTEP_EXAMPLE_DATA_DIR;
        std::array<char, 4096> path{};
        const int n = std::snprintf(path.data(), path.size(), "%s/%s", dir, name);
        if (n > 0 && static_cast<std::size_t>(n) < path.size()) file_ = std::fopen(path.data(), "w");
        if (file_ == nullptr) std::fprintf(stderr, "cannot write %s/%s\n", dir, name);
        return file_;
    }

public:
    odestep::csv_observer csv;  // declared after file_: constructed from the file open() opened
};

}  // namespace example

#endif
