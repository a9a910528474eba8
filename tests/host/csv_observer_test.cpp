// SPDX-License-Identifier: BSL-1.0
// The host CSV writer (include/odestep/host/csv_observer.hpp): what it writes, that numbers read back
// bit for bit, thinning, failures, and that its own code makes no allocation. Host only (stdio, iostreams).
#include <doctest/doctest.h>
#include <odestep/host/csv_observer.hpp>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <streambuf>
#include <string>

#ifdef ODESTEP_TEST_ALLOC_HOOKS
#include "support/alloc_counter.hpp"
#endif

namespace {

using pair = std::array<double, 2>;
using one = std::array<double, 1>;

// A stream buffer over a fixed array: writing through it never allocates.
struct fixed_buffer : std::streambuf {
    std::array<char, 4096> bytes{};
    fixed_buffer() { setp(bytes.data(), bytes.data() + bytes.size()); }
    std::string text() const { return std::string(pbase(), pptr()); }
};

// Splits "a,b,c" into its fields (for the round-trip tests).
std::array<std::string, 8> fields(const std::string& line) {
    std::array<std::string, 8> out{};
    std::size_t k = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= line.size() && k < out.size(); ++i) {
        if (i == line.size() || line[i] == ',' || line[i] == '\n') {
            out[k++] = line.substr(start, i - start);
            start = i + 1;
            if (i < line.size() && line[i] == '\n') break;
        }
    }
    return out;
}

}  // namespace

TEST_CASE("csv_observer: a header line, then t and every component of each state per observation") {
    std::ostringstream out;
    odestep::csv_observer csv(out);
    csv.header("t", "x", "v");
    csv(0.5, pair{1.0, -2.0});
    csv(0.75, one{3.0}, one{-0.25});
    CHECK(out.str() == "t,x,v\n0.5,1,-2\n0.75,3,-0.25\n");
    CHECK(csv.rows() == 2);
    CHECK(csv.observations() == 2);
    CHECK(csv.good());
}

TEST_CASE("csv_observer: observes a Newtonian run as t, x, v on every step") {
    // Euler for x'' = -1 from x = 0, v = 1 with dt = 0.5: (x, v) = (0, 1), (0.5, 0.5), (0.75, 0), all exact
    // in binary.
    std::ostringstream out;
    odestep::csv_observer csv(out);
    one x{0.0};
    one v{1.0};
    const auto r = odestep::integrate_n_steps(
        odestep::newtonian_euler<one>{}, [](double, const one&, const one&) { return one{-1.0}; }, x, v, 0.0, 0.5, 2,
        csv);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(out.str() == "0,0,1\n0.5,0.5,0.5\n1,0.75,0\n");
}

TEST_CASE("csv_observer: every(k) writes the 1st, (k+1)-th, ... observation; row and header are not thinned") {
    std::ostringstream out;
    odestep::csv_observer csv(out);
    csv.every(3);
    for (int i = 0; i < 7; ++i) csv(static_cast<double>(i), one{static_cast<double>(10 * i)});
    csv.row(99.0);
    CHECK(out.str() == "0,0\n3,30\n6,60\n99\n");
    CHECK(csv.observations() == 7);
    CHECK(csv.rows() == 4);
    std::ostringstream again;
    odestep::csv_observer zero(again);
    zero.every(0);  // taken as 1
    zero(1.0, one{2.0});
    zero(3.0, one{4.0});
    CHECK(again.str() == "1,2\n3,4\n");
}

