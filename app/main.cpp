// tumble: rigid-body dynamics from a scenario file (app/cli.cpp has the commands).
#include "commands.hpp"

int main(int argc, char** argv) {
  return tumble::cli::run_cli(argc, argv);
}
