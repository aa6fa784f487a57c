// Placeholder entry point; replaced by the CLI in solver/cli.cpp.
#include <iostream>
int main() { std::cout << "iga-run " << IGA_RUN_VERSION << "\n"; return 0; }
