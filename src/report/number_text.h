#pragma once
// Numbers as report text.
#include <string>

namespace maxillo::report {

// `value` with `decimals` digits after the point; a value that rounds to zero prints as 0 (never
// "-0.0", which reads as a direction in a table of signed moves).
std::string fixed(double value, int decimals);

}  // namespace maxillo::report
