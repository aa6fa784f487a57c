// iga-run: the command-line program. Everything lives in the library; see app/cli.cpp.
#include "app/cli.hpp"

int main(int argc, char** argv) { return iga::run_cli(argc, argv); }
