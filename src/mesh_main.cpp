// mrsim-mesh: the program behind `mrsim mesh` (cli/mesh_command.hpp).
#include "cli/mesh_command.hpp"

int main(int argc, char** argv) { return mrsim::run_mesh_cli(argc, argv); }
