#pragma once
// Test helpers: the message of the InputError (or another error) a call throws.

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

/// Runs `f` and returns the message of the `Error` it throws, "" when it throws none (for comparing
/// two constructions' refusals, which may both accept).
template <class Error, class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace iga::test
