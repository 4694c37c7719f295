// glint's command line: parse, run one subcommand, turn every glint::Error into one line and a
// non-zero exit.
#include "app/cli.h"

int main(int argc, char** argv) { return glint::run_cli(argc, argv); }
