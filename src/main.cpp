#include "cli/app.hpp"

int main(int argc, char** argv) { return mrsim::run_cli(argc, argv); }
