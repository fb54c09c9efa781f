// One libFuzzer target: the entry kTargets[MAXILLO_FUZZ_TARGET] of fuzz_entries.h. Built once per
// target by tests/fuzz/CMakeLists.txt when MAXILLO_FUZZ is on (clang, -fsanitize=fuzzer,address,
// undefined); scripts/fuzz runs them.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_entries.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  maxillo::fuzzing::kTargets[MAXILLO_FUZZ_TARGET].entry(std::as_bytes(std::span(data, size)));
  return 0;
}
