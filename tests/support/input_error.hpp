#pragma once
// Test helper: the message of the InputError a call is expected to throw.

#include <gtest/gtest.h>

#include <string>

#include "config/errors.hpp"

namespace iga::test {

/// Runs `f`, expects an InputError, and returns its message ("" and a test failure otherwise).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

}  // namespace iga::test
