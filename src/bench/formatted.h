#pragma once
// printf's formatting into a string: the benchmarks' text reports are built as strings (the
// command prints them) and keep the printf formats their figures were always printed with.
#include <string>

namespace maxillo::bench {

[[gnu::format(printf, 1, 2)]] std::string formatted(const char* format, ...);

}  // namespace maxillo::bench
