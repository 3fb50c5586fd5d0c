// marchstudio: one program, subcommands dispatched by cli/.
#include "cli/cli.h"

int main(int argc, char** argv) { return ms::run_cli(argc, argv); }
