#pragma once
// The message of the glint::Error that `action` throws, or "" plus a test failure when it throws none.
#include "core/error.h"

#include <gtest/gtest.h>

#include <string>

namespace glint::testing {

template <typename Action>
std::string error_of(Action&& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a glint::Error";
  return {};
}

}  // namespace glint::testing
