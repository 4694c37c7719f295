// glint's command line: app/'s subcommands and those of the folders above it (viewer/'s `view`),
// parsed and run by run_cli, every glint::Error one line and a non-zero exit. This file sits above
// every folder of src/, so app/ needs to include none of them.
#include "app/cli.h"
#include "viewer/view_command.h"

int main(int argc, char** argv) { return glint::run_cli(argc, argv, {glint::viewer::view_cli_command()}); }