TEST_CASE("csv_observer: doubles, floats and long doubles read back bit for bit at the default precision") {
    const double pi = std::acos(-1.0);
    const std::array<double, 6> doubles{0.1,    1.0 / 3.0, pi,
                                        1e-300, -2.5e300,  std::numeric_limits<double>::denorm_min()};
    std::ostringstream out;
    odestep::csv_observer csv(out);
    csv.row(doubles);
    const auto d = fields(out.str());
    for (std::size_t i = 0; i < doubles.size(); ++i) {
        const double back = std::strtod(d[i].c_str(), nullptr);
        CHECK(std::memcmp(&back, &doubles[i], sizeof back) == 0);
    }
    const std::array<float, 3> floats{0.1f, 1.0f / 3.0f, 16777217.0f};
    std::ostringstream fout;
    odestep::csv_observer fcsv(fout);
    fcsv.row(floats);
    const auto f = fields(fout.str());
    for (std::size_t i = 0; i < floats.size(); ++i) {
        const float back = std::strtof(f[i].c_str(), nullptr);
        CHECK(std::memcmp(&back, &floats[i], sizeof back) == 0);
    }
    CHECK(f[0] == "0.100000001");  // 9 significant digits (max_digits10 of float), not double's 17
    const long double third = 1.0L / 3.0L;
    std::ostringstream lout;
    odestep::csv_observer lcsv(lout);
    lcsv.row(third);
    const long double lback = std::strtold(fields(lout.str())[0].c_str(), nullptr);
    CHECK(lback == third);
}

TEST_CASE("csv_observer: precision(n) writes n significant digits; integers and bools are written as integers") {
    std::ostringstream out;
    odestep::csv_observer csv(out);
    csv.precision(4).row(1.0 / 3.0, std::size_t{3}, -2, true, std::array<int, 2>{7, -8});
    CHECK(out.str() == "0.3333,3,-2,1,7,-8\n");
}

TEST_CASE("csv_observer: writes through a FILE*, and a write that fails clears good()") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    odestep::csv_observer csv(file);
    csv.header("t", "y");
    csv(0.25, one{-1.5});
    CHECK(csv.good());
    std::rewind(file);
    std::array<char, 64> text{};
    const std::size_t n = std::fread(text.data(), 1, text.size() - 1, file);
    CHECK(std::string(text.data(), n) == "t,y\n0.25,-1.5\n");
    std::fclose(file);

    std::FILE* reading = std::fopen("/dev/null", "r");  // open for reading: every fwrite fails
    REQUIRE(reading != nullptr);
    odestep::csv_observer bad(reading);
    bad.row(1.0);
    CHECK_FALSE(bad.good());
    std::fclose(reading);

    std::ostringstream stream;
    stream.setstate(std::ios::badbit);
    odestep::csv_observer bad_stream(stream);
    bad_stream.row(1.0);
    CHECK_FALSE(bad_stream.good());
}

#ifdef ODESTEP_TEST_ALLOC_HOOKS
TEST_CASE("csv_observer: writing rows makes no allocation of its own (FILE* and std::ostream)") {
    // Both sinks are set up before counting: a FILE* over a caller's buffer (fmemopen allocates when it
    // opens, not when it writes) and a stream over a fixed array.
    std::array<char, 4096> memory{};
    std::FILE* file = fmemopen(memory.data(), memory.size(), "w");
    REQUIRE(file != nullptr);
    REQUIRE(std::setvbuf(file, nullptr, _IONBF, 0) == 0);
    fixed_buffer buffer;
    std::ostream stream(&buffer);
    const std::size_t before = odestep_test::allocations();
    {
        odestep::csv_observer to_file(file);
        odestep::csv_observer to_stream(stream);
        for (odestep::csv_observer* csv : {&to_file, &to_stream}) {
            csv->header("t", "x", "v");
            csv->every(2);
            for (int i = 0; i < 10; ++i) (*csv)(0.1 * i, pair{1.0 / 3.0, -2.0e-300}, one{1e300});
            csv->row(std::size_t{7}, 2.5f, 1.0L / 3.0L);
        }
        CHECK(to_file.good());
        CHECK(to_stream.good());
    }
    CHECK(odestep_test::allocations() == before);
    std::fclose(file);
    CHECK(buffer.text().substr(0, 6) == "t,x,v\n");
}
#endif
