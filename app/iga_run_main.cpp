// iga-run: the command-line program. Everything lives in the library; see solver/cli.cpp.
#include "app/cli.hpp"

int main(int argc, char** argv) { return iga::run_cli(argc, argv); }
