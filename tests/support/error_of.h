#pragma once
// What a test of a refusal wants from the maxillo::Error that `run` throws: its message, having
// checked its code. A run that throws nothing is a test failure (and gives "").
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"
#include "core/json.h"

namespace maxillo::testing {

inline std::string error_of(const std::function<void()>& run, ErrorCode expected = ErrorCode::kArchiveCorrupt) {
  try {
    run();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), expected) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

// The error of reading `good` once `damage` has changed a copy of it.
inline std::string error_after_damage(const Json& good, const std::function<void(Json&)>& damage,
                                      const std::function<void(const Json&)>& read,
                                      ErrorCode expected = ErrorCode::kArchiveCorrupt) {
  Json damaged = good;
  damage(damaged);
  return error_of([&] { read(damaged); }, expected);
}

}  // namespace maxillo::testing
