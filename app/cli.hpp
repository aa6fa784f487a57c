#pragma once
/// @file
/// The `iga-run` command line: iga-run CONFIG.yaml [--output DIR] [--levels N] [--quiet] [--version].

namespace iga {

/// Run the program; returns the exit code: 0 success, 2 bad input, 1 numerical failure.
int run_cli(int argc, char** argv);

}  // namespace iga
