// SPDX-License-Identifier: BSL-1.0
// Replays fuzz inputs without libFuzzer: each file named on the command line is read whole and passed to the
// target's LLVMFuzzerTestOneInput, once, in the order given. A broken promise aborts (ODESTEP_FUZZ_CHECK in
// fuzz_support.hpp), which fails the run; a file that cannot be read fails it too. tests/CMakeLists.txt links
// this with each target and registers one ctest test per target over its committed corpus
// (tests/fuzz/corpus/<target>/), so every regression input runs under every host preset's compiler.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool read_file(const char* path, std::vector<std::uint8_t>& bytes) {
    std::FILE* file = std::fopen(path, "rb");
    if (file == nullptr) return false;
    bytes.clear();
    unsigned char chunk[4096];
    std::size_t got = 0;
    while ((got = std::fread(chunk, 1, sizeof(chunk), file)) > 0) bytes.insert(bytes.end(), chunk, chunk + got);
    const bool ok = std::ferror(file) == 0;
    std::fclose(file);
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s INPUT...\n", argv[0]);
        return 2;
    }
    std::vector<std::uint8_t> bytes;
    for (int i = 1; i < argc; ++i) {
        if (!read_file(argv[i], bytes)) {
            std::fprintf(stderr, "replay: cannot read %s\n", argv[i]);
            return 1;
        }
        std::printf("replay: %s (%zu bytes)\n", argv[i], bytes.size());
        std::fflush(stdout);  // the name of the input that aborts is the last line printed
        (void)LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    }
    std::printf("replay: %d inputs, no property violated\n", argc - 1);
    return 0;
}
