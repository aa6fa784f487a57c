#pragma once
/// @file
/// Shared by the libFuzzer targets: what counts as a correct rejection of bad input.

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "config/errors.hpp"

namespace iga::fuzz {

/// Runs `step`; an InputError is the correct answer to bad input and is swallowed. Any other
/// exception would reach the command line as a wrong exit code (1 instead of 2) or an abort, so it
/// stops the fuzzer with the message (libFuzzer saves the input as a crash).
template <class Step>
void expect_input_error(Step&& step) {
  try {
    step();
  } catch (const iga::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an InputError: %s\n", e.what());
    std::abort();
  }
}

}  // namespace iga::fuzz
